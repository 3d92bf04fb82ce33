// constant_command (controller; component_host): an open-loop test driver. Parameters
// are documented in docs/scenarios.md; the output binds to `<robot>/cmd` unless remapped
// and names its IDL type (docs/topics.md).
//
//   out cmd {v, omega} (UnicycleCommand) = the parameters v, omega (m/s, rad/s; required).
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
        out_(add_output("cmd", {"v", "omega"}, "UnicycleCommand")) {}

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
