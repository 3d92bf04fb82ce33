#include "plexus/algorithms/unicycle/velocity_heading_observer.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Core>

#include "plexus/algorithms/core/angles.hpp"
#include "plexus/algorithms/core/validation.hpp"

namespace plexus::algorithms {
namespace {

/// e^{N h} for N = [[-L2, -u], [u, -L4]], closed form. Write N = -m I + B with
/// m = (L2 + L4) / 2, B = [[-d, -u], [u, d]], d = (L2 - L4) / 2; B^2 = (d^2 - u^2) I, so
/// e^{B h} = C I + S B with C = cosh(r), S = h sinh(r) / r, r^2 = (d^2 - u^2) h^2
/// (cos / sin for negative r^2, series near 0).
Eigen::Matrix2d exp_error_matrix(double L2, double L4, double u, double h) {
  const double m = 0.5 * (L2 + L4);
  const double d = 0.5 * (L2 - L4);
  const double q = (d * d - u * u) * h * h;
  double C = 0.0, S_over_h = 0.0;
  if (std::abs(q) < 1e-8) {
    C = 1.0 + 0.5 * q;
    S_over_h = 1.0 + q / 6.0;
  } else if (q > 0.0) {
    const double r = std::sqrt(q);
    C = std::cosh(r);
    S_over_h = std::sinh(r) / r;
  } else {
    const double r = std::sqrt(-q);
    C = std::cos(r);
    S_over_h = std::sin(r) / r;
  }
  const double S = S_over_h * h;
  Eigen::Matrix2d E;
  E << C - S * d, -S * u, S * u, C + S * d;
  return std::exp(-m * h) * E;
}

Eigen::Matrix2d rotation(double a) {
  Eigen::Matrix2d R;
  R << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
  return R;
}

}  // namespace

VelocityHeadingObserver::VelocityHeadingObserver(const VelocityHeadingObserverParams& params) : params_(params) {
  validation::require_positive("velocity_heading_observer", "L2", params.L2);
  validation::require_positive("velocity_heading_observer", "L4", params.L4);
}

void VelocityHeadingObserver::reset(const Eigen::Vector2d& z_hat0, const Eigen::Vector2d& position0) {
  state_.z_hat = z_hat0;
  state_.position = position0;
  state_.has_position = true;
}

void VelocityHeadingObserver::update(double dt, const Eigen::Vector2d& position, double u2) {
  if (!(dt > 0.0) || !std::isfinite(dt) || !position.allFinite() || !std::isfinite(u2)) return;
  if (!state_.has_position) {
    state_.position = position;
    state_.has_position = true;
    return;
  }
  const Eigen::Matrix2d E = exp_error_matrix(params_.L2, params_.L4, u2, dt);  // e^{N h}, paper 003 eq. (13)
  const Eigen::Vector2d dp = position - state_.position;
  Eigen::Vector2d z = E * state_.z_hat;
  if (params_.discretisation == ObserverDiscretisation::kExactArc) {
    // dp = h sinc(u2 h / 2) R(u2 h / 2) z  for the true velocity vector z (unicycle_step), and
    // z+ = R(u2 h) z, so the injection (R(u2 h) - E) z keeps e+ = E e exact.
    // sinc floored at 2 / pi: |u2 h| <= pi assumed.
    const double turn = u2 * dt;
    const double s = std::max(sinc(0.5 * turn), 2.0 / std::numbers::pi);
    const Eigen::Matrix2d K = (rotation(turn) - E) * rotation(-0.5 * turn) / (dt * s);
    z += K * dp;
  } else {
    z += Eigen::Vector2d(params_.L2 * dp.x(), params_.L4 * dp.y());
  }
  state_.z_hat = z;
  state_.position = position;
}

}  // namespace plexus::algorithms
