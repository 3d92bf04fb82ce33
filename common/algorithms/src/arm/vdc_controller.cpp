#include "plexus/algorithms/arm/vdc_controller.hpp"

#include <cmath>
#include <string>

#include <Eigen/Geometry>

#include "plexus/algorithms/arm/p_function.hpp"
#include "plexus/algorithms/core/validation.hpp"

namespace plexus::algorithms {
namespace {

constexpr const char* kWhereVdcController = "vdc_controller";

enum class Sign { positive, non_negative, negative };

void require_vector(const char* name, const Eigen::VectorXd& v, int n, Sign sign) {
  if (v.size() != n) {
    validation::fail(kWhereVdcController, std::string(name) + " size", "the joint count " + std::to_string(n),
                     static_cast<double>(v.size()));
  }
  for (int i = 0; i < n; ++i) {
    const std::string key = std::string(name) + "[" + std::to_string(i) + "]";
    if (sign == Sign::positive) validation::require_positive(kWhereVdcController, key, v(i));
    if (sign == Sign::non_negative) validation::require_non_negative(kWhereVdcController, key, v(i));
    if (sign == Sign::negative && !(std::isfinite(v(i)) && v(i) < 0.0))
      validation::fail(kWhereVdcController, key, "finite and < 0", v(i));
  }
}

Eigen::VectorXd per_joint(int n, double v) { return Eigen::VectorXd::Constant(n, v); }

constexpr int kAngular = 5;  // Z = [0 0 0 0 0 1]^T: the joint axis is z of {B_i}

}  // namespace

VdcParams VdcParams::paper_2dof() {
  VdcParams p;
  p.model = ArmModel::paper_2dof();
  // Table 3.
  p.k_b = Eigen::Vector2d(30, 20);
  p.rho = Eigen::Vector2d(50, 50);
  p.lambda = Eigen::Vector2d(20, 20);
  p.k_p = Eigen::Vector2d(350, 200);
  p.k_i = Eigen::Vector2d(2000, 2000);
  p.ts_min = Eigen::Vector2d(-500, -500);
  p.ts_max = Eigen::Vector2d(500, 500);
  p.lambda_q = Eigen::Vector2d(0.8, 0.5);
  p.lambda_phi = Eigen::Vector2d(20, 10);
  p.lambda_tau = Eigen::Vector2d(0.005, 0.005);
  p.k_phi = Eigen::Vector2d(200, 100);
  p.k_tau = Eigen::Vector2d(0.5, 0.5);
  return p;
}

VdcParams VdcParams::uniform(const ArmModel& model) {
  const int n = model.dof();
  VdcParams p;
  p.model = model;
  p.k_b = per_joint(n, 20), p.rho = per_joint(n, 50), p.lambda = per_joint(n, 20), p.k_p = per_joint(n, 200);
  p.k_i = per_joint(n, 2000), p.ts_min = per_joint(n, -500), p.ts_max = per_joint(n, 500);
  p.lambda_q = per_joint(n, 0.5), p.lambda_phi = per_joint(n, 10), p.lambda_tau = per_joint(n, 0.005);
  p.k_phi = per_joint(n, 100), p.k_tau = per_joint(n, 0.5);
  return p;
}

VdcController::VdcController(const VdcParams& p) : params_(p), n_(p.model.dof()) {
  p.model.validate();
  require_vector("k_b", p.k_b, n_, Sign::positive);
  require_vector("rho", p.rho, n_, Sign::non_negative);
  require_vector("lambda", p.lambda, n_, Sign::positive);
  require_vector("k_p", p.k_p, n_, Sign::positive);
  require_vector("k_i", p.k_i, n_, Sign::non_negative);
  require_vector("ts_min", p.ts_min, n_, Sign::negative);
  require_vector("ts_max", p.ts_max, n_, Sign::positive);
  require_vector("lambda_q", p.lambda_q, n_, Sign::positive);
  require_vector("lambda_phi", p.lambda_phi, n_, Sign::positive);
  require_vector("lambda_tau", p.lambda_tau, n_, Sign::positive);
  require_vector("k_phi", p.k_phi, n_, Sign::positive);
  require_vector("k_tau", p.k_tau, n_, Sign::positive);
  validation::require_open_interval(kWhereVdcController, "theta_lower", p.theta_lower, 0.0, 1.0 + 1e-12);
  if (!(std::isfinite(p.theta_upper) && p.theta_upper >= 1.0))
    validation::fail(kWhereVdcController, "theta_upper", "finite and >= 1", p.theta_upper);
  if (!(p.theta_initial >= p.theta_lower && p.theta_initial <= p.theta_upper)) {
    validation::fail(kWhereVdcController, "theta_initial",
                     "in [theta_lower, theta_upper] = [" + validation::format_value(p.theta_lower) + ", " +
                         validation::format_value(p.theta_upper) + "]",
                     p.theta_initial);
  }
  validation::require_positive(kWhereVdcController, "derivative_step", p.derivative_step);
  validation::require_positive(kWhereVdcController, "step", p.step);
  if (p.torque_limit.size() != 0) require_vector("torque_limit", p.torque_limit, n_, Sign::positive);
  if (!(p.disturbance_compensation >= 0.0 && p.disturbance_compensation <= 1.0)) {
    validation::fail(kWhereVdcController, "disturbance_compensation", "in [0, 1]", p.disturbance_compensation);
  }

  links_.resize(static_cast<std::size_t>(n_));
  stiffness_.resize(n_), motor_inertia_.resize(n_), friction_.resize(n_);
  for (int i = 0; i < n_; ++i) {
    const ArmLink& l = p.model.links[static_cast<std::size_t>(i)];
    const ArmJoint& j = p.model.joints[static_cast<std::size_t>(i)];
    stiffness_(i) = j.stiffness, motor_inertia_(i) = j.motor_inertia, friction_(i) = j.friction;
    Link& k = links_[static_cast<std::size_t>(i)];
    k.nominal = spatial::link_parameters(l.mass, Eigen::Vector3d(l.com, 0.0, 0.0),
                                         Eigen::Vector3d(l.inertia_xx_com(), l.inertia_yy_com(), l.inertia_zz_com()));
    k.lo = (p.theta_lower * k.nominal).cwiseMin(p.theta_upper * k.nominal);
    k.hi = (p.theta_lower * k.nominal).cwiseMax(p.theta_upper * k.nominal);
    k.v.setZero(), k.vr.setZero(), k.dvr.setZero(), k.fr.setZero(), k.y.setZero();
    k.inertia = spatial::spatial_inertia(k.nominal);
    k.base_rotation.setIdentity();
    // The constant part of {B_{i-1}} -> {B_i} (eq. (2)-(3)); link_torques() adds RotZ(q_i).
    const spatial::Transform fixed = p.model.fixed_link_frame(i);
    k.twist_rotation = fixed.rotation;
    k.from_parent.origin = fixed.origin;
  }
  const Eigen::VectorXd z = Eigen::VectorXd::Zero(n_);
  qr_d_ = qr_dd_ = qr_ddd_ = qr_dddd_ = tau_od_ = ts_ = ts_rate_ = u_ = z;
  q_e_ = qd_e_ = qr_d_e_ = qr_dd_e_ = tau_od_1_ = tau_od_2_ = dist_ = saturated_ = z;
  reset();
}

void VdcController::reset() {
  for (Link& k : links_) k.theta = params_.theta_initial * k.nominal;
  ts_.setZero();
  saturated_.setZero();
}

void VdcController::required_link_torques(const Eigen::VectorXd& q, const Eigen::VectorXd& qd,
                                          const Eigen::VectorXd& qr_d, const Eigen::VectorXd& qr_dd,
                                          Eigen::VectorXd& tau_od) {
  for (Link& k : links_) k.inertia = spatial::spatial_inertia(k.theta);
  link_torques(q, qd, qr_d, qr_dd, tau_od, true);
}

void VdcController::link_torques(const Eigen::VectorXd& q, const Eigen::VectorXd& qd, const Eigen::VectorXd& qr_d,
                                 const Eigen::VectorXd& qr_dd, Eigen::VectorXd& tau_od, bool regressor) {
  const ArmModel& m = params_.model;
  // Base -> tip: frames, V, V_r and d/dt V_r (eqs. (11)-(13)); the base does not move.
  spatial::Vector6 v_parent = spatial::Vector6::Zero(), vr_parent = v_parent, dvr_parent = v_parent;
  Eigen::Matrix3d r_parent = Eigen::Matrix3d::Identity();
  for (int i = 0; i < n_; ++i) {
    Link& k = links_[static_cast<std::size_t>(i)];
    const double c = std::cos(q(i)), s = std::sin(q(i));
    Eigen::Matrix3d rz;
    rz << c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0;
    if (i == 0) {
      k.from_parent.rotation = rz;
    } else {
      k.from_parent.rotation = k.twist_rotation * rz;
    }
    k.base_rotation = r_parent * k.from_parent.rotation;
    const spatial::Vector6 vr_in = spatial::velocity_to_child(k.from_parent, vr_parent);
    k.v = spatial::velocity_to_child(k.from_parent, v_parent);
    k.v(kAngular) += qd(i);
    k.vr = vr_in;
    k.vr(kAngular) += qr_d(i);
    spatial::Vector6 joint_twist = spatial::Vector6::Zero();
    joint_twist(kAngular) = qd(i);
    k.dvr = spatial::velocity_to_child(k.from_parent, dvr_parent) - spatial::cross_motion(joint_twist, vr_in);
    k.dvr(kAngular) += qr_dd(i);
    // Eq. (8)-(9): F_r* = Y theta^ + K_B (V_r - V), gravity in {B_i}, evaluated as
    // Y theta^ = M_B(theta^) (dV_r - [g_B; 0] + crm(V) V_r) + crf(V) M_B(theta^) V_r (spatial.hpp);
    // Y itself only where the adaptation needs it.
    const Eigen::Vector3d gravity_b = k.base_rotation.transpose() * m.gravity;
    if (regressor) k.y = spatial::link_regressor(k.dvr, k.vr, k.v, gravity_b);
    spatial::Vector6 a = k.dvr + spatial::cross_motion(k.v, k.vr);
    a.head<3>() -= gravity_b;
    k.fr.noalias() = k.inertia * a;
    k.fr +=
        spatial::cross_force(k.v, k.inertia * k.vr) + params_.k_b(i) * (k.vr - k.v);  // F_r*; (15) adds the child below
    v_parent = k.v, vr_parent = k.vr, dvr_parent = k.dvr, r_parent = k.base_rotation;
  }
  // Tip -> base: B_iF_r = F_r*_i + B_iU_{B_{i+1}} B_{i+1}F_r (eq. (15)); tau_od = Z^T F_r.
  for (int i = n_ - 1; i >= 0; --i) {
    Link& k = links_[static_cast<std::size_t>(i)];
    if (i + 1 < n_) {
      const Link& child = links_[static_cast<std::size_t>(i + 1)];
      k.fr += spatial::force_to_parent(child.from_parent, child.fr);
    }
    tau_od(i) = k.fr(kAngular);
  }
}

void VdcController::adapt() {
  // Eq. (10): theta^_gamma = P(s_gamma, rho, theta-, theta+), s = Y^T (V_r - V).
  for (int i = 0; i < n_; ++i) {
    Link& k = links_[static_cast<std::size_t>(i)];
    const spatial::Vector13 s = k.y.transpose() * (k.vr - k.v);
    for (int g = 0; g < 13; ++g) p_function_step(k.theta(g), params_.rho(i), s(g), k.lo(g), k.hi(g), params_.step);
  }
}

const Eigen::VectorXd& VdcController::step(const ArmReferenceSample& ref, const ArmFeedback& fb) {
  const VdcParams& p = params_;
  // Eq. (19) and its first three derivatives (q_d'''' omitted, header comment).
  qr_d_ = ref.qd + p.lambda.cwiseProduct(ref.q - fb.q);
  qr_dd_ = ref.qdd + p.lambda.cwiseProduct(ref.qd - fb.qd);
  qr_ddd_ = ref.qddd + p.lambda.cwiseProduct(ref.qdd - fb.qdd);
  qr_dddd_ = p.lambda.cwiseProduct(ref.qddd - fb.qddd);
  // tau_od' and tau_od'' (header comment): the link recursion at t = e and 2e along the
  // second-order Taylor path of (q, q', q_r', q_r''), then at t = 0 last, so the links keep
  // the nominal pass for the adaptation below.
  for (Link& k : links_) k.inertia = spatial::spatial_inertia(k.theta);  // M_B(theta^) of this step
  if (p.disturbance_compensation > 0.0) {
    // d^ = ID_theta^(q, q', q'') - tau (the link recursion with q_r' = q', q_r'' = q'').
    link_torques(fb.q, fb.qd, fb.qd, fb.qdd, dist_, false);
    dist_ = p.disturbance_compensation * (dist_ - fb.tau);
  }
  const double e = p.derivative_step;
  for (const int m : {1, 2}) {
    const double t = m * e, t2 = 0.5 * t * t;
    q_e_ = fb.q + t * fb.qd + t2 * fb.qdd;
    qd_e_ = fb.qd + t * fb.qdd + t2 * fb.qddd;
    qr_d_e_ = qr_d_ + t * qr_dd_ + t2 * qr_ddd_;
    qr_dd_e_ = qr_dd_ + t * qr_ddd_ + t2 * qr_dddd_;
    link_torques(q_e_, qd_e_, qr_d_e_, qr_dd_e_, m == 1 ? tau_od_1_ : tau_od_2_, false);
  }
  link_torques(fb.q, fb.qd, qr_d_, qr_dd_, tau_od_, true);  // with Y, for the adaptation
  if (saturated_.cwiseAbs().maxCoeff() == 0.0) adapt();     // anti-windup: held while a drive saturates
  for (int i = 0; i < n_; ++i) {
    const double ev = qr_d_(i) - fb.qd(i);      // q_r' - q'
    const double ea = qr_dd_(i) - fb.qdd(i);    // q_r'' - q''
    const double ej = qr_ddd_(i) - fb.qddd(i);  // q_r''' - q'''
    // (21); anti-windup: no integration towards a limit the output was clamped at.
    const bool hold = saturated_(i) * ev > 0.0;
    ts_rate_(i) = hold ? 0.0 : p_function_step(ts_(i), p.k_i(i), ev, p.ts_min(i), p.ts_max(i), p.step);
    const double ts_acc = (ts_(i) > p.ts_min(i) && ts_(i) < p.ts_max(i)) ? p.k_i(i) * ea : 0.0;
    const double taud_od = (4.0 * tau_od_1_(i) - 3.0 * tau_od_(i) - tau_od_2_(i)) / (2.0 * e);
    const double taudd_od = (tau_od_(i) - 2.0 * tau_od_1_(i) + tau_od_2_(i)) / (e * e);
    const double tau_r = tau_od_(i) - dist_(i) + p.k_p(i) * ev + ts_(i);  // (20)
    const double taud_r = taud_od + p.k_p(i) * ea + ts_rate_(i);
    const double taudd_r = taudd_od + p.k_p(i) * ej + ts_acc;
    const double phi_d = fb.q(i) + tau_r / stiffness_(i);  // (22)
    const double phid_d = fb.qd(i) + taud_r / stiffness_(i);
    const double phidd_d = fb.qdd(i) + taudd_r / stiffness_(i);
    const double phir_d = phid_d + p.lambda_q(i) * ev + p.lambda_phi(i) * (phi_d - fb.phi(i)) +
                          p.lambda_tau(i) * (tau_r - fb.tau(i));  // (23)
    const double phir_dd = phidd_d + p.lambda_q(i) * ea + p.lambda_phi(i) * (phid_d - fb.phid(i)) +
                           p.lambda_tau(i) * (taud_r - fb.taud(i));
    u_(i) = motor_inertia_(i) * phir_dd + friction_(i) * phir_d + p.k_phi(i) * (phir_d - fb.phid(i)) + tau_r +
            p.k_tau(i) * (tau_r - fb.tau(i));  // (18)
    saturated_(i) = 0.0;
    if (p.torque_limit.size() != 0) {
      const double limit = p.torque_limit(i);
      if (u_(i) > limit) u_(i) = limit, saturated_(i) = 1.0;
      if (u_(i) < -limit) u_(i) = -limit, saturated_(i) = -1.0;
    }
  }
  return u_;
}

}  // namespace plexus::algorithms
