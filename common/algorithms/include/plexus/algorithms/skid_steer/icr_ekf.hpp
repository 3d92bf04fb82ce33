// ICR extended Kalman filter (paper 001 section 3.1; docs/papers.md), on the shared
// EKF of core/ekf.hpp.
//
// State x = [X, Y, theta, y_l, y_r, x_G]; the ICRs are random walks. Input u = (v_l, v_r),
// Euler discretisation with step dt (eq. (7)):
//   f(x, u) = x + dt [v_x c - v_y s,  v_x s + v_y c,  omega,  0, 0, 0]^T
// with v_x, v_y, omega of icr_kinematics.hpp, c = cos theta, s = sin theta, d = y_l - y_r.
// Analytic Jacobian F = df/dx (the printed (10)-(11) is garbled; re-derived here and
// checked against finite differences in tests/skid_steer/icr_ekf_test.cpp):
//   dv_x/dy_l = -y_r (v_r - v_l) / d^2     dv_x/dy_r =  y_l (v_r - v_l) / d^2
//   dv_y/dy_l = -x_G (v_r - v_l) / d^2     dv_y/dy_r =  x_G (v_r - v_l) / d^2
//   dv_y/dx_G =  (v_r - v_l) / d
//   domega/dy_l = -(v_r - v_l) / d^2       domega/dy_r = (v_r - v_l) / d^2
//   F = I + dt [ 0 0 -Y'  c dv_x/dy_l - s dv_y/dy_l   c dv_x/dy_r - s dv_y/dy_r   -s dv_y/dx_G
//                0 0  X'  s dv_x/dy_l + c dv_y/dy_l   s dv_x/dy_r + c dv_y/dy_r    c dv_y/dx_G
//                0 0  0   domega/dy_l                 domega/dy_r                  0
//                0 ... 0 ]
// with X' = v_x c - v_y s, Y' = v_x s + v_y c.
// Process noise (eq. (8)): P- = F P F^T + L Q L^T. The paper's eq. (12) takes L = I dt,
// i.e. Q_d = Q dt^2 (ProcessNoiseModel::kDtSquared, the default); kContinuous uses
// Q_d = Q dt (Q as a spectral density) and kPerStep Q_d = Q.
// Measurement (eqs. (13)-(14)): z = (X, Y, theta), H = [I3 0], heading residual wrapped to
// (-pi, pi]. The state's theta is kept continuous (not wrapped).
// Tuning (eq. (21)): Q = diag(0.3^2, 0.3^2, (3 pi/180)^2, 0.01^2, 0.01^2, 0.01^2),
// R = diag(0.01^2, 0.01^2, (3 pi/180)^2); initial ICR guess (1.0, -1.0, 1.0).
// Adaptive reset (eq. (22)): P <- P_B = diag(0.3^2, 0.3^2, (3 pi/180)^2, 0.5^2, 0.5^2, 0.5^2).
// The initial covariance is not given by the paper; default P_0 = P_B.
// Track sides (an option, on by default): the left track's ICR lies left of the body's
// centreline and the right one's right of it (y_l > 0 > y_r). After an adaptive reset P_B is
// large and one update can throw the estimate across that boundary onto a spurious branch
// of the model (measured: y_r jumped to +1.2 m on a user terrain and never came back), so
// after every update y_l is clamped to >= track_side_margin and y_r to <= -track_side_margin
// (a projection of the estimate; P is kept).
// A prediction whose ICR estimate has y_l - y_r <= min_track_separation is not applied
// (the kinematics are singular there); predict() returns false and counts it.
#pragma once

#include <Eigen/Core>

#include "plexus/algorithms/core/ekf.hpp"
#include "plexus/algorithms/skid_steer/icr_kinematics.hpp"

namespace plexus::algorithms {

enum class ProcessNoiseModel { kDtSquared, kContinuous, kPerStep };

/// "dt_squared" | "continuous" | "per_step"; throws std::invalid_argument otherwise.
ProcessNoiseModel process_noise_model_from_string(const std::string& name);

using IcrVector = Eigen::Matrix<double, 6, 1>;
using IcrMatrix = Eigen::Matrix<double, 6, 6>;

struct IcrEkfParams {
  IcrVector q_diag = paper_q();           ///< Q diagonal, finite >= 0
  Eigen::Vector3d r_diag = paper_r();     ///< R diagonal, finite > 0
  IcrVector p0_diag = paper_p_b();        ///< initial P diagonal, finite > 0
  IcrVector p_b_diag = paper_p_b();       ///< adaptive-reset P_B diagonal, finite > 0
  IcrParams initial_icr{1.0, -1.0, 1.0};  ///< paper section 4.1
  ProcessNoiseModel process_noise = ProcessNoiseModel::kDtSquared;
  double min_track_separation = 1e-3;  ///< m, > 0: predictions need y_l - y_r above it
  bool enforce_track_sides = true;     ///< clamp y_l >= margin, y_r <= -margin after updates
  double track_side_margin = 0.01;     ///< m, >= 0

  static IcrVector paper_q();
  static Eigen::Vector3d paper_r();
  static IcrVector paper_p_b();
};

class IcrEkf {
 public:
  /// Validates params; throws std::invalid_argument naming the offending entry. The filter
  /// starts at pose 0 with the initial ICRs and P_0; call reset() with the first measurement.
  explicit IcrEkf(const IcrEkfParams& params);

  /// x = (pose, initial ICRs), P = P_0.
  void reset(const Pose2& pose);
  /// Adaptive reset (eq. (22)): P = P_B, state kept.
  void reset_covariance_to_p_b();
  /// Prior reset (plexus, docs/algorithms/skid_steer.md): the ICRs set to a terrain's learned
  /// values `icr`, their covariance to diag(sd^2); the pose and its covariance (P_B's pose
  /// block) as in the covariance reset; no cross-covariance. sd > 0, finite.
  void reset_to_prior(const IcrParams& icr, const Eigen::Vector3d& sd);
  /// The ICRs replaced by `icr` with covariance diag(sd^2), uncorrelated with the pose; the
  /// pose and its covariance kept (the prior applied to a saved state). sd > 0, finite.
  void replace_icrs(const IcrParams& icr, const Eigen::Vector3d& sd);
  /// Sets the state and covariance, e.g. to a saved copy; P symmetric positive definite.
  void restore(const IcrVector& x, const IcrMatrix& p) { ekf_.reset(x, p); }

  /// Prediction over dt > 0 with track speeds u. Returns false (estimate unchanged) if the
  /// step is not finite or the ICR estimate is singular. No allocation.
  bool predict(const TrackSpeeds& u, double dt);
  /// Update with a measured pose (theta may be wrapped). Returns false if rejected. No allocation.
  bool update(const Pose2& z);

  const IcrVector& state() const { return ekf_.state(); }
  const IcrMatrix& covariance() const { return ekf_.covariance(); }
  Pose2 pose() const { return {state()(0), state()(1), state()(2)}; }
  IcrParams icr() const { return {state()(3), state()(4), state()(5)}; }
  const IcrEkfParams& params() const { return params_; }
  long rejected_predictions() const { return rejected_; }
  /// How many updates were followed by a track-side clamp.
  long side_clamps() const { return clamps_; }
  double last_nis() const { return ekf_.last_nis(); }
  /// -2 log likelihood of the last update's innovation, up to a constant: NIS + log det S.
  double last_neg2_log_likelihood() const { return ekf_.last_nis() + ekf_.last_log_det_s(); }

  /// The Euler transition f(x, u) and its Jacobian (above). Public for tests.
  static IcrVector transition(const IcrVector& x, const TrackSpeeds& u, double dt);
  static IcrMatrix jacobian(const IcrVector& x, const TrackSpeeds& u, double dt);

 private:
  void set_icrs(const IcrParams& icr, const Eigen::Vector3d& sd, const Eigen::Matrix3d& pose_covariance);

  IcrEkfParams params_;
  ExtendedKalmanFilter<6> ekf_;
  IcrMatrix p0_, p_b_;
  Eigen::Matrix3d r_;
  long rejected_ = 0;
  long clamps_ = 0;
};

}  // namespace plexus::algorithms
