#include "plexus/algorithms/arm/ct_pd_controller.hpp"

#include <string>

#include "plexus/algorithms/core/validation.hpp"

namespace plexus::algorithms {

CtPdParams CtPdParams::paper_2dof() {
  CtPdParams p;
  p.k_p = Eigen::Vector2d(1900, 500);
  p.k_v = Eigen::Vector2d(500, 150);
  p.k_d = Eigen::Vector2d(110, 110);
  return p;
}

CtPdController::CtPdController(const CtPdParams& p) : params_(p), n_(p.model.dof()), dyn_(p.model) {
  const std::pair<const char*, const Eigen::VectorXd*> gains[] = {{"k_p", &p.k_p}, {"k_v", &p.k_v}, {"k_d", &p.k_d}};
  for (const auto& [name, v] : gains) {
    if (v->size() != n_) {
      validation::fail("ct_pd_controller", std::string(name) + " size", "the joint count " + std::to_string(n_),
                       static_cast<double>(v->size()));
    }
    for (int i = 0; i < n_; ++i) {
      validation::require_non_negative("ct_pd_controller", std::string(name) + "[" + std::to_string(i) + "]", (*v)(i));
    }
  }
  u_ = Eigen::VectorXd::Zero(n_);
}

const Eigen::VectorXd& CtPdController::step(const ArmReferenceSample& ref, const ArmFeedback& fb) {
  const Eigen::VectorXd& a = params_.acceleration == CtPdAcceleration::kDesired ? ref.qdd : fb.qdd;
  dyn_.inverse_dynamics(fb.q, fb.qd, a, u_);  // M(q) q_d'' + C(q, q') q' + G(q)
  if (params_.inertia == CtPdInertia::kWithMotors)
    for (int i = 0; i < n_; ++i) {
      const ArmJoint& j = params_.model.joints[static_cast<std::size_t>(i)];
      u_(i) += j.motor_inertia * a(i) + j.friction * ref.qd(i);  // eq. (16) at phi = q
    }
  const Eigen::VectorXd& v = params_.velocity == CtPdVelocity::kLink ? fb.qd : fb.phid;
  u_ += params_.k_p.cwiseProduct(ref.q - fb.q) + params_.k_v.cwiseProduct(ref.qd - v) +
        params_.k_d.cwiseProduct(fb.qd - fb.phid);  // eq. (60)
  return u_;
}

}  // namespace plexus::algorithms
