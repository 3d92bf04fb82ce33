// arm_ct_pd (controller; joint_controller): computed torque + PD, the comparator of paper
// 004 eq. (60) (docs/algorithms/arm.md).
//
//   the arm model keys (services/common/arm_model_params.hpp: model, dof, length ..
//   stiffness, gravity, payload_mass) + k_p, k_v, k_d (lists; default eq. (60)'s gains for
//   2 joints, 0 otherwise), velocity (motor | link, default motor), inertia (links |
//   with_motors, default links), acceleration (desired | estimated, default desired): the
//   readings of (60), docs/algorithms/arm.md "Table 4: the set-up".
//   in reference {q1.., dq1.., ddq1.., dddq1..} (JointReference), estimate {q1.., dq1..,
//   ddq1.., dddq1.., tau1.., dtau1.., phi1.., dphi1..} (LinkJointState);
//   out cmd {u1..un} (JointCommand; 0 until both inputs exist).
#include <memory>
#include <string>

#include "plexus/algorithms/arm/ct_pd_controller.hpp"
#include "plexus/scenario/params.hpp"
#include "plexus/scenario/registry.hpp"
#include "services/common/arm_model_params.hpp"
#include "services/joint_controller/arm_controller_base.hpp"

namespace plexus::scenario {
namespace {

namespace alg = plexus::algorithms;

alg::CtPdParams read_ct_pd(const YamlMap& p) {
  alg::CtPdParams v = alg::CtPdParams::paper_2dof();
  v.model = read_model(p);
  const int n = v.model.dof();
  if (n != 2) v.k_p = v.k_v = v.k_d = Eigen::VectorXd::Zero(n);
  read_into(p, "k_p", v.k_p);
  read_into(p, "k_v", v.k_v);
  read_into(p, "k_d", v.k_d);
  v.velocity = choice(p, "velocity", "motor", {"motor", "link"}) == "motor" ? alg::CtPdVelocity::kMotor
                                                                            : alg::CtPdVelocity::kLink;
  v.inertia = choice(p, "inertia", "links", {"links", "with_motors"}) == "links" ? alg::CtPdInertia::kLinks
                                                                                 : alg::CtPdInertia::kWithMotors;
  v.acceleration = choice(p, "acceleration", "desired", {"desired", "estimated"}) == "desired"
                       ? alg::CtPdAcceleration::kDesired
                       : alg::CtPdAcceleration::kEstimated;
  return v;
}

class ArmCtPdComponent final : public ArmControllerBase {
 public:
  explicit ArmCtPdComponent(const ComponentConfig& c) : ArmCtPdComponent(c, read_ct_pd(c.params())) {}
  void step(int64_t /*k*/, double /*t*/) override {
    if (read()) write(ctpd_.step(sample_, fb_));
  }

 private:
  ArmCtPdComponent(const ComponentConfig& c, const alg::CtPdParams& p)
      : ArmControllerBase(c, p.model.dof()), ctpd_(p) {}
  alg::CtPdController ctpd_;
};

const ComponentRegistration kArmCtPd{"arm_ct_pd",
                                     ComponentKind::controller,
                                     "computed torque + PD comparator (paper 004 eq. (60))",
                                     [](const ComponentConfig& c) { return std::make_unique<ArmCtPdComponent>(c); },
                                     {"paper004.controller"}};

}  // namespace
}  // namespace plexus::scenario
