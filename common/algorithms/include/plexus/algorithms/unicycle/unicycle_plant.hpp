// Unicycle (differential-drive) kinematics with exact integration.
//
//   x' = v cos(theta),  y' = v sin(theta),  theta' = omega        (paper 000, eq. (1))
//
// With v and omega held over a step h (zero-order hold), the solution is exact:
//   dx = v h sinc(omega h / 2) cos(theta + omega h / 2)
//   dy = v h sinc(omega h / 2) sin(theta + omega h / 2)
//   dtheta = omega h
// The sinc form is smooth through omega = 0 (straight driving).
#pragma once

#include <cmath>

#include "plexus/algorithms/core/angles.hpp"

namespace plexus::algorithms {

struct UnicycleState {
  double x = 0.0;      ///< m
  double y = 0.0;      ///< m
  double theta = 0.0;  ///< rad, not wrapped (continuous), wrap for display with wrap_angle()
};

struct UnicycleInput {
  double v = 0.0;      ///< forward speed, m/s
  double omega = 0.0;  ///< turn rate, rad/s
};

/// Advances `s` by `h` seconds under a constant input `u`. Exact for constant u.
inline UnicycleState unicycle_step(const UnicycleState& s, const UnicycleInput& u, double h) {
  const double half = 0.5 * u.omega * h;
  const double dist = u.v * h * sinc(half);
  const double mid = s.theta + half;
  return {s.x + dist * std::cos(mid), s.y + dist * std::sin(mid), s.theta + u.omega * h};
}

}  // namespace plexus::algorithms
