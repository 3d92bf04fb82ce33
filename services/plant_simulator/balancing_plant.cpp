// wheeled_inverted_pendulum (plant; plant_simulator): the two-wheeled balancing robot of
// paper 002 eq. (10) (docs/algorithms/balancing.md). Angles travel in rad and rad/s; YAML
// keys with _deg are in degrees, as in the paper's Table 1.
//
//   in cmd {torque} (WheelTorqueCommand); out truth/state {x, v, theta, theta_dot, x_ddot,
//     theta_ddot} (BalancingTruth).
//   body_mass, com_height, body_inertia, wheel_mass, wheel_radius, wheel_inertia, gravity,
//     max_torque (WheeledPendulumParams defaults; services/common/balancing_params.hpp),
//     theta0_deg (0), torque_noise_std (N m, 0: actuation noise drawn from the plant's
//     seed), substeps (4, RK4)
#include <memory>

#include "plexus/algorithms/balancing/wheeled_inverted_pendulum.hpp"
#include "plexus/algorithms/core/random.hpp"
#include "plexus/scenario/params.hpp"
#include "plexus/scenario/registry.hpp"
#include "services/common/balancing_params.hpp"

namespace plexus::scenario {
namespace {

namespace alg = plexus::algorithms;

class PendulumPlantComponent final : public Component {
 public:
  explicit PendulumPlantComponent(const ComponentConfig& c)
      : Component(c),
        plant_(pendulum_params(c.params())),
        h_(c.period()),
        torque_noise_(optional_non_negative(c.params(), "torque_noise_std")),
        substeps_(c.params().optional<int>("substeps", 4)),
        rng_(c.seed),
        cmd_(add_input("cmd", {"torque"}, "WheelTorqueCommand")),
        out_(add_output("truth/state", {"x", "v", "theta", "theta_dot", "x_ddot", "theta_ddot"}, "BalancingTruth")) {
    if (substeps_ < 1) c.params().fail("substeps", "must be >= 1");
    state_.theta = degrees(c.params(), "theta0_deg", 0.0);
    acc_ = plant_.accelerations(state_, 0.0);
  }

  void step(int64_t k, double /*t*/) override {
    if (k > 0) {
      double T = cmd_.valid() ? cmd_[0] : 0.0;
      if (torque_noise_ > 0.0) T += torque_noise_ * rng_.normal();
      acc_ = plant_.step(state_, T, h_, substeps_);
    }
    out_[0] = state_.x;
    out_[1] = state_.v;
    out_[2] = state_.theta;
    out_[3] = state_.theta_dot;
    out_[4] = acc_.x_ddot;
    out_[5] = acc_.theta_ddot;
  }

 private:
  alg::WheeledInvertedPendulum plant_;
  double h_;
  double torque_noise_;
  int substeps_;
  alg::Rng rng_;
  alg::WheeledPendulumState state_;
  alg::WheeledPendulumAccelerations acc_;
  InputPort& cmd_;
  OutputPort& out_;
};

const ComponentRegistration kBalancingPlant{
    "wheeled_inverted_pendulum",
    ComponentKind::plant,
    "two-wheeled balancing robot (paper 002 eq. (10)); in cmd {torque}, out truth/state {x, v, theta, theta_dot, "
    "x_ddot, theta_ddot}",
    [](const ComponentConfig& c) { return std::make_unique<PendulumPlantComponent>(c); },
    {"paper002.plant"}};

}  // namespace
}  // namespace plexus::scenario
