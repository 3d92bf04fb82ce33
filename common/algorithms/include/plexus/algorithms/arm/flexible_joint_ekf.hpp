// "Indirect" EKF observer of a flexible-joint arm (paper 004, section 4.2), continuous time.
//
// State x = [tau, tau', phi, phi'] (4n), measurement y = h(x) = [phi, phi'] (eq. (29)):
//   f(x, u) = [tau'; K (phi'' - q''); phi'; phi'']                        (35)
//   phi'' = J^{-1} (u - tau - F phi'),   q'' = M(q)^{-1} (tau - C(q, q') q' - G(q)),
//   q = phi - K^{-1} tau,   q' = phi' - K^{-1} tau'                        (17)
// (K (phi'' - q'') is the paper's N expanded.) The filter (eqs. (31)-(33)):
//   x^' = f(x^, u) + L (y - h(x^)),   P' = F P + P F^T + Q - L H P,   L = P H^T R^{-1},
// with Q = q I, R = r I, P(0) = p0 I (paper: 4, 0.1, 1).
//
// Jacobian F = df/dx:
//  - kFull (default): exact, including the dependence of M, C, G on q(phi, tau) and
//    q'(phi', tau'); with A = dq''/dq = -M^{-1} dID/dq, B = dq''/dq' = -M^{-1} dID/dq'
//    (exact: the tangents of chain_dynamics.hpp; `fd_step` is accepted and not read):
//      df2/dtau = K (-J^{-1} - M^{-1} + A K^{-1}),  df2/dtau' = K B K^{-1},
//      df2/dphi = -K A,                               df2/dphi' = -K (J^{-1} F + B),
//      df4/dtau = -J^{-1},                             df4/dphi' = -J^{-1} F.
//  - kPaper: eq. (36), i.e. A = B = 0; the printed (4,1) block J^{-1} has the wrong sign
//    (phi'' = J^{-1}(u - tau - F phi')), we use -J^{-1}.
//
// Integration over one controller step dt (the EKF runs inside the controller's step):
// `substeps` RK4 steps of x^ with P held, then of P with F held (both refreshed each
// sub-step); u is held over the step (zero-order hold) and y interpolated linearly between
// the previous sample and this one (first-order hold; holding y_k biases the estimate by
// about half a step).
// Link side: q^ = phi^ - K^{-1} tau^, q^' = phi^' - K^{-1} tau^'. q^'' (LinkAcceleration):
//  - kModel (default): the observer's own forward dynamics M^{-1}(tau^ - C q^' - G) at x^,
//    algebraic, no lag;
//  - kDifferentiator: a filtered differentiator of q^' (the paper's section 4, cutoff
//    `accel_filter_hz`). Its lag destabilises the VDC phi_r'' loop at 1 kHz (measured, see
//    docs/algorithms/arm.md), so it is not the default.
// q^''' (the VDC's phi_r'' needs tau_r'' and so the link jerk): always from the model, the
// time derivative of the forward dynamics along the estimate's own derivative,
//   q''' = M^{-1} (tau' - dID/dq q' - dID/dq' q'')
// with q'' the model's (algebraic, no lag; the link side of eq. (35)); this is the limit of
// the central difference [FD(q + e q', q' + e q'', tau + e tau') - FD(q - e q', ...)] / 2e
// used before (e = 1e-5 s).
//
// Disturbance state (not in the paper; issue 18, docs/algorithms/arm.md "Model error"):
// with `disturbance` on, x = [tau, tau', d, phi, phi'] (5n) where d is a lumped link-side
// torque the nominal model misses (payload, mass and inertia errors):
//   M(q) q'' + C(q, q') q' + G(q) = tau + d,   d' = w_d,  E[w_d w_d^T] = q_disturbance I,
// so q'' = M^{-1} (tau + d - C q' - G) everywhere above (tau'', A, B, the feedback's q'' and
// q'''), and df2/dd = -K M^{-1}. The measured states stay last, so H = [0 I].
// `q_tau_rate` (> 0) replaces q on the tau' rows when set (Q = diag(q, q_tau_rate, q_d, q, q)).
// Payload state (also issue 18): with `payload` on, one more state m_p (kg), an unknown point
// mass at the tip of the last link added to the model's (x = [tau, tau', (d), m_p, phi, phi']):
//   M(q; m_p) q'' + C(q, q'; m_p) q' + G(q; m_p) = tau (+ d),   m_p' = w_p,  E[w_p^2] = q_payload,
// P(0) = p0_payload for it; df2/dm_p = K M^{-1} Y_p(q, q', q'') with Y_p the torques a unit tip
// mass needs (ArmChainDynamics::payload_regressor). A constant error is then a constant state:
// no lag, little noise.
#pragma once

#include <Eigen/Core>

#include "plexus/algorithms/arm/arm_feedback.hpp"
#include "plexus/algorithms/arm/arm_model.hpp"
#include "plexus/algorithms/arm/chain_dynamics.hpp"
#include "plexus/algorithms/arm/filtered_differentiator.hpp"

namespace plexus::algorithms {

enum class EkfJacobian { kFull, kPaper };
enum class LinkAcceleration { kModel, kDifferentiator };

struct FlexibleJointEkfParams {
  ArmModel model = ArmModel::paper_2dof();  ///< the observer's (nominal) model
  double q = 4.0;                           ///< Q = q I, > 0
  double r = 0.1;                           ///< R = r I, > 0
  double p0 = 1.0;                          ///< P(0) = p0 I, > 0
  int substeps = 1;                         ///< RK4 sub-steps per update, >= 1 (1 at the scenarios' 5 kHz)
  double step = 1e-3;                       ///< s, the update period (for the q'' differentiator), > 0
  double accel_filter_hz = 50.0;            ///< cutoff of the q'' differentiator, > 0
  double fd_step = 1e-6;                    ///< not read (A and B are exact tangents); accepted in parameter files, > 0
  EkfJacobian jacobian = EkfJacobian::kFull;
  LinkAcceleration acceleration = LinkAcceleration::kModel;
  bool disturbance = false;    ///< augment x with a link-side disturbance torque d per joint (header)
  double q_disturbance = 1e4;  ///< (N m)^2/s: process noise of d, > 0 (used with `disturbance`)
  double q_tau_rate = 0.0;     ///< process noise of the tau' rows; 0: the same as q; else > 0
  bool payload = false;        ///< augment x with an unknown tip mass m_p (header)
  double q_payload = 1.0;      ///< kg^2/s: process noise of m_p, > 0 (used with `payload`)
  double p0_payload = 1.0;     ///< kg^2: initial variance of m_p, > 0 (used with `payload`)

  /// Paper 004 section 4.2: Q = 4 I, R = 0.1 I, P(0) = I, no disturbance state (the defaults).
  static FlexibleJointEkfParams paper();
  /// The robust tuning (issue 18; docs/algorithms/arm.md "Model error"): the paper's filter
  /// plus the tip-mass state (q_payload 1e4, p0_payload 1e3) and the disturbance state
  /// (q_disturbance 3e6), for an arm whose model is wrong. The services' default.
  static FlexibleJointEkfParams robust();
};

class FlexibleJointEkf {
 public:
  using Vector = Eigen::VectorXd;
  using Matrix = Eigen::MatrixXd;

  /// Validates the parameters; state x^ = 0, P = p0 I.
  explicit FlexibleJointEkf(const FlexibleJointEkfParams& params);

  int dof() const { return n_; }
  /// Length of x: 4 n, + n with the disturbance state, + 1 with the payload state.
  int state_size() const { return m_; }
  /// Sets x^ = [tau, tau', phi, phi'] (d = 0, m_p = 0 with those states), or the whole x,
  /// and P = p0 I (p0_payload for m_p); resets the q'' differentiator.
  void reset(const Vector& x0);

  /// Integrates the observer over dt with input u (held) and measurement y = [phi, phi'].
  /// Non-finite inputs or dt <= 0 leave the state unchanged. No allocation.
  void update(const Vector& u, const Vector& y, double dt);
  /// Integrates the observer over dt with input u (held) and no measurement (the model alone,
  /// L = 0; P grows by F P + P F^T + Q): a period whose sample did not come. The next update
  /// holds y from this prediction's h(x^). Non-finite u or dt <= 0 leave the state unchanged.
  /// No allocation.
  void predict(const Vector& u, double dt);

  /// f(x, u) of eq. (35).
  void dynamics(const Vector& x, const Vector& u, Vector& dx);
  /// F = df/dx at (x, u) (mode per params).
  void jacobian(const Vector& x, const Vector& u, Matrix& f);

  const Vector& state() const { return x_; }
  const Matrix& covariance() const { return p_; }
  /// Link- and motor-side feedback from the estimate (q, q', q'', q''', tau, tau', phi, phi').
  const ArmFeedback& feedback() const { return fb_; }
  /// The disturbance estimate d^ (zero without the disturbance state).
  const Vector& disturbance() const { return d_; }
  /// The tip-mass estimate m_p^ (kg; zero without the payload state).
  double payload() const { return params_.payload ? x_(ipay_) : 0.0; }

 private:
  void link_state(const Vector& x);  // fills q_, qd_ from x
  void model_pass(const Vector& x);  // link_state(x) and the forward dynamics at x into qdd_ (cached)
  void link_jerk(const Vector& x);   // fb_.qddd at x, after dynamics(x, ...)
  void riccati(const Matrix& p, double gain, Matrix& dp);                    // gain: R^{-1}, 0 without a measurement
  void integrate(const Vector& u, const Vector& y, double dt, double gain);  // x^ and P over dt, gain on the innovation
  void finish(const Vector& u);                                              // the feedback at the new x^

  FlexibleJointEkfParams params_;
  int n_;
  int m_;         ///< state size (4n or 5n)
  int ipay_;      ///< offset of m_p in x (with the payload state)
  int iphi_;      ///< offset of phi in x; phi' follows
  Vector qdiag_;  ///< diagonal of Q
  Vector d_;      ///< d^ (zero without the disturbance state)
  ArmChainDynamics dyn_;
  Vector k_, j_, f_;
  Vector x_, k1_, k2_, k3_, k4_, xt_, innovation_;
  Matrix p_, fjac_, p1_, p2_, p3_, p4_, pt_, tmp_;
  Vector q_, qd_, qdd_, qdd_plus_, qdd_minus_, tau_, qp_;  ///< tau_: tau + d, the torque on the links
  Vector jq_, jqd_, jtau_;                                 ///< shifted link state of the jerk difference
  Matrix minv_, a_, b_, did_q_, did_qd_;
  Vector yp_;      ///< payload regressor
  Vector pass_x_;  ///< the x of dyn_'s last forward-dynamics pass
  bool pass_valid_ = false;
  Vector y_prev_;
  bool has_y_prev_ = false;
  ArmFeedback fb_;
  FilteredDifferentiator accel_;
};

}  // namespace plexus::algorithms
