// Inertial sensors of the balancing robot (paper 002, section 4.1): a single-axis rate
// gyro (ADXRS150, +-150 deg/s) and a two-axis accelerometer (ADXL202, +-2 g) whose tilt
// is atan2 of its two axes.
//
// Gyro (drift model of paper 002 eq. (10), third line; Barshan & Durrant-Whyte 1995):
//   gyro_k = sat(theta_dot + eps + n_g),  n_g ~ N(0, noise_std^2)
//   eps' = gamma1 eps + gamma2 + w_eps,   w_eps white with PSD drift_noise_psd
//   (integrated exactly over each sample period for gamma1 != 0: an Ornstein-Uhlenbeck step)
// Accelerometer at height d on the body axis, measuring the specific force in body axes
// (x_b forward across the body, z_b along the body towards its top):
//   p = (x + d sin theta, d cos theta),  f = p'' + (0, g)
//   f_xb = f . (cos theta, -sin theta),  f_zb = f . (sin theta, cos theta)
//   each + N(0, noise_std^2), saturated at +-range; tilt = atan2(-f_xb, f_zb).
// At rest tilt = theta; when the body accelerates the tilt is off by the linear
// acceleration (the error the filters must ride through).
#pragma once

#include <cstdint>

#include "plexus/algorithms/balancing/wheeled_inverted_pendulum.hpp"
#include "plexus/algorithms/core/random.hpp"

namespace plexus::algorithms {

struct GyroParams {
  double noise_std = 0.0087;          ///< white noise per sample, rad/s, >= 0 (0.5 deg/s)
  double gamma1 = -0.01;              ///< drift model pole, 1/s, finite (<= 0 for a stable drift)
  double gamma2 = 0.0;                ///< drift model forcing, rad/s^2, finite
  double drift_noise_psd = 1e-6;      ///< drift random walk PSD, rad^2/s^3, >= 0
  double initial_drift = 0.0087;      ///< eps(0), rad/s, finite (0.5 deg/s)
  double range = 2.6179938779914944;  ///< saturation, rad/s, > 0 (150 deg/s)
};

struct AccelerometerParams {
  double noise_std = 0.0343;  ///< per axis per sample, m/s^2, >= 0 (0.2 deg of tilt at 1 g)
  double height = 0.12;       ///< d, mounting point above the axle on the body axis, m, finite
  double range = 19.62;       ///< per-axis saturation, m/s^2, > 0 (2 g)
};

struct ImuSample {
  double gyro = 0.0;      ///< rad/s
  double acc_x = 0.0;     ///< f_xb, m/s^2
  double acc_z = 0.0;     ///< f_zb, m/s^2
  double acc_tilt = 0.0;  ///< atan2(-acc_x, acc_z), rad
  double drift = 0.0;     ///< true gyro drift eps at this sample, rad/s (truth, for metrics)
};

class ImuSensor {
 public:
  /// Validates; throws std::invalid_argument naming the parameter ("gyro.noise_std", ...).
  ImuSensor(const GyroParams& gyro, const AccelerometerParams& acc, double gravity, std::uint64_t seed);

  /// Samples the sensors at the plant state `s` with accelerations `acc`; `dt` (> 0) is the
  /// time since the previous sample (the drift is advanced by it; the first call only
  /// samples). No allocation.
  ImuSample measure(const WheeledPendulumState& s, const WheeledPendulumAccelerations& acc, double dt);

  /// The noise-free accelerometer specific force (f_xb, f_zb) at a state.
  static void specific_force(const WheeledPendulumState& s, const WheeledPendulumAccelerations& acc, double height,
                             double gravity, double& f_xb, double& f_zb);

  double drift() const { return drift_; }

 private:
  GyroParams gyro_;
  AccelerometerParams acc_;
  double gravity_;
  Rng rng_;
  double drift_;
  bool started_ = false;
};

}  // namespace plexus::algorithms
