// unicycle (plant; plant_simulator): the unicycle of papers 000 and 003
// (plexus/algorithms/unicycle/unicycle_plant.hpp; docs/algorithms/unicycle.md), exact
// integration. Ports bind to `<robot>/<port>` unless remapped; the output names its IDL
// type (docs/topics.md).
//
//   type: unicycle         (plant)
//   x0, y0, theta0         initial pose, m, m, rad (default 0)
//   v_noise_std            actuation noise, m/s, >= 0 (default 0): each plant step applies
//   omega_noise_std        v + N(0, v_noise_std^2), omega + N(0, omega_noise_std^2), drawn
//                          from the plant's own seed (v first, then omega)
//   input  cmd   {v, omega} (UnicycleCommand)  held over each plant period (the latest command before the step)
//   output truth/state {x, y, theta} (Pose2D)  theta continuous (not wrapped)
#include <memory>

#include "plexus/algorithms/core/random.hpp"
#include "plexus/algorithms/unicycle/unicycle_plant.hpp"
#include "plexus/msg/messages.hpp"
#include "plexus/scenario/params.hpp"
#include "plexus/scenario/registry.hpp"

namespace plexus::scenario {
namespace {

class UnicyclePlantComponent final : public Component {
 public:
  explicit UnicyclePlantComponent(const ComponentConfig& c)
      : Component(c),
        state_{c.params().optional<double>("x0", 0.0), c.params().optional<double>("y0", 0.0),
               c.params().optional<double>("theta0", 0.0)},
        h_(c.period()),
        v_noise_(optional_non_negative(c.params(), "v_noise_std")),
        omega_noise_(optional_non_negative(c.params(), "omega_noise_std")),
        rng_(c.seed),
        cmd_(add_input<msg::UnicycleCommand>("cmd")),
        out_(add_output<msg::Pose2D>("truth/state")) {}

  void step(int64_t k, double /*t*/) override {
    if (k > 0 && cmd_.valid()) {
      algorithms::UnicycleInput u{cmd_->v(), cmd_->omega()};
      if (v_noise_ > 0.0) u.v += v_noise_ * rng_.normal();
      if (omega_noise_ > 0.0) u.omega += omega_noise_ * rng_.normal();
      state_ = algorithms::unicycle_step(state_, u, h_);
    }
    out_->x() = state_.x;
    out_->y() = state_.y;
    out_->theta() = state_.theta;
  }

 private:
  algorithms::UnicycleState state_;
  double h_;
  double v_noise_;
  double omega_noise_;
  algorithms::Rng rng_;
  TypedInput<msg::UnicycleCommand>& cmd_;
  TypedOutput<msg::Pose2D>& out_;
};

const ComponentRegistration kUnicycle{
    "unicycle",
    ComponentKind::plant,
    "unicycle kinematics, exact integration; in cmd {v, omega}, out truth/state {x, y, theta}",
    [](const ComponentConfig& c) { return std::make_unique<UnicyclePlantComponent>(c); },
    {"paper000.plant"}};

}  // namespace
}  // namespace plexus::scenario
