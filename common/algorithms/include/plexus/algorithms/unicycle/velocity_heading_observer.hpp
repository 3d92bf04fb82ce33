// Velocity and heading observer from positions (paper 003, Theorem 1, eqs. (10)-(14)).
//
// Plant with constant unknown speed u1 != 0 and measured turn rate u2. With
// z1 = x, z2 = x' = u1 cos theta, z3 = y, z4 = y' = u1 sin theta (eq. (10)):
//   z2' = -z4 u2,  z4' = z2 u2.
// Observer (eq. (11), with the sign of the z4_bar equation fixed, docs/papers.md):
//   z2_bar' = -(z4_bar + L4 z3) u2 - L2 (z2_bar + L2 z1)
//   z4_bar' =  (z2_bar + L2 z1) u2 - L4 (z4_bar + L4 z3)
//   z2_hat = z2_bar + L2 z1,  z4_hat = z4_bar + L4 z3
//   theta_hat = atan2(z4_hat, z2_hat),  u1_hat = z2_hat cos theta_hat + z4_hat sin theta_hat  (eq. (14))
// Error e = (z2 - z2_hat, z4 - z4_hat): e' = N e with N = [[-L2, -u2], [u2, -L4]]
// (eq. (13)), |e(t)| <= |e(0)| exp(-min(L2, L4) t).
//
// Note u1_hat = |z_hat| >= 0: a robot driving backwards (u1 < 0) is represented by
// theta_hat = theta + pi and u1_hat = -u1; the velocity vector z_hat is unambiguous.
//
// Discretisation (update()), u2 held over the step, E = e^{N h} in closed form:
//   kExactArc (default): z_hat+ = E z_hat + (R(u2 h) - E) R(-u2 h / 2) / (h sinc(u2 h / 2)) dp,
//     the exact solution when the position moves along the unicycle arc between samples;
//     with the exact plant the error obeys e+ = E e exactly.
//   kHeldPosition: z_hat+ = E z_hat + diag(L2, L4) dp (ODE exact with the position held).
#pragma once

#include <cmath>

#include <Eigen/Core>

#include "plexus/algorithms/unicycle/heading_observer.hpp"

namespace plexus::algorithms {

struct VelocityHeadingObserverParams {
  double L2 = 2.0;  ///< gain on x, > 0 (paper 003, section 5: 2)
  double L4 = 2.0;  ///< gain on y, > 0 (paper 003, section 5: 2)
  ObserverDiscretisation discretisation = ObserverDiscretisation::kExactArc;
};

struct VelocityHeadingObserverState {
  Eigen::Vector2d z_hat = Eigen::Vector2d::Zero();     ///< (z2_hat, z4_hat), estimate of (x', y'), m/s
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  ///< last measured position (z1, z3), m
  bool has_position = false;
};

class VelocityHeadingObserver {
 public:
  /// Validates L2 > 0, L4 > 0 (finite); throws std::invalid_argument naming the gain.
  explicit VelocityHeadingObserver(const VelocityHeadingObserverParams& params);

  /// Sets z_hat(0) = (z2_hat, z4_hat) and the position measured at t = 0;
  /// the paper's states are z_bar(0) = z_hat0 - diag(L2, L4) position0.
  void reset(const Eigen::Vector2d& z_hat0, const Eigen::Vector2d& position0);

  /// Advances by dt to the new `position` measurement with turn rate u2 held.
  /// dt <= 0 or non-finite arguments leave the state unchanged; the first call without
  /// reset() only records the position. No allocation.
  void update(double dt, const Eigen::Vector2d& position, double u2);

  /// theta_hat = atan2(z4_hat, z2_hat)  (eq. (14)); 0 when z_hat = 0.
  double heading() const { return std::atan2(state_.z_hat.y(), state_.z_hat.x()); }

  /// u1_hat = z2_hat cos theta_hat + z4_hat sin theta_hat = |z_hat|  (eq. (14)).
  double speed() const { return state_.z_hat.norm(); }

  /// The paper's states (z2_bar, z4_bar) = z_hat - diag(L2, L4) position  (eq. (11)).
  Eigen::Vector2d z_bar() const {
    return {state_.z_hat.x() - params_.L2 * state_.position.x(), state_.z_hat.y() - params_.L4 * state_.position.y()};
  }

  const VelocityHeadingObserverState& state() const { return state_; }
  const VelocityHeadingObserverParams& params() const { return params_; }

 private:
  VelocityHeadingObserverParams params_;
  VelocityHeadingObserverState state_;
};

}  // namespace plexus::algorithms
