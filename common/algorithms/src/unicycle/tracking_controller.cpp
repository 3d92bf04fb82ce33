#include "plexus/algorithms/unicycle/tracking_controller.hpp"

#include <cmath>
#include <numbers>

#include "plexus/algorithms/core/angles.hpp"
#include "plexus/algorithms/core/validation.hpp"

namespace plexus::algorithms {
namespace {

void validate(const TrackingControllerParams& p) {
  constexpr const char* kWhere = "tracking_controller";
  validation::require_positive(kWhere, "k1", p.k1);
  validation::require_positive(kWhere, "k2", p.k2);
  validation::require_positive(kWhere, "k3", p.k3);
  validation::require_open_interval(kWhere, "gamma", p.gamma, 0.0, 1.0);
  validation::require_positive(kWhere, "min_speed_for_turn", p.min_speed_for_turn);
}

}  // namespace

TrajectoryTrackingController::TrajectoryTrackingController(const TrackingControllerParams& params) : params_(params) {
  validate(params);
}

void TrajectoryTrackingController::set_params(const TrackingControllerParams& params) {
  validate(params);
  params_ = params;
}

TrackingOutput TrajectoryTrackingController::state_feedback(const ReferenceSample& ref,
                                                            const UnicycleState& state) const {
  return compute(ref, {state.x, state.y}, {std::cos(state.theta), std::sin(state.theta)}, state.theta);
}

TrackingOutput TrajectoryTrackingController::output_feedback(const ReferenceSample& ref,
                                                             const Eigen::Vector2d& position,
                                                             const Eigen::Vector2d& z_hat) const {
  // Paper 000, eq. (27): cos theta, sin theta, theta -> z3_hat, z4_hat, theta_hat (eq. (11)).
  return compute(ref, position, z_hat, std::atan2(z_hat.y(), z_hat.x()));
}

TrackingOutput TrajectoryTrackingController::compute(const ReferenceSample& ref, const Eigen::Vector2d& position,
                                                     const Eigen::Vector2d& cs, double theta) const {
  const double k1 = params_.k1, k2 = params_.k2, k3 = params_.k3;
  TrackingOutput out;
  // eq. (13)
  const double z1 = position.x() - ref.p.x();
  const double z2 = position.y() - ref.p.y();
  out.error = {z1, z2};
  // eq. (14): f_i = k_i atan(zeta_i), v = |(x_r' - f1, y_r' - f2)|, theta* = atan2(S_y, S_x)
  const double f1 = k1 * std::atan(z1);
  const double f2 = k2 * std::atan(z2);
  const double Sx = ref.dp.x() - f1;
  const double Sy = ref.dp.y() - f2;
  const double v = std::hypot(Sx, Sy);
  const double theta_star = std::atan2(Sy, Sx);
  const double zeta3 = wrap_angle(theta - theta_star);
  // f_i' = k_i zeta_i' / (1 + zeta_i^2), zeta1' = v c - x_r', zeta2' = v s - y_r' (exact derivative;
  // in output feedback (c, s) = z_hat, docs/papers.md on eq. (28)).
  const double dz1 = v * cs.x() - ref.dp.x();
  const double dz2 = v * cs.y() - ref.dp.y();
  const double df1 = k1 * dz1 / (1.0 + z1 * z1);
  const double df2 = k2 * dz2 / (1.0 + z2 * z2);
  // theta*' = [S_x (y_r'' - f2') - S_y (x_r'' - f1')] / v^2 (eq. (14), second derivatives restored),
  // with v^2 floored at v_eps^2 (numerator is O(v): the feedforward vanishes continuously as v -> 0).
  const double v_eps = params_.min_speed_for_turn;
  out.speed_floored = v < v_eps;
  const double denom = out.speed_floored ? v_eps * v_eps : v * v;
  const double theta_star_dot = (Sx * (ref.ddp.y() - df2) - Sy * (ref.ddp.x() - df1)) / denom;
  // omega = theta*' - k3 zeta3 - v zeta1 g1(a, theta*) - v zeta2 g2(a, theta*), a = theta* + zeta3
  // (eq. (14) / (27)); a uses the wrapped zeta3 so g is consistent with the heading error.
  const double a = theta_star + zeta3;
  const double omega =
      theta_star_dot - k3 * zeta3 - v * z1 * tracking_g1(a, theta_star) - v * z2 * tracking_g2(a, theta_star);
  out.input = {v, omega};
  out.theta_star = theta_star;
  out.zeta3 = zeta3;
  out.theta_star_dot = theta_star_dot;
  return out;
}

std::optional<std::string> check_gain_condition(const TrackingControllerParams& params, double v_rm) {
  validate(params);
  validation::require_positive("tracking_controller", "v_rm", v_rm);
  // Paper 000, eq. (15): k1^2 + k2^2 <= gamma^2 (4 / pi^2) v_rm^2.
  const double lhs = params.k1 * params.k1 + params.k2 * params.k2;
  const double rhs = params.gamma * params.gamma * 4.0 / (std::numbers::pi * std::numbers::pi) * v_rm * v_rm;
  if (lhs <= rhs) return std::nullopt;
  const double k_max = params.gamma * 2.0 / std::numbers::pi * v_rm;  // largest k1 = k2 / sqrt(2) norm
  std::string msg = "tracking_controller: gain condition (15) of paper 000 violated: k1^2 + k2^2 = ";
  msg += validation::format_value(lhs) + " (k1 = " + validation::format_value(params.k1) +
         ", k2 = " + validation::format_value(params.k2) +
         ") > gamma^2 (4/pi^2) v_rm^2 = " + validation::format_value(rhs) +
         " (gamma = " + validation::format_value(params.gamma) + ", v_rm = " + validation::format_value(v_rm) +
         " m/s), " + validation::format_value(lhs / rhs) +
         "x over; sqrt(k1^2 + k2^2) must be <= " + validation::format_value(k_max) +
         ". The speed v >= (1 - gamma) v_rm is then not guaranteed and v may approach 0"
         " (theta*' uses the min_speed_for_turn floor there).";
  return msg;
}

}  // namespace plexus::algorithms
