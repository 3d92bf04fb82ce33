// arm_vdc (controller; joint_controller): virtual decomposition control of the
// flexible-joint arm (paper 004 eqs. (9)-(23); docs/algorithms/arm.md).
//
//   the arm model keys (services/common/arm_model_params.hpp: model, dof, length ..
//   stiffness, gravity, payload_mass) + k_b, rho, lambda, k_p, k_i, ts_min, ts_max,
//   lambda_q, lambda_phi, lambda_tau, k_phi, k_tau (lists; default Table 3), theta_lower
//   (0.6), theta_upper (1.8), theta_initial (1.0), disturbance_compensation (robust preset:
//   see `tuning`), torque_limit (list, N m; default none), tuning (robust | paper).
//   in reference {q1.., dq1.., ddq1.., dddq1..} (JointReference), estimate {q1.., dq1..,
//   ddq1.., dddq1.., tau1.., dtau1.., phi1.., dphi1..} (LinkJointState);
//   out cmd {u1..un} (JointCommand; 0 until both inputs exist).
#include <memory>
#include <string>
#include <utility>

#include "plexus/algorithms/arm/vdc_controller.hpp"
#include "plexus/scenario/params.hpp"
#include "plexus/scenario/registry.hpp"
#include "services/common/arm_model_params.hpp"
#include "services/joint_controller/arm_controller_base.hpp"

namespace plexus::scenario {
namespace {

namespace alg = plexus::algorithms;

alg::VdcParams read_vdc(const ComponentConfig& c) {
  const YamlMap& p = c.params();
  const alg::ArmModel model = read_model(p);
  alg::VdcParams v = p.optional<std::string>("model", "paper_2dof") == "paper_2dof" ? alg::VdcParams::paper_2dof()
                                                                                    : alg::VdcParams::uniform(model);
  v.model = model;
  // tuning: robust (default; docs/algorithms/arm.md "Model error") feeds half of the
  // observer's model residual forward; paper is eqs. (18)-(23) as printed.
  const std::string tuning = choice(p, "tuning", "robust", {"robust", "paper"});
  v.disturbance_compensation = tuning == "robust" ? alg::VdcParams::kRobustDisturbanceCompensation : 0.0;
  for (auto [key, vec] : {std::pair{"k_b", &v.k_b},
                          {"rho", &v.rho},
                          {"lambda", &v.lambda},
                          {"k_p", &v.k_p},
                          {"k_i", &v.k_i},
                          {"ts_min", &v.ts_min},
                          {"ts_max", &v.ts_max},
                          {"lambda_q", &v.lambda_q},
                          {"lambda_phi", &v.lambda_phi},
                          {"lambda_tau", &v.lambda_tau},
                          {"k_phi", &v.k_phi},
                          {"k_tau", &v.k_tau}}) {
    read_into(p, key, *vec);
  }
  v.theta_lower = p.optional<double>("theta_lower", v.theta_lower);
  v.theta_upper = p.optional<double>("theta_upper", v.theta_upper);
  v.theta_initial = p.optional<double>("theta_initial", v.theta_initial);
  v.disturbance_compensation = p.optional<double>("disturbance_compensation", v.disturbance_compensation);
  if (p.has("torque_limit")) {
    v.torque_limit = Eigen::VectorXd::Zero(model.dof());
    read_into(p, "torque_limit", v.torque_limit);
  }
  v.step = c.period();
  return v;
}

class ArmVdcComponent final : public ArmControllerBase {
 public:
  explicit ArmVdcComponent(const ComponentConfig& c) : ArmVdcComponent(c, read_vdc(c)) {}
  void step(int64_t /*k*/, double /*t*/) override {
    if (read() && !write(vdc_.step(sample_, fb_))) vdc_.reset();
  }

 private:
  ArmVdcComponent(const ComponentConfig& c, const alg::VdcParams& p) : ArmControllerBase(c, p.model.dof()), vdc_(p) {}
  alg::VdcController vdc_;
};

const ComponentRegistration kArmVdc{"arm_vdc",
                                    ComponentKind::controller,
                                    "virtual decomposition control (paper 004 eqs. (9)-(23))",
                                    [](const ComponentConfig& c) { return std::make_unique<ArmVdcComponent>(c); },
                                    {"paper004.controller"}};

}  // namespace
}  // namespace plexus::scenario
