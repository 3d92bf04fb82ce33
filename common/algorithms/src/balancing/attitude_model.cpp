#include "plexus/algorithms/balancing/attitude_model.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/LU>

#include "plexus/algorithms/core/validation.hpp"

namespace plexus::algorithms {

AttitudeModel::AttitudeModel(const AttitudeModelParams& p) : params_(p) {
  constexpr const char* kWhere = "attitude_model";
  validation::require_positive(kWhere, "dt", p.dt);
  validation::require_finite(kWhere, "gamma1", p.gamma1);
  validation::require_finite(kWhere, "gamma2", p.gamma2);
  validation::require_positive_or_inf(kWhere, "gyro_range", p.gyro_range);
  validation::require_finite(kWhere, "accelerometer_height", p.accelerometer_height);
  validation::require_positive(kWhere, "gravity", p.gravity);
  if (!(p.coefficients.alpha1 >= 0.0 && p.coefficients.alpha1 < 1.0)) {
    validation::fail(kWhere, "alpha1", "in [0, 1)", p.coefficients.alpha1);
  }
  validation::require_finite(kWhere, "alpha2", p.coefficients.alpha2);
  validation::require_finite(kWhere, "alpha3", p.coefficients.alpha3);
  validation::require_finite(kWhere, "alpha4", p.coefficients.alpha4);
  validation::require_finite(kWhere, "torque_gain", p.coefficients.torque_gain);
}

double AttitudeModel::tilt_acceleration(double theta, double theta_dot, double torque) const {
  return params_.process == AttitudeProcessModel::kNonlinear
             ? params_.coefficients.tilt_acceleration(theta, theta_dot, torque)
             : params_.coefficients.linear_tilt_acceleration(theta, torque);
}

AttitudeModel::State AttitudeModel::predict(const State& x, double torque) const {
  const double dt = params_.dt;
  return {x(0) + dt * x(1), x(1) + dt * tilt_acceleration(x(0), x(1), torque),
          x(2) + dt * (params_.gamma1 * x(2) + params_.gamma2)};
}

void AttitudeModel::tilt_acceleration_partials(double t, double w, double torque, double& d_theta,
                                               double& d_rate) const {
  const PendulumCoefficients& a = params_.coefficients;
  if (params_.process == AttitudeProcessModel::kLinear) {
    d_theta = a.alpha3 / (1.0 - a.alpha1);
    d_rate = 0.0;
    return;
  }
  // theta'' = N / D, N = a2 sin2t w^2 + a3 sin t + kT (1 + a4 cos t) T, D = 1 - a1 cos^2 t
  const double s = std::sin(t), c = std::cos(t), s2 = std::sin(2.0 * t), c2 = std::cos(2.0 * t);
  const double N = a.alpha2 * s2 * w * w + a.alpha3 * s + a.torque_gain * (1.0 + a.alpha4 * c) * torque;
  const double D = 1.0 - a.alpha1 * c * c;
  const double N_t = 2.0 * a.alpha2 * c2 * w * w + a.alpha3 * c - a.torque_gain * a.alpha4 * s * torque;
  const double D_t = a.alpha1 * s2;
  d_theta = (N_t * D - N * D_t) / (D * D);
  d_rate = 2.0 * a.alpha2 * s2 * w / D;
}

Eigen::Matrix3d AttitudeModel::jacobian(const State& x, double torque) const {
  const double dt = params_.dt;
  double d_theta, d_rate;
  tilt_acceleration_partials(x(0), x(1), torque, d_theta, d_rate);
  Eigen::Matrix3d F;
  F << 1.0, dt, 0.0,                         //
      dt * d_theta, 1.0 + dt * d_rate, 0.0,  //
      0.0, 0.0, 1.0 + dt * params_.gamma1;
  return F;
}

double AttitudeModel::accelerometer_tilt(const State& x, double torque) const {
  const PendulumCoefficients& a = params_.coefficients;
  const double d = params_.accelerometer_height, g = params_.gravity;
  const double t = x(0), w = x(1);
  if (params_.process == AttitudeProcessModel::kLinear) {
    const double A = a.linear_tilt_acceleration(t, torque);
    const double X = a.beta2 * torque - a.beta1 * A;
    return t - (X + d * A) / g;
  }
  const double A = a.tilt_acceleration(t, w, torque);
  const double X = a.axle_acceleration(t, w, A, torque);
  const double s = std::sin(t), c = std::cos(t);
  const double fx = X + d * (c * A - s * w * w);
  const double fz = g - d * (s * A + c * w * w);
  return std::atan2(-(fx * c - fz * s), fx * s + fz * c);
}

Eigen::RowVector3d AttitudeModel::accelerometer_tilt_gradient(const State& x, double torque) const {
  const PendulumCoefficients& a = params_.coefficients;
  const double d = params_.accelerometer_height, g = params_.gravity;
  const double t = x(0), w = x(1);
  double A_t, A_w;
  tilt_acceleration_partials(t, w, torque, A_t, A_w);
  if (params_.process == AttitudeProcessModel::kLinear) {
    return {1.0 - (d - a.beta1) * A_t / g, 0.0, 0.0};
  }
  const double A = a.tilt_acceleration(t, w, torque);
  const double s = std::sin(t), c = std::cos(t), b1 = a.beta1;
  const double X = a.axle_acceleration(t, w, A, torque);
  const double X_t = b1 * (c * w * w + s * A - c * A_t);
  const double X_w = b1 * (2.0 * s * w - c * A_w);
  const double fx = X + d * (c * A - s * w * w);
  const double fz = g - d * (s * A + c * w * w);
  const double fx_t = X_t + d * (-s * A + c * A_t - c * w * w);
  const double fx_w = X_w + d * (c * A_w - 2.0 * s * w);
  const double fz_t = -d * (c * A + s * A_t - s * w * w);
  const double fz_w = -d * (s * A_w + 2.0 * c * w);
  const double fxb = fx * c - fz * s, fzb = fx * s + fz * c;
  const double fxb_t = fx_t * c - fx * s - fz_t * s - fz * c, fxb_w = fx_w * c - fz_w * s;
  const double fzb_t = fx_t * s + fx * c + fz_t * c - fz * s, fzb_w = fx_w * s + fz_w * c;
  // d atan2(-fxb, fzb) = (-fzb dfxb + fxb dfzb) / (fxb^2 + fzb^2)
  const double n2 = fxb * fxb + fzb * fzb;
  return {(-fzb * fxb_t + fxb * fzb_t) / n2, (-fzb * fxb_w + fxb * fzb_w) / n2, 0.0};
}

double AttitudeModel::gyro(const State& x) const {
  return std::clamp(x(1) + x(2), -params_.gyro_range, params_.gyro_range);
}

double AttitudeModel::gyro_slope(const State& x) const {
  return std::abs(x(1) + x(2)) < params_.gyro_range ? 1.0 : 0.0;
}

int AttitudeModel::observability_rank(const State& x, double torque, AttitudeMeasurementForm form) const {
  const Eigen::Matrix3d F = jacobian(x, torque);
  Eigen::Matrix<double, 6, 3> O = Eigen::Matrix<double, 6, 3>::Zero();
  Eigen::Matrix<double, 2, 3> H = Eigen::Matrix<double, 2, 3>::Zero();
  H(0, 0) = 1.0;
  if (form == AttitudeMeasurementForm::kObservable) {
    H.row(0) = accelerometer_tilt_gradient(x, torque);
    H.row(1) << 0.0, gyro_slope(x), gyro_slope(x);
  }
  O.topRows<2>() = H;
  O.middleRows<2>(2) = H * F;
  O.bottomRows<2>() = H * F * F;
  Eigen::FullPivLU<Eigen::Matrix<double, 6, 3>> lu(O);
  lu.setThreshold(1e-12);
  return static_cast<int>(lu.rank());
}

}  // namespace plexus::algorithms
