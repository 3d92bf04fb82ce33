// flexible_joint_arm (plant; plant_simulator): the n-DoF flexible-joint arm of paper 004
// (docs/algorithms/arm.md), KDL dynamics, RK4 sub-steps.
//
//   the arm model keys (services/common/arm_model_params.hpp: model, dof, length .. stiffness,
//     gravity, payload_mass) + q0 (list, default 0), dq0 (list, default 0: at rest): the
//     arm starts in steady motion at (q0, dq0), motors at dq0, springs holding C q' + G;
//     max_substep (s, default 1e-4: RK4 sub-step inside each plant period), torque_limit
//     (list, N m per joint, > 0; default none: the drive applies any torque).
//   in cmd {u1..un} (JointCommand); out truth/state {q1..qn, dq1..dqn, phi1..phin,
//     dphi1..dphin, tau1..taun} (FlexibleJointTruth: link side, motor side, joint torque;
//     for metrics).
#include <memory>
#include <string>

#include "plexus/algorithms/arm/flexible_joint_plant.hpp"
#include "plexus/scenario/registry.hpp"
#include "services/common/arm_fields.hpp"
#include "services/common/arm_model_params.hpp"

namespace plexus::scenario {
namespace {

namespace alg = plexus::algorithms;

alg::FlexibleJointArmParams read_plant(const YamlMap& p) {
  alg::FlexibleJointArmParams a{read_model(p), p.optional<double>("max_substep", 1e-4), {}};
  if (p.has("torque_limit")) {
    a.torque_limit = Eigen::VectorXd::Zero(a.model.dof());
    read_into(p, "torque_limit", a.torque_limit);
  }
  return a;
}

class FlexibleJointArmComponent final : public Component {
 public:
  explicit FlexibleJointArmComponent(const ComponentConfig& c)
      : Component(c),
        plant_(read_plant(c.params())),
        n_(plant_.dof()),
        h_(c.period()),
        u_(Eigen::VectorXd::Zero(n_)),
        tau_(Eigen::VectorXd::Zero(n_)),
        cmd_(add_input("cmd", names("u", n_), "JointCommand")),
        state_(
            add_output("truth/state",
                       concat({names("q", n_), names("dq", n_), names("phi", n_), names("dphi", n_), names("tau", n_)}),
                       "FlexibleJointTruth")) {
    if (n_ > kMaxScenarioDof)
      c.params().fail("model", "has " + std::to_string(n_) + " joints; at most " + std::to_string(kMaxScenarioDof));
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n_);
    plant_.reset_in_motion(number_list(c.params(), "q0", n_, zero), number_list(c.params(), "dq0", n_, zero));
  }

  void step(int64_t k, double /*t*/) override {
    if (k > 0) {
      // The arm moves whether or not a command arrived: without one (realtime, before the
      // first command) its drives hold the last torque (zero at first).
      if (cmd_.valid())
        for (int i = 0; i < n_; ++i) u_(i) = cmd_[static_cast<std::size_t>(i)];
      plant_.step(u_, h_);
    }
    const alg::FlexibleJointArmState& s = plant_.state();
    plant_.spring_torque(tau_);
    const auto n = static_cast<std::size_t>(n_);
    for (int i = 0; i < n_; ++i) {
      const auto a = static_cast<std::size_t>(i);
      state_[a] = s.q(i), state_[n + a] = s.qd(i);
      state_[2 * n + a] = s.phi(i), state_[3 * n + a] = s.phid(i);
      state_[4 * n + a] = tau_(i);
    }
  }

 private:
  alg::FlexibleJointArmPlant plant_;
  int n_;
  double h_;
  Eigen::VectorXd u_, tau_;
  InputPort& cmd_;
  OutputPort& state_;
};

const ComponentRegistration kArmPlant{
    "flexible_joint_arm",
    ComponentKind::plant,
    "n-DoF flexible-joint arm (paper 004), KDL dynamics, RK4 sub-steps; in cmd, out truth/state",
    [](const ComponentConfig& c) { return std::make_unique<FlexibleJointArmComponent>(c); },
    {"paper004.plant"}};

}  // namespace
}  // namespace plexus::scenario
