// joint_encoders (sensor; plant_simulator): the arm's motor encoders (paper 004;
// docs/algorithms/arm.md).
//
//   dof (2), position_noise_std (rad, 0), velocity_noise_std (rad/s, 0).
//   in truth/state {phi.., dphi..}; out <sensor name> {phi1.., dphi1..}
//   (JointState, motor side: the scenarios name it joint_states).
#include <memory>
#include <string>

#include "plexus/algorithms/core/random.hpp"
#include "plexus/scenario/params.hpp"
#include "plexus/scenario/registry.hpp"
#include "services/common/arm_fields.hpp"

namespace plexus::scenario {
namespace {

namespace alg = plexus::algorithms;

/// The motor encoders: phi and phi' of every joint, with optional Gaussian noise (position
/// noises drawn first, then velocity, from the sensor's own seed).
class JointEncodersComponent final : public Component {
 public:
  explicit JointEncodersComponent(const ComponentConfig& c)
      : Component(c),
        n_(dof(c.params())),
        position_std_(optional_non_negative(c.params(), "position_noise_std")),
        velocity_std_(optional_non_negative(c.params(), "velocity_noise_std")),
        rng_(c.seed),
        in_(add_input("truth/state", concat({names("phi", n_), names("dphi", n_)}), "FlexibleJointTruth")),
        out_(add_output(c.key, concat({names("phi", n_), names("dphi", n_)}), "JointState")) {}

  void step(int64_t /*k*/, double /*t*/) override {
    const auto n = static_cast<std::size_t>(n_);
    for (std::size_t i = 0; i < n; ++i) out_[i] = position_std_ > 0.0 ? in_[i] + position_std_ * rng_.normal() : in_[i];
    for (std::size_t i = n; i < 2 * n; ++i)
      out_[i] = velocity_std_ > 0.0 ? in_[i] + velocity_std_ * rng_.normal() : in_[i];
  }

 private:
  static int dof(const YamlMap& p) {
    const int n = p.optional<int>("dof", 2);
    if (n < 1 || n > kMaxScenarioDof) p.fail("dof", "must be in 1.." + std::to_string(kMaxScenarioDof));
    return n;
  }
  int n_;
  double position_std_, velocity_std_;
  alg::Rng rng_;
  InputPort& in_;
  OutputPort& out_;
};

const ComponentRegistration kJointEncoders{
    "joint_encoders", ComponentKind::sensor, "motor encoders: phi and phi' per joint with optional noise",
    [](const ComponentConfig& c) { return std::make_unique<JointEncodersComponent>(c); }};

}  // namespace
}  // namespace plexus::scenario
