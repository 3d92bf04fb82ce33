// constant_command (controller; component_host): an open-loop test driver. Parameters
// are documented in docs/scenarios.md; the output binds to `<robot>/cmd` unless remapped
// and names its IDL type (docs/topics.md).
//
//   out cmd {v, omega} (UnicycleCommand) = the parameters v, omega (m/s, rad/s; required;
//     tunable while it runs: plexus param).
#include <memory>

#include "plexus/scenario/registry.hpp"

namespace plexus::scenario {
namespace {

class ConstantCommand final : public Component {
 public:
  explicit ConstantCommand(const ComponentConfig& c)
      : Component(c),
        v_(c.params().required<double>("v")),
        omega_(c.params().required<double>("omega")),
        out_(add_output("cmd", {"v", "omega"}, "UnicycleCommand")) {
    add_tunable(
        "v", "m/s: the commanded speed", [this] { return v_; }, [this](double v) { v_ = v; });
    add_tunable(
        "omega", "rad/s: the commanded turn rate", [this] { return omega_; }, [this](double w) { omega_ = w; });
  }

  void step(int64_t /*k*/, double /*t*/) override {
    out_[0] = v_;
    out_[1] = omega_;
  }

 private:
  double v_;
  double omega_;
  OutputPort& out_;
};

const ComponentRegistration kConstantCommand{
    "constant_command", ComponentKind::controller, "open loop: constant cmd {v, omega}",
    [](const ComponentConfig& c) { return std::make_unique<ConstantCommand>(c); }};

}  // namespace
}  // namespace plexus::scenario
