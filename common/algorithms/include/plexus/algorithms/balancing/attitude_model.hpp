// Attitude process and measurement models of paper 002, section 3, discretised for the
// filters (state X = [theta, theta_dot, eps]: tilt, tilt rate, gyro drift; rad, rad/s, rad/s).
//
// Process (eq. (10), explicit Euler over the sample time dt, additive per-step noise w):
//   theta+     = theta + dt theta_dot                               + w1
//   theta_dot+ = theta_dot + dt theta''(theta, theta_dot, T)        + w2
//   eps+       = eps + dt (gamma1 eps + gamma2)                     + w3
// with theta'' from eq. (10) (kNonlinear) or eq. (11) (kLinear); T = T_L + T_R is the
// torque applied over the step (the controller's previous command).
// Measurements:
//   kPaper:      z = theta + v                                (eq. (11), accelerometer tilt only;
//                the drift then never enters any output: unobservable, see observability_rank)
//   kObservable: z = [tilt_acc(x, T); sat(theta_dot + eps)] + v   (accelerometer tilt and the gyro,
//                with the gyro's saturation at +-gyro_range in the model)
// tilt_acc is what the two-axis accelerometer at height d reads (imu_sensor.hpp): atan2 of
// the specific force, which contains the body's linear acceleration. With the torque known
// the model predicts that acceleration from the state (theta'' from eq. (10), x'' from the
// wheel equation), so tilt_acc(x, T) is a nonlinear function of [theta, theta_dot]:
//   kNonlinear: exact atan2 form;  kLinear: tilt_acc = theta - (x'' + d theta'') / g, linearised.
// (The paper's form treats the accelerometer tilt as theta itself; when the robot
// accelerates it is off by about (x'' + d theta'') / g, which the paper's R_A ignores.)
#pragma once

#include <Eigen/Core>

#include "plexus/algorithms/balancing/wheeled_inverted_pendulum.hpp"

namespace plexus::algorithms {

enum class AttitudeProcessModel { kNonlinear, kLinear };
enum class AttitudeMeasurementForm { kPaper, kObservable };

struct AttitudeModelParams {
  PendulumCoefficients coefficients;       ///< alpha1..alpha4, k_T (from WheeledInvertedPendulum)
  double gamma1 = -0.01;                   ///< drift model pole, 1/s, finite
  double gamma2 = 0.0;                     ///< drift model forcing, rad/s^2, finite
  double dt = 0.01;                        ///< sample time, s, > 0 (paper Table 1: 0.01)
  double gyro_range = 2.6179938779914944;  ///< rad/s, > 0 (150 deg/s; infinity: no saturation)
  double accelerometer_height = 0.12;      ///< d, m, finite (imu_sensor.hpp)
  double gravity = 9.81;                   ///< g, m/s^2, > 0
  AttitudeProcessModel process = AttitudeProcessModel::kNonlinear;
};

class AttitudeModel {
 public:
  using State = Eigen::Vector3d;

  /// Validates; throws std::invalid_argument ("attitude_model: dt must be ...").
  explicit AttitudeModel(const AttitudeModelParams& params);

  /// f(x, T): one Euler step of eq. (10) or (11).
  State predict(const State& x, double torque) const;
  /// df/dx at x (analytic).
  Eigen::Matrix3d jacobian(const State& x, double torque) const;
  /// theta'' of the chosen process model.
  double tilt_acceleration(double theta, double theta_dot, double torque) const;
  /// Partial derivatives of theta'' with respect to theta and theta_dot.
  void tilt_acceleration_partials(double theta, double theta_dot, double torque, double& d_theta, double& d_rate) const;

  /// Accelerometer tilt model tilt_acc(x, T) and its gradient d/dx (third entry 0).
  double accelerometer_tilt(const State& x, double torque) const;
  Eigen::RowVector3d accelerometer_tilt_gradient(const State& x, double torque) const;

  /// Gyro model sat(theta_dot + eps) and its derivative (1 inside the range, 0 outside).
  double gyro(const State& x) const;
  double gyro_slope(const State& x) const;

  /// Rank of the observability matrix [H; H F; H F^2] of the linearised pair at x.
  int observability_rank(const State& x, double torque, AttitudeMeasurementForm form) const;

  const AttitudeModelParams& params() const { return params_; }

 private:
  AttitudeModelParams params_;
};

}  // namespace plexus::algorithms
