// Attitude filter of the balancing robot (paper 002): one of the three generic filters
// (core/ukf.hpp, core/ekf.hpp) on the attitude model (attitude_model.hpp).
//
//   kUkfAugmented: AugmentedUkf over [x; w; v]: 3 + 3 + 1 = 7 -> 15 sigma points with the
//                  paper's measurement (3 + 3 + 2 = 8 -> 17 with the observable form)
//   kUkfAdditive:  AdditiveUkf, 2 * 3 + 1 = 7 sigma points (paper section 4.2)
//   kEkf:          ExtendedKalmanFilter with the analytic Jacobians of attitude_model
//
// Noise (paper 002, Table 1), per sample: Q = diag(Q_A, Q_G, Q_eps) on [theta, theta_dot,
// eps] (the Table's units are those of the states: (0.2 deg)^2, (0.05 deg/s)^2,
// (0.3 deg/s)^2), R = R_A (paper form) or diag(R_A, R_G) (observable form; R_G is not in
// the paper: default the gyro's noise, (0.5 deg/s)^2).
// Each step(): predict with the torque applied over the last sample, then update with the
// accelerometer tilt (and the gyro). The first step() after reset() only updates.
#pragma once

#include <cstdint>

#include <Eigen/Core>

#include "plexus/algorithms/balancing/attitude_model.hpp"
#include "plexus/algorithms/core/ekf.hpp"
#include "plexus/algorithms/core/ukf.hpp"

namespace plexus::algorithms {

enum class AttitudeFilterKind { kUkfAugmented, kUkfAdditive, kEkf };

struct AttitudeFilterParams {
  AttitudeFilterKind kind = AttitudeFilterKind::kUkfAugmented;
  AttitudeMeasurementForm measurement = AttitudeMeasurementForm::kObservable;
  AttitudeModelParams model;
  double q_theta = 0.0034906585039886592;            ///< sqrt(Q_A), rad, >= 0 (0.2 deg)
  double q_rate = 0.00087266462599716477;            ///< sqrt(Q_G), rad/s, >= 0 (0.05 deg/s)
  double q_drift = 0.0052359877559829887;            ///< sqrt(Q_eps), rad/s, >= 0 (0.3 deg/s)
  double r_tilt = 0.0034906585039886592;             ///< sqrt(R_A), rad, > 0 (0.2 deg)
  double r_gyro = 0.0087266462599716477;             ///< sqrt(R_G), rad/s, > 0 (0.5 deg/s; observable form)
  double initial_theta_std = 0.0087266462599716477;  ///< rad, > 0 (0.5 deg; starts upright)
  double initial_rate_std = 0.017453292519943295;    ///< rad/s, > 0 (1 deg/s)
  double initial_drift_std = 0.017453292519943295;   ///< rad/s, > 0 (1 deg/s)
  UnscentedParams sigma;                             ///< alpha, beta (2), kappa for the UKFs
};

class AttitudeFilter {
 public:
  using State = Eigen::Vector3d;

  /// Validates everything; throws std::invalid_argument naming the parameter.
  explicit AttitudeFilter(const AttitudeFilterParams& params);

  /// Estimate x0 with the initial covariance diag(initial_*_std^2).
  void reset(const State& x0);

  /// One sample: predict over dt with `torque` (applied since the previous sample), then
  /// update with the accelerometer tilt and the gyro (ignored in the paper form). Returns
  /// false if the filter refused a step (non-finite input; estimate kept). No allocation.
  bool step(double torque, double acc_tilt, double gyro);
  /// One sample period of prediction with `torque` and no measurement: a sample that never
  /// came. The next step() predicts its own period and updates as usual. Before the first
  /// step() it does nothing (the first step() only updates). Returns false if refused
  /// (non-finite torque or prediction; estimate kept). No allocation.
  bool predict(double torque);

  const State& state() const;
  const Eigen::Matrix3d& covariance() const;
  const AttitudeModel& model() const { return model_; }
  const AttitudeFilterParams& params() const { return params_; }
  /// Sigma points per cycle (0 for the EKF).
  int sigma_points() const;

 private:
  AttitudeFilterParams params_;
  AttitudeModel model_;
  Eigen::Matrix3d Q_;
  bool predicted_once_ = false;
  AugmentedUkf<3, 3, 1> aug1_;
  AugmentedUkf<3, 3, 2> aug2_;
  AdditiveUkf<3> add_;
  ExtendedKalmanFilter<3> ekf_;
};

}  // namespace plexus::algorithms
