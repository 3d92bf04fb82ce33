// Balancing controller and motion profile of the two-wheeled robot (paper 002, section 4:
// "the robot balances briefly, then moves").
//
// Controller: full-state feedback on the linearisation at the upright equilibrium,
//   T = -K [x - x_ref, v - v_ref, theta_hat, theta_dot_hat]
// with K placed by Ackermann's formula so that eig(A - B K) = the four given (real,
// negative, distinct) poles. x and v come from the wheel encoders (taken exact); theta
// and theta_dot from the attitude filter's estimate. The command is saturated at the
// plant's max_torque.
//
// Motion profile: at rest for hold_time, then a smooth (raised-cosine) acceleration to
// `speed` over ramp_time, then constant speed:
//   v_ref(t) = speed * s((t - hold_time) / ramp_time),  s(u) = (1 - cos(pi u)) / 2 on [0, 1]
//   x_ref(t) = integral of v_ref.
#pragma once

#include <array>

#include <Eigen/Core>

#include "plexus/algorithms/balancing/wheeled_inverted_pendulum.hpp"

namespace plexus::algorithms {

struct MotionProfileParams {
  double hold_time = 1.0;  ///< s at rest first, >= 0
  double ramp_time = 1.5;  ///< s of acceleration, > 0
  double speed = 0.3;      ///< m/s after the ramp, finite (negative: backwards)
};

struct MotionReference {
  double x = 0.0;  ///< m
  double v = 0.0;  ///< m/s
};

class MotionProfile {
 public:
  /// Validates; throws std::invalid_argument.
  explicit MotionProfile(const MotionProfileParams& params);
  MotionReference sample(double t) const;
  const MotionProfileParams& params() const { return params_; }

 private:
  MotionProfileParams params_;
};

struct BalancingControllerParams {
  std::array<double, 4> poles{-2.0, -3.0, -9.0, -10.0};  ///< closed-loop poles, 1/s, real < 0, distinct
};

class BalancingController {
 public:
  /// Validates the poles and places them on `plant`'s linearisation (throws
  /// std::invalid_argument if the pair is not controllable).
  BalancingController(const BalancingControllerParams& params, const WheeledInvertedPendulum& plant);

  /// Torque T_L + T_R for the encoder state (x, v), the attitude estimate and the reference.
  double torque(double x, double v, double theta_hat, double theta_dot_hat, const MotionReference& ref) const;

  const Eigen::RowVector4d& gain() const { return K_; }

 private:
  Eigen::RowVector4d K_;
  double max_torque_;
};

}  // namespace plexus::algorithms
