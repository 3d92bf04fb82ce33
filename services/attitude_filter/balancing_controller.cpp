// balancing_controller (controller; attitude_filter): pole-placement state feedback of the
// balancing robot on the estimated attitude and the wheel encoders (paper 002;
// docs/algorithms/balancing.md). Ports bind to `<robot>/<port>` unless remapped; the
// output names its IDL type (docs/topics.md).
//
//   in odometry {x, v} (TravelState: wheel encoders), attitude {theta, theta_dot}
//     (AttitudeEstimate), reference {x, v} (TravelState); out cmd {torque}
//     (WheelTorqueCommand; 0 until an attitude estimate exists).
//   poles (list of 4, [-2, -3, -9, -10]); its model: the plant's keys (body_mass ..
//   max_torque, services/common/balancing_params.hpp), same defaults.
#include <memory>
#include <string>

#include "plexus/algorithms/balancing/balancing_controller.hpp"
#include "plexus/algorithms/balancing/wheeled_inverted_pendulum.hpp"
#include "plexus/scenario/params.hpp"
#include "plexus/scenario/registry.hpp"
#include "services/common/balancing_params.hpp"

namespace plexus::scenario {
namespace {

namespace alg = plexus::algorithms;

alg::BalancingControllerParams controller_params(const YamlMap& p) {
  alg::BalancingControllerParams b;
  if (p.has("poles")) {
    const auto poles = p.sequence("poles");
    if (poles.size() != 4) p.fail("poles", "must list 4 poles, got " + std::to_string(poles.size()));
    // Through number(): yaml-cpp's as<double>() threw its own exception for a pole that was
    // not a number (found by fuzzing the scenario loader) and took .nan.
    for (std::size_t i = 0; i < 4; ++i) b.poles[i] = number(p, poles[i], "poles");
  }
  return b;
}

class BalancingControllerComponent final : public Component {
 public:
  explicit BalancingControllerComponent(const ComponentConfig& c)
      : Component(c),
        plant_(pendulum_params(c.params())),  // its model: the robot's keys, as the plant reads them
        ctl_(controller_params(c.params()), plant_),
        state_(add_input("odometry", {"x", "v"}, "TravelState")),
        est_(add_input("attitude", {"theta", "theta_dot"}, "AttitudeEstimate")),
        ref_(add_input("reference", {"x", "v"}, "TravelState")),
        out_(add_output("cmd", {"torque"}, "WheelTorqueCommand")) {}

  void step(int64_t /*k*/, double /*t*/) override {
    const alg::MotionReference r{ref_[0], ref_[1]};
    out_[0] = est_.valid() ? ctl_.torque(state_[0], state_[1], est_[0], est_[1], r) : 0.0;
  }

 private:
  alg::WheeledInvertedPendulum plant_;
  alg::BalancingController ctl_;
  InputPort& state_;
  InputPort& est_;
  InputPort& ref_;
  OutputPort& out_;
};

const ComponentRegistration kController{
    "balancing_controller", ComponentKind::controller,
    "pole-placement state feedback on the estimated attitude + encoders; out cmd {torque}",
    [](const ComponentConfig& c) { return std::make_unique<BalancingControllerComponent>(c); }};

}  // namespace
}  // namespace plexus::scenario
