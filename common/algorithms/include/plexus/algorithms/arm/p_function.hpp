// Zhu's bounded-integral "P-function" (paper 004, eqs. (10) and (21); Zhu 2010):
//
//   x = P(s, rho, x-, x+, t) = x(0) + integral of rho s kappa dt,
//   kappa = 0 if (x <= x- and s <= 0) or (x >= x+ and s >= 0), else 1,
//
// i.e. an integrator of rho s that stops at the bounds when the drive points outward.
// Discrete form used here: x+ = clamp(x + dt rho s kappa, x-, x+) with kappa taken at the
// start of the step, so x never leaves [x-, x+] (the property the adaptation proofs need).
#pragma once

#include <algorithm>

namespace plexus::algorithms {

/// Advances x by one P-function step; returns the applied rate dx/dt (0 when projected).
inline double p_function_step(double& x, double rho, double s, double lo, double hi, double dt) {
  const double rate = rho * s;
  if ((x <= lo && rate <= 0.0) || (x >= hi && rate >= 0.0)) {
    x = std::clamp(x, lo, hi);
    return 0.0;
  }
  const double next = std::clamp(x + dt * rate, lo, hi);
  const double applied = (next - x) / dt;
  x = next;
  return applied;
}

}  // namespace plexus::algorithms
