// Path following by input-output linearisation of h(x, y): state feedback (paper 003,
// eqs. (3)-(5)) and observer-based (paper 003, eqs. (15)-(16)).
//
// With the velocity vector w = (x', y') = u1 (cos theta, sin theta):
//   h' = grad h . w,  h'' = f + g u2                                   (eq. (3))
//   f = w^T Hess(h) w = (h_xx cos^2 + h_yy sin^2 + 2 h_xy sin cos) u1^2  (eq. (4))
//   g = -h_x w_y + h_y w_x = (-h_x sin theta + h_y cos theta) u1
//   u2 = (-f - k2 h' - k1 h) / g                                          (eq. (5))
// giving h'' + k2 h' + k1 h = 0 (eq. (6)). The observer-based law (15)-(16) is the same
// formula with w replaced by the observer's z_hat = (z2_hat, z4_hat), so both variants
// share one implementation (compute()).
//
// Degenerate g (|g| < min_abs_g; the law is only local, Remark 2 and Lemma 1): g is
// replaced by copysign(min_abs_g, g) (+min_abs_g when g = 0) and the output reports
// g_saturated; then |u2| is clamped to max_turn_rate (default: no clamp) and
// turn_rate_saturated reports it. Outputs are finite for finite inputs.
#pragma once

#include <limits>

#include <Eigen/Core>

#include "plexus/algorithms/unicycle/geometric_path.hpp"
#include "plexus/algorithms/unicycle/unicycle_plant.hpp"

namespace plexus::algorithms {

struct PathFollowingParams {
  double k1 = 1.0;                                                 ///< > 0 (paper 003, section 5: 1)
  double k2 = 2.0;                                                 ///< > 0 (paper 003, section 5: 2)
  double min_abs_g = 1e-3;                                         ///< > 0, floor on |g| (units of h per m times m/s)
  double max_turn_rate = std::numeric_limits<double>::infinity();  ///< rad/s, > 0, |u2| clamp
};

struct PathFollowingOutput {
  double u2 = 0.0;     ///< turn-rate command, rad/s
  double h = 0.0;      ///< path error h(x, y)
  double h_dot = 0.0;  ///< h' (or its estimate, eq. (16))
  double f = 0.0;      ///< f (or f_hat)
  double g = 0.0;      ///< g (or g_hat), before saturation
  bool g_saturated = false;
  bool turn_rate_saturated = false;
};

class PathFollowingController {
 public:
  /// Validates k1, k2, min_abs_g > 0 and max_turn_rate > 0 (infinity allowed).
  explicit PathFollowingController(const PathFollowingParams& params);

  /// Shared law: u2 = (-f - k2 h' - k1 h) / g for path data `path` and velocity vector `w`.
  PathFollowingOutput compute(const PathEvaluation& path, const Eigen::Vector2d& w) const;

  /// State feedback, paper 003 eq. (5): true pose and speed u1.
  PathFollowingOutput state_feedback(const GeometricPath& path, const UnicycleState& state, double u1) const {
    return compute(path.evaluate({state.x, state.y}), {u1 * std::cos(state.theta), u1 * std::sin(state.theta)});
  }

  /// Observer-based, paper 003 eqs. (15)-(16): measured position and the observer's
  /// z_hat = (z2_hat, z4_hat) (VelocityHeadingObserver::state().z_hat).
  PathFollowingOutput observer_based(const GeometricPath& path, const Eigen::Vector2d& position,
                                     const Eigen::Vector2d& z_hat) const {
    return compute(path.evaluate(position), z_hat);
  }

  const PathFollowingParams& params() const { return params_; }

 private:
  PathFollowingParams params_;
};

}  // namespace plexus::algorithms
