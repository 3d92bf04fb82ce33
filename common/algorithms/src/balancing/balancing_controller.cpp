#include "plexus/algorithms/balancing/balancing_controller.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include <Eigen/LU>

#include "plexus/algorithms/core/validation.hpp"

namespace plexus::algorithms {

MotionProfile::MotionProfile(const MotionProfileParams& p) : params_(p) {
  validation::require_non_negative("motion_profile", "hold_time", p.hold_time);
  validation::require_positive("motion_profile", "ramp_time", p.ramp_time);
  validation::require_finite("motion_profile", "speed", p.speed);
}

MotionReference MotionProfile::sample(double t) const {
  const double T = params_.ramp_time, V = params_.speed;
  const double u = (t - params_.hold_time) / T;
  if (u <= 0.0) return {0.0, 0.0};
  if (u >= 1.0) return {V * (0.5 * T + (t - params_.hold_time - T)), V};
  const double pi = std::numbers::pi;
  // x = V T (u - sin(pi u) / pi) / 2
  return {0.5 * V * T * (u - std::sin(pi * u) / pi), 0.5 * V * (1.0 - std::cos(pi * u))};
}

BalancingController::BalancingController(const BalancingControllerParams& p, const WheeledInvertedPendulum& plant)
    : max_torque_(plant.params().max_torque) {
  for (std::size_t i = 0; i < p.poles.size(); ++i) {
    const std::string name = "poles[" + std::to_string(i) + "]";
    if (!(std::isfinite(p.poles[i]) && p.poles[i] < 0.0)) {
      validation::fail("balancing_controller", name, "finite and < 0", p.poles[i]);
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (p.poles[j] == p.poles[i])
        validation::fail("balancing_controller", name, "distinct from the others", p.poles[i]);
    }
  }
  // Ackermann: K = [0 0 0 1] C^-1 phi(A), C = [B, AB, A^2 B, A^3 B], phi the desired polynomial.
  const Eigen::Matrix4d A = plant.linear_a();
  const Eigen::Vector4d B = plant.linear_b();
  Eigen::Matrix4d C;
  C << B, A * B, A * A * B, A * A * A * B;
  Eigen::FullPivLU<Eigen::Matrix4d> lu(C);
  if (lu.rank() < 4) validation::fail("balancing_controller", "plant", "controllable", 0.0);
  Eigen::Matrix4d phi = Eigen::Matrix4d::Identity();
  for (double pole : p.poles) phi = (phi * (A - pole * Eigen::Matrix4d::Identity())).eval();
  K_ = Eigen::RowVector4d(0, 0, 0, 1) * lu.inverse() * phi;
}

double BalancingController::torque(double x, double v, double theta_hat, double theta_dot_hat,
                                   const MotionReference& ref) const {
  const Eigen::Vector4d e(x - ref.x, v - ref.v, theta_hat, theta_dot_hat);
  return std::clamp(-(K_ * e)(0), -max_torque_, max_torque_);
}

}  // namespace plexus::algorithms
