#include "plexus/algorithms/balancing/imu_sensor.hpp"

#include <algorithm>
#include <cmath>

#include "plexus/algorithms/core/validation.hpp"

namespace plexus::algorithms {

ImuSensor::ImuSensor(const GyroParams& g, const AccelerometerParams& a, double gravity, std::uint64_t seed)
    : gyro_(g), acc_(a), gravity_(gravity), rng_(seed), drift_(g.initial_drift) {
  constexpr const char* kWhere = "imu_sensor";
  validation::require_non_negative(kWhere, "gyro.noise_std", g.noise_std);
  validation::require_finite(kWhere, "gyro.gamma1", g.gamma1);
  validation::require_finite(kWhere, "gyro.gamma2", g.gamma2);
  validation::require_non_negative(kWhere, "gyro.drift_noise_psd", g.drift_noise_psd);
  validation::require_finite(kWhere, "gyro.initial_drift", g.initial_drift);
  validation::require_positive_or_inf(kWhere, "gyro.range", g.range);
  validation::require_non_negative(kWhere, "accelerometer.noise_std", a.noise_std);
  validation::require_finite(kWhere, "accelerometer.height", a.height);
  validation::require_positive_or_inf(kWhere, "accelerometer.range", a.range);
  validation::require_positive(kWhere, "gravity", gravity);
}

void ImuSensor::specific_force(const WheeledPendulumState& s, const WheeledPendulumAccelerations& acc, double d,
                               double g, double& f_xb, double& f_zb) {
  const double sn = std::sin(s.theta), cs = std::cos(s.theta);
  const double w2 = s.theta_dot * s.theta_dot;
  // p'' of p = (x + d sin theta, d cos theta), plus the gravity reaction (0, g).
  const double fx = acc.x_ddot + d * (cs * acc.theta_ddot - sn * w2);
  const double fz = -d * (sn * acc.theta_ddot + cs * w2) + g;
  f_xb = fx * cs - fz * sn;
  f_zb = fx * sn + fz * cs;
}

ImuSample ImuSensor::measure(const WheeledPendulumState& s, const WheeledPendulumAccelerations& acc, double dt) {
  if (started_ && dt > 0.0) {
    // eps' = gamma1 eps + gamma2 + w: exact discretisation (Ornstein-Uhlenbeck for gamma1 != 0).
    const double g1 = gyro_.gamma1;
    double phi, gain, var;
    if (std::abs(g1 * dt) < 1e-9) {
      phi = 1.0;
      gain = dt;
      var = gyro_.drift_noise_psd * dt;
    } else {
      phi = std::exp(g1 * dt);
      gain = (phi - 1.0) / g1;
      var = gyro_.drift_noise_psd * (phi * phi - 1.0) / (2.0 * g1);
    }
    drift_ = phi * drift_ + gain * gyro_.gamma2 + std::sqrt(std::max(var, 0.0)) * rng_.normal();
  }
  started_ = true;
  ImuSample m;
  m.drift = drift_;
  m.gyro = std::clamp(s.theta_dot + drift_ + gyro_.noise_std * rng_.normal(), -gyro_.range, gyro_.range);
  double fx, fz;
  specific_force(s, acc, acc_.height, gravity_, fx, fz);
  m.acc_x = std::clamp(fx + acc_.noise_std * rng_.normal(), -acc_.range, acc_.range);
  m.acc_z = std::clamp(fz + acc_.noise_std * rng_.normal(), -acc_.range, acc_.range);
  m.acc_tilt = std::atan2(-m.acc_x, m.acc_z);
  return m;
}

}  // namespace plexus::algorithms
