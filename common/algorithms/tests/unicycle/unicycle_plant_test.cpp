#include "plexus/algorithms/unicycle/unicycle_plant.hpp"

#include <gtest/gtest.h>

#include <numbers>

namespace plexus::algorithms {
namespace {

TEST(UnicyclePlant, ExactOnACircle) {
  // v = 1, omega = 1: a unit circle centred at (0, 1), a quarter turn after pi/2 s.
  UnicycleState s;
  const double h = std::numbers::pi / 2 / 7;  // seven coarse steps must still be exact
  for (int i = 0; i < 7; ++i) s = unicycle_step(s, {1.0, 1.0}, h);
  EXPECT_NEAR(s.x, 1.0, 1e-12);
  EXPECT_NEAR(s.y, 1.0, 1e-12);
  EXPECT_NEAR(s.theta, std::numbers::pi / 2, 1e-12);
}

TEST(UnicyclePlant, StraightLineWhenOmegaIsZero) {
  UnicycleState s{1.0, 2.0, std::numbers::pi / 4};
  s = unicycle_step(s, {2.0, 0.0}, 0.5);
  EXPECT_NEAR(s.x, 1.0 + std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(s.y, 2.0 + std::sqrt(0.5), 1e-12);
}

TEST(Angles, WrapAndSinc) {
  EXPECT_NEAR(wrap_angle(3 * std::numbers::pi), std::numbers::pi, 1e-12);
  EXPECT_NEAR(wrap_angle(-std::numbers::pi), std::numbers::pi, 1e-12);
  EXPECT_NEAR(wrap_angle(0.5), 0.5, 1e-15);
  EXPECT_NEAR(sinc(1e-5), std::sin(1e-5) / 1e-5, 1e-15);
  EXPECT_NEAR(sinc(0.0), 1.0, 0.0);
}

}  // namespace
}  // namespace plexus::algorithms
