#include "plexus/algorithms/unicycle/heading_observer.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "plexus/algorithms/core/angles.hpp"
#include "plexus/algorithms/core/validation.hpp"

namespace plexus::algorithms {
namespace {

/// (1 - e^{-a}) / a, smooth through a = 0 (value 1).
double one_minus_exp_over(double a) {
  if (std::abs(a) < 1e-8) return 1.0 - 0.5 * a;
  return -std::expm1(-a) / a;
}

/// Rotation of `v` by angle `a`.
Eigen::Vector2d rotate(const Eigen::Vector2d& v, double a) {
  const double c = std::cos(a), s = std::sin(a);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

}  // namespace

HeadingObserver::HeadingObserver(const HeadingObserverParams& params) : params_(params) {
  validation::require_positive("heading_observer", "L", params.L);
}

void HeadingObserver::set_params(const HeadingObserverParams& params) {
  validation::require_positive("heading_observer", "L", params.L);
  params_ = params;
}

void HeadingObserver::reset(const Eigen::Vector2d& z_hat0, const Eigen::Vector2d& position0) {
  state_.z_hat = z_hat0;
  state_.position = position0;
  state_.has_position = true;
}

void HeadingObserver::update(double dt, const Eigen::Vector2d& position, const UnicycleInput& input) {
  if (!(dt > 0.0) || !std::isfinite(dt) || !position.allFinite() || !std::isfinite(input.v) ||
      !std::isfinite(input.omega)) {
    return;
  }
  if (!state_.has_position) {
    state_.position = position;
    state_.has_position = true;
    return;
  }
  const double L = params_.L;
  const double a = L * input.v * dt;     // decay exponent of e^{M h}, M = -L v I + omega J
  const double turn = input.omega * dt;  // rotation of e^{M h}
  const Eigen::Vector2d dp = position - state_.position;
  // Homogeneous part: e^{M h} z_hat = e^{-L v h} R(omega h) z_hat  (paper 000, eq. (5) with p held).
  Eigen::Vector2d z = std::exp(-a) * rotate(state_.z_hat, turn);
  if (params_.discretisation == ObserverDiscretisation::kExactArc) {
    // Injection making e+ = e^{M h} e exact for the unicycle arc: with
    // dp = v h sinc(omega h / 2) R(omega h / 2) (cos theta, sin theta) (unicycle_step),
    // (1 - e^{-L v h}) R(omega h) (cos theta, sin theta) = L phi(L v h) / sinc(omega h / 2) R(omega h / 2) dp.
    // sinc is floored at sinc(pi / 2) = 2 / pi, i.e. |omega h| <= pi is assumed (a coarser step
    // cannot be reconstructed from two samples anyway).
    const double s = std::max(sinc(0.5 * turn), 2.0 / std::numbers::pi);
    z += (L * one_minus_exp_over(a) / s) * rotate(dp, 0.5 * turn);
  } else {
    // z_hat = zeta + L p jumps by L dp when the held position is refreshed.
    z += L * dp;
  }
  state_.z_hat = z;
  state_.position = position;
}

}  // namespace plexus::algorithms
