#include "plexus/algorithms/balancing/wheeled_inverted_pendulum.hpp"

#include <algorithm>
#include <cmath>

#include "plexus/algorithms/core/validation.hpp"

namespace plexus::algorithms {

double PendulumCoefficients::tilt_acceleration(double theta, double theta_dot, double torque) const {
  // Paper 002, eq. (10), with the torque gain k_T explicit.
  const double c = std::cos(theta);
  return (alpha2 * std::sin(2.0 * theta) * theta_dot * theta_dot + alpha3 * std::sin(theta) +
          torque_gain * (1.0 + alpha4 * c) * torque) /
         (1.0 - alpha1 * c * c);
}

double PendulumCoefficients::linear_tilt_acceleration(double theta, double torque) const {
  // Paper 002, eq. (11): sin theta ~ theta, cos theta ~ 1, theta'^2 ~ 0.
  return (alpha3 * theta + torque_gain * (1.0 + alpha4) * torque) / (1.0 - alpha1);
}

double PendulumCoefficients::axle_acceleration(double theta, double theta_dot, double theta_ddot, double torque) const {
  return beta2 * torque + beta1 * (std::sin(theta) * theta_dot * theta_dot - std::cos(theta) * theta_ddot);
}

WheeledInvertedPendulum::WheeledInvertedPendulum(const WheeledPendulumParams& p) : params_(p) {
  constexpr const char* kWhere = "wheeled_inverted_pendulum";
  validation::require_positive(kWhere, "body_mass", p.body_mass);
  validation::require_positive(kWhere, "com_height", p.com_height);
  validation::require_non_negative(kWhere, "body_inertia", p.body_inertia);
  validation::require_non_negative(kWhere, "wheel_mass", p.wheel_mass);
  validation::require_positive(kWhere, "wheel_radius", p.wheel_radius);
  validation::require_non_negative(kWhere, "wheel_inertia", p.wheel_inertia);
  validation::require_positive(kWhere, "gravity", p.gravity);
  validation::require_positive_or_inf(kWhere, "max_torque", p.max_torque);
  a_ = p.body_mass + p.wheel_mass + p.wheel_inertia / (p.wheel_radius * p.wheel_radius);
  b_ = p.body_mass * p.com_height;
  c_ = p.body_inertia + p.body_mass * p.com_height * p.com_height;
  coeffs_.alpha1 = b_ * b_ / (a_ * c_);  // < 1: a c - b^2 = m_b I_b + (m_w + I_w / r^2) c > 0
  coeffs_.alpha2 = -0.5 * coeffs_.alpha1;
  coeffs_.alpha3 = b_ * p.gravity / c_;
  coeffs_.alpha4 = b_ / (a_ * p.wheel_radius);
  coeffs_.torque_gain = -1.0 / c_;
  coeffs_.beta1 = b_ / a_;
  coeffs_.beta2 = 1.0 / (a_ * p.wheel_radius);
  if (!(coeffs_.alpha1 < 1.0 - 1e-9)) {
    validation::fail(kWhere, "body_inertia", "> 0 when wheel_mass and wheel_inertia are 0 (alpha1 < 1)",
                     p.body_inertia);
  }
}

double WheeledInvertedPendulum::saturate(double torque) const {
  return std::clamp(torque, -params_.max_torque, params_.max_torque);
}

WheeledPendulumAccelerations WheeledInvertedPendulum::accelerations(const WheeledPendulumState& s,
                                                                    double torque) const {
  const double T = saturate(torque);
  const double sn = std::sin(s.theta), cs = std::cos(s.theta);
  const double r = params_.wheel_radius;
  // [a, b cos; b cos, c] [x''; theta''] = [T / r + b sin theta'^2; b g sin - T]
  const double m12 = b_ * cs;
  const double rhs1 = T / r + b_ * sn * s.theta_dot * s.theta_dot;
  const double rhs2 = b_ * params_.gravity * sn - T;
  const double det = a_ * c_ - m12 * m12;
  return {(c_ * rhs1 - m12 * rhs2) / det, (a_ * rhs2 - m12 * rhs1) / det};
}

WheeledPendulumAccelerations WheeledInvertedPendulum::step(WheeledPendulumState& s, double torque, double h,
                                                           int substeps) const {
  if (substeps < 1) substeps = 1;
  const double dt = h / substeps;
  using V = Eigen::Vector4d;
  auto deriv = [&](const V& y) {
    const WheeledPendulumAccelerations acc = accelerations({y(0), y(1), y(2), y(3)}, torque);
    return V(y(1), acc.x_ddot, y(3), acc.theta_ddot);
  };
  V y(s.x, s.v, s.theta, s.theta_dot);
  for (int i = 0; i < substeps; ++i) {
    const V k1 = deriv(y);
    const V k2 = deriv(y + 0.5 * dt * k1);
    const V k3 = deriv(y + 0.5 * dt * k2);
    const V k4 = deriv(y + dt * k3);
    y += (dt / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }
  s = {y(0), y(1), y(2), y(3)};
  return accelerations(s, torque);
}

Eigen::Matrix4d WheeledInvertedPendulum::linear_a() const {
  // At theta = 0: [a, b; b, c] [x''; theta''] = [T / r; b g theta - T]
  const double det = a_ * c_ - b_ * b_;
  Eigen::Matrix4d A = Eigen::Matrix4d::Zero();
  A(0, 1) = 1.0;
  A(2, 3) = 1.0;
  A(1, 2) = -b_ * b_ * params_.gravity / det;
  A(3, 2) = a_ * b_ * params_.gravity / det;
  return A;
}

Eigen::Vector4d WheeledInvertedPendulum::linear_b() const {
  const double det = a_ * c_ - b_ * b_;
  const double r = params_.wheel_radius;
  return {0.0, (c_ / r + b_) / det, 0.0, (-a_ - b_ / r) / det};
}

}  // namespace plexus::algorithms
