#include "plexus/algorithms/unicycle/path_following_controller.hpp"

#include <gtest/gtest.h>

#include "../support/validation_message.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "plexus/algorithms/unicycle/geometric_path.hpp"
#include "plexus/algorithms/unicycle/unicycle_plant.hpp"
#include "plexus/algorithms/unicycle/velocity_heading_observer.hpp"

namespace plexus::algorithms {
namespace {

constexpr double kStep = 0.01;  // 100 Hz, inputs held over the step, exact plant

// Paper 003, section 5 with state feedback (eq. (5)): u1 = 1, unit circle, k1 = 1, k2 = 2.
// The closed loop is h'' + 2 h' + h = 0 (eq. (6)): h(t) = (h0 + (h0' + h0) t) e^{-t}.
TEST(PathFollowing, StateFeedbackFollowsTheLinearisedErrorDynamics) {
  GeometricPath circle(CirclePath{});
  PathFollowingController ctl({1.0, 2.0});
  const double u1 = 1.0;
  UnicycleState s{1.2, 0.0, std::numbers::pi / 2 + 0.3};
  const PathFollowingOutput first = ctl.state_feedback(circle, s, u1);
  const double h0 = first.h, hd0 = first.h_dot;
  double max_dev = 0;
  for (int k = 1; k <= 2000; ++k) {
    const PathFollowingOutput out = ctl.state_feedback(circle, s, u1);
    ASSERT_FALSE(out.g_saturated);
    s = unicycle_step(s, {u1, out.u2}, kStep);
    const double t = k * kStep;
    const double analytic = (h0 + (hd0 + h0) * t) * std::exp(-t);
    max_dev = std::max(max_dev, std::abs(circle.evaluate({s.x, s.y}).h - analytic));
  }
  EXPECT_LT(max_dev, 0.01 * std::abs(h0));  // O(step) from the held u2
  const PathFollowingOutput last = ctl.state_feedback(circle, s, u1);
  EXPECT_LT(std::abs(last.h), 1e-6);
  EXPECT_LT(std::abs(last.h_dot), 1e-6);
  EXPECT_NEAR(last.u2, 1.0, 1e-5);  // unit circle at unit speed, counter-clockwise
}

struct ObserverRun {
  double h = 0, h_dot = 0, e = 0;  // at the end
  double max_abs_h_tail = 0;       // max |h| over the last 5 s
  bool saturated = false;
};

// Observer-based law (15)-(16) with the velocity observer (11). Initial conditions (not given
// in the paper, documented in docs/algorithms/unicycle.md): robot at (1.2, 0) heading
// pi/2 + 0.3, u1 = 1; observer z_hat(0) = (0.3, 0.6) against the true (x', y') = (-0.30, 0.96).
ObserverRun run_observer_based(const GeometricPath& path, UnicycleState s, Eigen::Vector2d z_hat0, double T,
                               bool check_rate = false, double step = kStep) {
  PathFollowingController ctl({1.0, 2.0});
  VelocityHeadingObserver obs({2.0, 2.0});
  const double u1 = 1.0;
  obs.reset(z_hat0, {s.x, s.y});
  auto err = [&] {
    return (Eigen::Vector2d(u1 * std::cos(s.theta), u1 * std::sin(s.theta)) - obs.state().z_hat).norm();
  };
  const double e0 = err();
  ObserverRun r;
  const int steps = static_cast<int>(std::lround(T / step));
  for (int k = 1; k <= steps; ++k) {
    const PathFollowingOutput out = ctl.observer_based(path, {s.x, s.y}, obs.state().z_hat);
    r.saturated |= out.g_saturated;
    s = unicycle_step(s, {u1, out.u2}, step);
    obs.update(step, {s.x, s.y}, out.u2);
    if (check_rate) {
      EXPECT_LE(err(), e0 * std::exp(-2.0 * k * step) * (1 + 1e-9) + 1e-13);
    }
    if (k * step > T - 5.0) r.max_abs_h_tail = std::max(r.max_abs_h_tail, std::abs(path.evaluate({s.x, s.y}).h));
  }
  const PathFollowingOutput truth = ctl.state_feedback(path, s, u1);
  r.h = truth.h;
  r.h_dot = truth.h_dot;
  r.e = err();
  return r;
}

TEST(PathFollowing, ObserverBasedOnTheUnitCircleDrivesPathAndObserverErrorsToZero) {
  GeometricPath circle(CirclePath{});
  const ObserverRun r = run_observer_based(circle, {1.2, 0.0, std::numbers::pi / 2 + 0.3}, {0.3, 0.6}, 20.0, true);
  EXPECT_FALSE(r.saturated);
  EXPECT_LT(std::abs(r.h), 1e-6);
  EXPECT_LT(std::abs(r.h_dot), 1e-6);
  EXPECT_LT(r.e, 1e-12);
}

// On paths of varying curvature the held (zero-order hold) u2 leaves an O(step) residual:
// h'' = f + g u2 is exact only at the sample instants. The residual must shrink with the step.
TEST(PathFollowing, ObserverBasedOnOtherPathShapesConvergesToAnOStepResidual) {
  PolynomialPath cubic;  // y - 0.1 x^3 = 0
  cubic.c(0, 1) = 1.0;
  cubic.c(3, 0) = -0.1;
  const GeometricPath paths[] = {GeometricPath(EllipsePath{{0.0, 0.0}, 3.0, 1.5, 0.4}),
                                 GeometricPath(LinePath{{0.0, 0.5}, {0.0, 1.0}}), GeometricPath(cubic)};
  const UnicycleState starts[] = {{2.8, 1.6, 2.0}, {-3.0, 0.3, 0.2}, {-1.0, 0.0, 0.3}};
  for (int i = 0; i < 3; ++i) {
    const UnicycleState s = starts[i];
    const Eigen::Vector2d z0(std::cos(s.theta) + 0.2, std::sin(s.theta) - 0.2);
    const double h0 = std::abs(paths[i].evaluate({s.x, s.y}).h);
    const ObserverRun coarse = run_observer_based(paths[i], s, z0, 20.0, false, 0.01);
    const ObserverRun fine = run_observer_based(paths[i], s, z0, 20.0, false, 0.001);
    EXPECT_FALSE(coarse.saturated) << i;
    EXPECT_LT(coarse.max_abs_h_tail, 0.02 * h0) << i;
    EXPECT_LT(coarse.e, 1e-12) << i;
    // (the straight line has no curvature residual, only the decaying transient: absolute floor)
    EXPECT_LT(fine.max_abs_h_tail, std::max(0.2 * coarse.max_abs_h_tail, 1e-5)) << i;
  }
}

TEST(PathFollowing, FiniteAndReportedWhenGHatVanishes) {
  GeometricPath circle(CirclePath{});
  PathFollowingParams p;
  p.min_abs_g = 1e-3;
  p.max_turn_rate = 5.0;
  PathFollowingController ctl(p);
  // z_hat = 0 (observer not yet converged): g_hat = 0 exactly.
  const PathFollowingOutput a = ctl.observer_based(circle, {1.5, 0.0}, {0.0, 0.0});
  EXPECT_TRUE(a.g_saturated);
  EXPECT_TRUE(std::isfinite(a.u2));
  EXPECT_LE(std::abs(a.u2), 5.0);
  // Velocity along the gradient: g_hat = 0 with a non-zero h' and f.
  const PathFollowingOutput b = ctl.observer_based(circle, {1.5, 0.0}, {1.0, 0.0});
  EXPECT_EQ(b.g, 0.0);
  EXPECT_TRUE(b.g_saturated);
  EXPECT_TRUE(b.turn_rate_saturated);
  EXPECT_DOUBLE_EQ(std::abs(b.u2), 5.0);
  // Near zero from either side: the sign of g is kept, u2 is bounded by |numerator| / min_abs_g.
  PathFollowingController unclamped({});
  for (double g_sign : {1.0, -1.0}) {
    const PathFollowingOutput c = unclamped.observer_based(circle, {1.5, 0.0}, {1.0, g_sign * 1e-9});
    EXPECT_TRUE(c.g_saturated);
    const double num = -c.f - 2.0 * c.h_dot - 1.0 * c.h;
    EXPECT_NEAR(c.u2, num / (std::copysign(1e-3, c.g)), 1e-9 * std::abs(num / 1e-3));
  }
}

TEST(PathFollowing, ValidationNamesTheParameter) {
  auto message = [](const PathFollowingParams& p) {
    return testing::invalid_argument_message<PathFollowingController>(p);
  };
  PathFollowingParams p;
  p.k1 = -1.0;
  EXPECT_NE(message(p).find("k1"), std::string::npos);
  p = {};
  p.k2 = 0.0;
  EXPECT_NE(message(p).find("k2"), std::string::npos);
  p = {};
  p.min_abs_g = 0.0;
  EXPECT_NE(message(p).find("min_abs_g"), std::string::npos);
  p = {};
  p.max_turn_rate = -1.0;
  EXPECT_NE(message(p).find("max_turn_rate"), std::string::npos);
  EXPECT_EQ(message({}), "");
}

}  // namespace
}  // namespace plexus::algorithms
