// Trajectory tracking for the unicycle: state feedback (paper 000, Theorem 2, eq. (14))
// and output feedback with the heading observer (paper 000, eqs. (27)-(28)).
//
// With zeta1 = x - x_r, zeta2 = y - y_r (eq. (13)), f_i = k_i atan(zeta_i):
//   S_x = x_r' - f1,  S_y = y_r' - f2,  v = sqrt(S_x^2 + S_y^2)           (eq. (14))
//   theta* = atan2(S_y, S_x),  zeta3 = wrap(theta - theta*)
//   f_i' = k_i zeta_i' / (1 + zeta_i^2),  zeta1' = v c - x_r',  zeta2' = v s - y_r'
//   theta*' = [S_x (y_r'' - f2') - S_y (x_r'' - f1')] / v^2
//   omega = theta*' - k3 zeta3 - v zeta1 g1(a, theta*) - v zeta2 g2(a, theta*),  a = theta* + zeta3
// State feedback: (c, s) = (cos theta, sin theta). Output feedback (27)-(28): (c, s) =
// (z3_hat, z4_hat) from the heading observer and theta replaced by theta_hat =
// atan2(z4_hat, z3_hat) everywhere, including inside zeta_i' (the exact derivative;
// the printed (28) drops the -x_r', -y_r' terms, docs/papers.md).
// The printed theta*' lost the second derivatives of the reference; fixed above.
//
// g1, g2 (eq. (14)) are evaluated in the sinc form, smooth at a = b:
//   g1(a, b) = (cos a - cos b) / (a - b) = -sin((a + b) / 2) sinc((a - b) / 2)
//   g2(a, b) = (sin a - sin b) / (a - b) =  cos((a + b) / 2) sinc((a - b) / 2)
//
// Degenerate speed (v -> 0, possible when condition (15) is violated): theta*' is
// computed with v^2 replaced by max(v^2, v_eps^2), v_eps = min_speed_for_turn. Its
// numerator is O(v), so the feedforward turn rate is continuous and tends to 0 as
// v -> 0 instead of diverging; at v = 0 exactly theta* = atan2(0, 0) = 0. Every
// output is finite for finite inputs; TrackingOutput::speed_floored reports it.
//
// The controller is static (no internal state): the only dynamic element of the
// output-feedback loop is the HeadingObserver, which the caller owns and updates.
#pragma once

#include <optional>
#include <string>

#include <Eigen/Core>

#include "plexus/algorithms/core/angles.hpp"
#include "plexus/algorithms/unicycle/figure_eight_reference.hpp"
#include "plexus/algorithms/unicycle/unicycle_plant.hpp"

namespace plexus::algorithms {

/// g1(a, b) = (cos a - cos b) / (a - b), -sin a at a = b  (paper 000, eq. (14), sinc form).
inline double tracking_g1(double a, double b) { return -std::sin(0.5 * (a + b)) * sinc(0.5 * (a - b)); }

/// g2(a, b) = (sin a - sin b) / (a - b), cos a at a = b  (paper 000, eq. (14), sinc form).
inline double tracking_g2(double a, double b) { return std::cos(0.5 * (a + b)) * sinc(0.5 * (a - b)); }

struct TrackingControllerParams {
  double k1 = 0.11;  ///< m/s, gain of f1 = k1 atan(zeta1), > 0 (paper 000: 0.11)
  double k2 = 0.11;  ///< m/s, gain of f2 = k2 atan(zeta2), > 0 (paper 000: 0.11)
  double k3 = 1.0;   ///< 1/s, heading gain, > 0 (paper 000: 1 in 6.2, 0.01 in 6.3.1, 0.1 in 6.3.2)
  /// gamma of condition (15), in (0, 1); used only by check_gain_condition(). The paper
  /// does not give it; 0.9 is permissive (guaranteed v >= (1 - gamma) v_rm).
  double gamma = 0.9;
  /// v_eps, m/s, > 0: floor of v in the theta*' denominator (see the file comment).
  double min_speed_for_turn = 1e-3;
};

/// The command and the intermediate quantities of one evaluation, for logging and tests.
struct TrackingOutput {
  UnicycleInput input;                              ///< (v, omega) command
  Eigen::Vector2d error = Eigen::Vector2d::Zero();  ///< (zeta1, zeta2) = position - reference, m
  double theta_star = 0.0;                          ///< desired heading theta*, rad
  double zeta3 = 0.0;                               ///< wrap(theta - theta*) (or theta_hat - theta*), rad
  double theta_star_dot = 0.0;                      ///< feedforward theta*', rad/s (after the v floor)
  bool speed_floored = false;                       ///< v < min_speed_for_turn: theta*' used the floor
};

class TrajectoryTrackingController {
 public:
  /// Validates k1, k2, k3 > 0, gamma in (0, 1), min_speed_for_turn > 0;
  /// throws std::invalid_argument naming the parameter and value.
  explicit TrajectoryTrackingController(const TrackingControllerParams& params);

  /// State feedback, paper 000 Theorem 2, eq. (14): needs the true heading.
  TrackingOutput state_feedback(const ReferenceSample& ref, const UnicycleState& state) const;

  /// Output feedback, paper 000 eqs. (27)-(28): position measurement and the heading
  /// observer's z_hat = (z3_hat, z4_hat) (HeadingObserver::state().z_hat).
  TrackingOutput output_feedback(const ReferenceSample& ref, const Eigen::Vector2d& position,
                                 const Eigen::Vector2d& z_hat) const;

  const TrackingControllerParams& params() const { return params_; }
  /// New gains while it runs (plexus param): validated as the constructor validates them;
  /// throws std::invalid_argument and keeps the old ones when they are invalid. The
  /// controller is static, so the next evaluation simply uses them.
  void set_params(const TrackingControllerParams& params);

 private:
  TrackingOutput compute(const ReferenceSample& ref, const Eigen::Vector2d& position, const Eigen::Vector2d& cs,
                         double theta) const;

  TrackingControllerParams params_;
};

/// Checks gain condition (15) of paper 000: k1^2 + k2^2 <= gamma^2 (4 / pi^2) v_rm^2, which
/// guarantees v >= (1 - gamma) v_rm > 0 (eq. (21)). Returns nullopt when it holds, else a
/// warning naming k1, k2, gamma, v_rm, both sides and their ratio. Throws
/// std::invalid_argument for invalid params or v_rm <= 0. (The paper's own gains
/// k1 = k2 = 0.11 fail it by about 12x for the figure-eight h1 = 5, h2 = 0.02.)
std::optional<std::string> check_gain_condition(const TrackingControllerParams& params, double v_rm);

}  // namespace plexus::algorithms
