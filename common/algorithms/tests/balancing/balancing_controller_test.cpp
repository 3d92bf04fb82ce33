#include "plexus/algorithms/balancing/balancing_controller.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "../support/validation_message.hpp"

namespace plexus::algorithms {
namespace {

// Ackermann's formula places exactly the requested poles on the linearisation.
TEST(BalancingController, PlacesThePoles) {
  WheeledInvertedPendulum plant({});
  for (const std::array<double, 4> poles :
       {std::array<double, 4>{-2, -3, -9, -10}, std::array<double, 4>{-1, -4, -6, -15}}) {
    BalancingController ctl({poles}, plant);
    const Eigen::Matrix4d Acl = plant.linear_a() - plant.linear_b() * ctl.gain();
    Eigen::Vector4d ev = Acl.eigenvalues().real();
    std::sort(ev.data(), ev.data() + 4);
    std::array<double, 4> want = poles;
    std::sort(want.begin(), want.end());
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(ev(i), want[i], 1e-6 * std::abs(want[i]));
    EXPECT_LT(Acl.eigenvalues().imag().cwiseAbs().maxCoeff(), 1e-6);
  }
}

// With the true state the nonlinear plant balances from 5 degrees and follows the profile.
TEST(BalancingController, BalancesTheNonlinearPlantAndFollowsTheProfile) {
  WheeledInvertedPendulum plant({});
  BalancingController ctl({}, plant);
  MotionProfile profile({});
  WheeledPendulumState s{0, 0, 5.0 * M_PI / 180, 0};
  double max_tilt = 0;
  for (int k = 0; k < 1000; ++k) {
    plant.step(s, ctl.torque(s.x, s.v, s.theta, s.theta_dot, profile.sample(k * 0.01)), 0.01);
    max_tilt = std::max(max_tilt, std::abs(s.theta));
  }
  EXPECT_LT(max_tilt, 0.2);
  EXPECT_NEAR(s.v, profile.params().speed, 0.02);
  EXPECT_NEAR(s.x, profile.sample(10.0).x, 0.1);
}

// The profile is at rest, then continuous in position and speed, with v = dx/dt.
TEST(MotionProfile, ContinuousAndConsistent) {
  MotionProfile p({1.0, 1.5, 0.3});
  EXPECT_EQ(p.sample(0.5).v, 0.0);
  EXPECT_EQ(p.sample(1.0).x, 0.0);
  for (double t = 0.0; t < 5.0; t += 0.013) {
    const double h = 1e-6;
    EXPECT_NEAR((p.sample(t + h).x - p.sample(t - h).x) / (2 * h), p.sample(t).v, 1e-6) << t;
  }
  EXPECT_NEAR(p.sample(2.5 - 1e-12).v, 0.3, 1e-9);
  EXPECT_NEAR(p.sample(2.5 + 1e-12).x, 0.3 * 0.75, 1e-9);
}

TEST(BalancingController, EveryValidationError) {
  WheeledInvertedPendulum plant({});
  auto msg = [&](std::array<double, 4> poles) {
    return testing::invalid_argument_message<BalancingController>(BalancingControllerParams{poles}, plant);
  };
  EXPECT_EQ(msg({-1, -2, 0, -4}), "balancing_controller: poles[2] must be finite and < 0 (got 0)");
  EXPECT_EQ(msg({NAN, -2, -3, -4}), "balancing_controller: poles[0] must be finite and < 0 (got nan)");
  EXPECT_EQ(msg({-1, -2, -3, -2}), "balancing_controller: poles[3] must be distinct from the others (got -2)");
  EXPECT_EQ(testing::invalid_argument_message<MotionProfile>(MotionProfileParams{-1, 1, 1}),
            "motion_profile: hold_time must be finite and >= 0 (got -1)");
  EXPECT_EQ(testing::invalid_argument_message<MotionProfile>(MotionProfileParams{1, 0, 1}),
            "motion_profile: ramp_time must be finite and > 0 (got 0)");
  EXPECT_EQ(testing::invalid_argument_message<MotionProfile>(MotionProfileParams{1, 1, NAN}),
            "motion_profile: speed must be finite (got nan)");
}

}  // namespace
}  // namespace plexus::algorithms
