// Small numerically safe helpers shared by every algorithm family.
#pragma once

#include <cmath>
#include <numbers>

namespace plexus::algorithms {

/// Wraps an angle to (-pi, pi].
inline double wrap_angle(double a) {
  // Already in range: returned as is, which is exactly what remainder() gives there (the
  // quotient rounds to 0), without its cost.
  if (a > -std::numbers::pi && a <= std::numbers::pi) return a;
  a = std::remainder(a, 2.0 * std::numbers::pi);  // [-pi, pi]
  return a <= -std::numbers::pi ? a + 2.0 * std::numbers::pi : a;
}

/// sin(x)/x, smooth through 0 (Taylor series below 1e-4, where it is exact to double precision).
inline double sinc(double x) {
  if (std::abs(x) < 1e-4) return 1.0 - x * x / 6.0;
  return std::sin(x) / x;
}

}  // namespace plexus::algorithms
