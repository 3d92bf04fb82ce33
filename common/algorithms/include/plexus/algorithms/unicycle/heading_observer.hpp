// Reduced-order heading observer from positions (paper 000, Theorem 1, eqs. (5)-(11)).
//
// Measured: position (x, y) and the applied input (v, omega). Estimated:
// (z3, z4) = (cos theta, sin theta), and theta_hat = atan2(z4_hat, z3_hat) (eq. (11)).
//
// Continuous time (docs/papers.md, paper 000; the paper prints the zeta' equations as z_hat'):
//   z3_hat = zeta3 + L x,  z4_hat = zeta4 + L y
//   zeta3' = -z4_hat omega - L v z3_hat
//   zeta4' =  z3_hat omega - L v z4_hat
// Error e = (cos theta - z3_hat, sin theta - z4_hat):  e' = (-L v I + omega J) e
// (eq. (8)), so |e(t)| <= |e(0)| exp(-L v_min t) (eq. (10)).
//
// Discretisation (update()): inputs are held over the step (the same zero-order
// hold as unicycle_step). In terms of z_hat, with M = -L v I + omega J:
//   kExactArc (default): z_hat+ = e^{M h} z_hat + L phi(L v h) / sinc(omega h / 2) R(omega h / 2) dp
//     with phi(a) = (1 - e^{-a}) / a. This is the exact solution of the observer ODE when
//     the position between the two samples follows the unicycle arc under the held
//     input; with the exact plant the error obeys e+ = e^{M h} e exactly, i.e. the
//     continuous-time decay of eq. (10) is reproduced at any step size.
//   kHeldPosition: z_hat+ = e^{M h} z_hat + L dp: the ODE integrated exactly with the
//     position held between samples (then the jump L dp of z_hat = zeta + L p). Error
//     O(h) relative to the continuous observer; robust when the position sample is
//     not refreshed every step (slow sensor, repeated measurement).
// Both are allocation-free closed forms (a 2x2 rotation and an exponential).
#pragma once

#include <cmath>

#include <Eigen/Core>

#include "plexus/algorithms/unicycle/unicycle_plant.hpp"

namespace plexus::algorithms {

/// How the continuous observer ODE is integrated over one update() step.
enum class ObserverDiscretisation {
  kExactArc,      ///< exact for the unicycle under held inputs (default)
  kHeldPosition,  ///< exact for a position held constant between samples
};

struct HeadingObserverParams {
  double L = 1.0;  ///< observer gain, > 0 (paper 000: 1 in 6.1, 4 in 6.3.1, 0.6 in 6.3.2)
  ObserverDiscretisation discretisation = ObserverDiscretisation::kExactArc;
};

struct HeadingObserverState {
  Eigen::Vector2d z_hat = Eigen::Vector2d::Zero();     ///< (z3_hat, z4_hat), estimate of (cos theta, sin theta)
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  ///< last measured position (z1, z2), m
  bool has_position = false;                           ///< false until reset() or the first update()
};

class HeadingObserver {
 public:
  /// Validates L > 0 (finite); throws std::invalid_argument naming L and its value.
  explicit HeadingObserver(const HeadingObserverParams& params);

  /// Sets z_hat(0) and the position measured at t = 0. The paper's observer states are
  /// then zeta(0) = z_hat0 - L position0.
  void reset(const Eigen::Vector2d& z_hat0, const Eigen::Vector2d& position0);

  /// Advances the observer from the previous measurement to `position`, measured dt
  /// seconds later, with `input` applied (held) over that interval. dt <= 0 or a
  /// non-finite argument leaves the state unchanged. The first call without reset()
  /// only records the position. No allocation.
  void update(double dt, const Eigen::Vector2d& position, const UnicycleInput& input);

  /// theta_hat = atan2(z4_hat, z3_hat) in (-pi, pi]  (paper 000, eq. (11)); 0 when z_hat = 0.
  double heading() const { return std::atan2(state_.z_hat.y(), state_.z_hat.x()); }

  /// The paper's internal states (zeta3, zeta4) = z_hat - L position (eq. (5)).
  Eigen::Vector2d zeta() const { return state_.z_hat - params_.L * state_.position; }

  const HeadingObserverState& state() const { return state_; }
  const HeadingObserverParams& params() const { return params_; }
  /// A new gain while it runs (plexus param): validated as the constructor validates it
  /// (throws std::invalid_argument, keeping the old one). The estimate z_hat is the state
  /// kept, so it stays continuous; zeta = z_hat - L position follows the new L.
  void set_params(const HeadingObserverParams& params);

 private:
  HeadingObserverParams params_;
  HeadingObserverState state_;
};

}  // namespace plexus::algorithms
