// Virtual decomposition control of an n-DoF flexible-joint arm (paper 004, section 3).
//
// Rigid-link subsystems (section 3.2), velocities from the base to the tip and required
// forces from the tip to the base, every quantity a 6-vector in the link frame {B_i}:
//   q_r' = q_d' + lambda (q_d - q)                                   (19)
//   B_iV   = B_{i-1}U_{B_i}^T B_{i-1}V   + Z q_i'                    (11)-(12)
//   B_iV_r = B_{i-1}U_{B_i}^T B_{i-1}V_r + Z q_ri'                   (13)
//   d/dt B_iV_r = U^T d/dt B_{i-1}V_r - crm(Z q_i') U^T B_{i-1}V_r + Z q_ri''
//   F_r*_i = Y_i theta_i^ + K_Bi (V_r,i - V_i)                       (9), Y_i from (8)
//   theta_i^ = P(Y_i^T (V_r,i - V_i), rho_i, theta-, theta+)         (10)
//   B_iF_r = F_r*_i + B_iU_{B_{i+1}} B_{i+1}F_r,   F_r,n+1 = 0       (15)
//   tau_od,i = Z^T B_iF_r                                            (after (23))
// Flexible-joint subsystems (section 3.3), one per joint:
//   tau_r = tau_od + k_p (q_r' - q') + t_s                           (20)
//   t_s  = P((q_r' - q'), k_I, t_s-, t_s+)                           (21)
//   phi_d = q + tau_r / K                                            (22)
//   phi_r' = phi_d' + lambda_q (q_r' - q') + lambda_phi (phi_d - phi) + lambda_tau (tau_r - tau)   (23)
//   u = J phi_r'' + F phi_r' + k_phi (phi_r' - phi') + tau_r + k_tau (tau_r - tau)                (18)
// with the time derivatives built algebraically from the signals the paper lists as needed
// (q, q', q'', phi, phi', tau, tau'; section 4), the link jerk q''' (from the observer's
// model) and the reference up to q_d''' (the paper is silent on how; docs/algorithms/arm.md):
//   q_r''' = q_d''' + lambda (q_d'' - q''),   q_r'''' = lambda (q_d''' - q''') (q_d'''' omitted),
//   tau_r' = tau_od' + k_p (q_r'' - q'') + t_s',   tau_r'' = tau_od'' + k_p (q_r''' - q''') + t_s'',
//   phi_d' = q' + tau_r'/K,   phi_d'' = q'' + tau_r''/K,
//   phi_r'' = phi_d'' + lambda_q (q_r'' - q'') + lambda_phi (phi_d' - phi') + lambda_tau (tau_r' - tau'),
// i.e. phi_r'' is the exact time derivative of (23). tau_od' and tau_od'' come from the link
// recursion T evaluated at t = 0, e, 2e along the second-order Taylor path of
// (q, q', q_r', q_r''): tau_od' = (4 T(e) - 3 T(0) - T(2e)) / 2e, tau_od'' = (T(0) - 2 T(e) +
// T(2e)) / e^2 (no time lag; the adaptation rate's contribution Y theta^' is neglected).
// The tau_r''/K term matters: its k_p q''' part (q''' ~ M^{-1} tau') feeds the spring rate
// back into the motor (J k_p / M ~ 250 N m s/rad on joint 2) and damps the joint-spring
// mode. Numerical differentiation in time (filtered) is NOT used: its lag destabilises the
// phi_r'' loop (measured; see the docs). Gravity enters through G_B = M_B [-g_B; 0] in the
// regressor.
//
// Every step is O(n): three base->tip / tip->base passes of the link recursion (t = 0, e,
// 2e), fixed-size 6x13 regressors per link; no allocation after construction.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "plexus/algorithms/arm/arm_feedback.hpp"
#include "plexus/algorithms/arm/arm_model.hpp"
#include "plexus/algorithms/arm/sine_reference.hpp"
#include "plexus/algorithms/arm/spatial.hpp"

namespace plexus::algorithms {

struct VdcParams {
  ArmModel model = ArmModel::paper_2dof();  ///< nominal model: the "true values" of the bounds
  // Rigid links (Table 3), one entry per link.
  Eigen::VectorXd k_b;  ///< K_Bi = k_b I6, > 0
  Eigen::VectorXd rho;  ///< adaptation gain for all 13 parameters of link i, >= 0
  // Flexible joints (Table 3), one entry per joint.
  Eigen::VectorXd lambda, k_p, k_i, ts_min, ts_max, lambda_q, lambda_phi, lambda_tau, k_phi, k_tau;
  double theta_lower = 0.6;       ///< lower adaptation bound, fraction of the nominal value (0.6 = 60 %)
  double theta_upper = 1.8;       ///< upper bound (1.8 = 180 %), > theta_lower
  double theta_initial = 1.0;     ///< theta^(0) as a fraction of the nominal value, in [lower, upper]
  double step = 1e-3;             ///< s, controller period, > 0
  double derivative_step = 1e-4;  ///< s, > 0: spacing e of the tau_od', tau_od'' differences
  /// Disturbance compensation (not in the paper; issue 18, docs/algorithms/arm.md "Model
  /// error"): tau_r gets - d^, d^ = ID_theta^(q, q', q'') - tau the residual of the adapted
  /// link model at the observer's estimate (the observer's disturbance state when it has
  /// one), scaled by this factor in [0, 1] (0: the paper's (20)).
  double disturbance_compensation = 0.0;
  /// Drive torque limit per joint (N m, > 0), empty: none (the paper). The output u is
  /// clamped to it, and anti-windup (docs/algorithms/arm.md "Torque limit"): while a joint's
  /// output was clamped at the previous step, its integral t_s (21) does not integrate
  /// towards the limit, and the parameter adaptation (10) of every link is held.
  Eigen::VectorXd torque_limit;

  /// disturbance_compensation of the robust tuning (docs/algorithms/arm.md "Model error").
  static constexpr double kRobustDisturbanceCompensation = 0.5;

  /// Table 3 gains for the paper's 2-DoF arm.
  static VdcParams paper_2dof();
  /// Table 3 joint-2 / link-2 gains repeated for every joint of `model`.
  static VdcParams uniform(const ArmModel& model);
};

class VdcController {
 public:
  /// Validates every parameter (sizes, signs, bounds); throws std::invalid_argument naming it.
  explicit VdcController(const VdcParams& params);

  int dof() const { return n_; }
  /// Restores theta^ = theta_initial * nominal and t_s = 0.
  void reset();

  /// One control step: returns the motor torques u (eq. (18)). No allocation.
  const Eigen::VectorXd& step(const ArmReferenceSample& ref, const ArmFeedback& fb);

  /// The rigid-link part alone: velocities base->tip, regressors, required forces
  /// tip->base, for given q, q', q_r', q_r''. Writes tau_od (n). With q_r' = q', q_r'' = q''
  /// and theta^ = nominal, tau_od is the inverse dynamics M q'' + C q' + G.
  void required_link_torques(const Eigen::VectorXd& q, const Eigen::VectorXd& qd, const Eigen::VectorXd& qr_d,
                             const Eigen::VectorXd& qr_dd, Eigen::VectorXd& tau_od);

  // Introspection (after a step or required_link_torques).
  const spatial::Vector6& link_velocity(int i) const { return links_[static_cast<std::size_t>(i)].v; }
  const spatial::Vector6& link_required_force(int i) const { return links_[static_cast<std::size_t>(i)].fr; }
  const spatial::Transform& link_transform(int i) const { return links_[static_cast<std::size_t>(i)].from_parent; }
  const spatial::Vector13& theta(int i) const { return links_[static_cast<std::size_t>(i)].theta; }
  const spatial::Vector13& theta_min(int i) const { return links_[static_cast<std::size_t>(i)].lo; }
  const spatial::Vector13& theta_max(int i) const { return links_[static_cast<std::size_t>(i)].hi; }
  const spatial::Vector13& theta_nominal(int i) const { return links_[static_cast<std::size_t>(i)].nominal; }
  const Eigen::VectorXd& ts() const { return ts_; }
  /// d^ of the last step (zero without disturbance compensation).
  const Eigen::VectorXd& disturbance() const { return dist_; }
  /// Per joint: +1 / -1 when the last output was clamped at the upper / lower limit, else 0.
  const Eigen::VectorXd& saturation() const { return saturated_; }
  const VdcParams& params() const { return params_; }

 private:
  struct Link {
    spatial::Transform from_parent;  ///< {B_{i-1}} -> {B_i} (base frame for i = 0)
    Eigen::Matrix3d twist_rotation;  ///< RotX(twist of link i-1), constant (i > 0)
    Eigen::Matrix3d base_rotation;   ///< 0_R_{B_i}
    spatial::Vector6 v, vr, dvr, fr;
    spatial::Regressor y;
    spatial::Vector13 theta, lo, hi, nominal;
    spatial::Matrix6 inertia;  ///< M_B(theta^), refreshed at each step
  };

  void adapt();
  /// The recursion of required_link_torques with M_B(theta^) as it stands; the regressors
  /// Y_i (for the adaptation) only when `regressor`.
  void link_torques(const Eigen::VectorXd& q, const Eigen::VectorXd& qd, const Eigen::VectorXd& qr_d,
                    const Eigen::VectorXd& qr_dd, Eigen::VectorXd& tau_od, bool regressor);

  VdcParams params_;
  int n_;
  std::vector<Link> links_;
  Eigen::VectorXd stiffness_, motor_inertia_, friction_;
  Eigen::VectorXd qr_d_, qr_dd_, qr_ddd_, qr_dddd_, tau_od_, ts_, ts_rate_, u_;
  Eigen::VectorXd q_e_, qd_e_, qr_d_e_, qr_dd_e_, tau_od_1_, tau_od_2_, dist_, saturated_;
};

}  // namespace plexus::algorithms
