#include "plexus/algorithms/unicycle/path_following_controller.hpp"

#include <algorithm>
#include <cmath>

#include "plexus/algorithms/core/validation.hpp"

namespace plexus::algorithms {

PathFollowingController::PathFollowingController(const PathFollowingParams& params) : params_(params) {
  constexpr const char* kWhere = "path_following_controller";
  validation::require_positive(kWhere, "k1", params.k1);
  validation::require_positive(kWhere, "k2", params.k2);
  validation::require_positive(kWhere, "min_abs_g", params.min_abs_g);
  validation::require_positive_or_inf(kWhere, "max_turn_rate", params.max_turn_rate);
}

PathFollowingOutput PathFollowingController::compute(const PathEvaluation& path, const Eigen::Vector2d& w) const {
  PathFollowingOutput out;
  const Eigen::Vector2d& grad = path.gradient;
  out.h = path.h;
  // paper 003, eq. (2) / (16): h' = h_x w_x + h_y w_y
  out.h_dot = grad.dot(w);
  // eq. (4) / (16): f = w^T Hess(h) w,  g = -h_x w_y + h_y w_x
  out.f = w.dot(path.hessian * w);
  out.g = -grad.x() * w.y() + grad.y() * w.x();
  double g = out.g;
  if (!(std::abs(g) >= params_.min_abs_g)) {  // also catches NaN
    g = std::signbit(g) ? -params_.min_abs_g : params_.min_abs_g;
    out.g_saturated = true;
  }
  // eq. (5) / (15): u2 = (-f - k2 h' - k1 h) / g
  double u2 = (-out.f - params_.k2 * out.h_dot - params_.k1 * out.h) / g;
  if (std::abs(u2) > params_.max_turn_rate) {
    u2 = std::copysign(params_.max_turn_rate, u2);
    out.turn_rate_saturated = true;
  }
  out.u2 = u2;
  return out;
}

}  // namespace plexus::algorithms
