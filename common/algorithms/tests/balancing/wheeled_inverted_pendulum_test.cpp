#include "plexus/algorithms/balancing/wheeled_inverted_pendulum.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "../support/validation_message.hpp"

namespace plexus::algorithms {
namespace {

using testing::invalid_argument_message;

// The paper's eq. (10) with the derived alpha1..alpha4, k_T equals theta'' of the full
// 2x2 Lagrange equations at any state and torque.
TEST(WheeledInvertedPendulum, PaperFormEqualsLagrangeEquations) {
  WheeledInvertedPendulum plant({});
  const PendulumCoefficients& c = plant.coefficients();
  for (double th : {-1.2, -0.3, 0.0, 0.1, 0.7, 1.4})
    for (double w : {-3.0, 0.0, 0.5, 2.0})
      for (double T : {-2.0, 0.0, 1.5}) {
        const WheeledPendulumAccelerations a = plant.accelerations({0.0, 0.0, th, w}, T);
        EXPECT_NEAR(c.tilt_acceleration(th, w, T), a.theta_ddot, 1e-10 * (1 + std::abs(a.theta_ddot)));
        EXPECT_NEAR(c.axle_acceleration(th, w, a.theta_ddot, T), a.x_ddot, 1e-10 * (1 + std::abs(a.x_ddot)));
      }
}

// Near 0 the nonlinear model approaches the linearisation (11): the difference is of
// second order (it shrinks ~100x when the state shrinks 10x), and A, B match eq. (11).
TEST(WheeledInvertedPendulum, NonlinearModelApproachesLinearisationNearZero) {
  WheeledInvertedPendulum plant({});
  const PendulumCoefficients& c = plant.coefficients();
  double prev = 0;
  for (double eps : {1e-1, 1e-2, 1e-3}) {
    const double th = eps, w = 2 * eps, T = 0.5 * eps;
    const double diff = std::abs(c.tilt_acceleration(th, w, T) - c.linear_tilt_acceleration(th, T));
    if (prev > 0) {
      EXPECT_LT(diff, prev * 0.02) << eps;  // ~ eps^2 (1/100 per decade) or better
    }
    prev = diff;
  }
  const Eigen::Matrix4d A = plant.linear_a();
  const Eigen::Vector4d B = plant.linear_b();
  EXPECT_NEAR(A(3, 2), c.alpha3 / (1 - c.alpha1), 1e-9);
  EXPECT_NEAR(B(3), c.torque_gain * (1 + c.alpha4) / (1 - c.alpha1), 1e-9);
  // Finite-difference linearisation of the full model at 0 equals (A, B).
  const double h = 1e-7;
  for (int j = 0; j < 4; ++j) {
    Eigen::Vector4d s = Eigen::Vector4d::Zero();
    s(j) = h;
    const auto a = plant.accelerations({s(0), s(1), s(2), s(3)}, 0.0);
    EXPECT_NEAR(a.x_ddot / h, A(1, j), 1e-5);
    EXPECT_NEAR(a.theta_ddot / h, A(3, j), 1e-5);
  }
  const auto a = plant.accelerations({}, h);
  EXPECT_NEAR(a.x_ddot / h, B(1), 1e-5);
  EXPECT_NEAR(a.theta_ddot / h, B(3), 1e-5);
}

// Without torque the upright is unstable at rate sqrt(alpha3 / (1 - alpha1)); the
// integrator conserves the energy of the torque-free system.
TEST(WheeledInvertedPendulum, UnstableUprightAndEnergyConservation) {
  WheeledPendulumParams p;
  WheeledInvertedPendulum plant(p);
  WheeledPendulumState s{0, 0, 1e-6, 0};
  const double lambda = std::sqrt(plant.coefficients().alpha3 / (1 - plant.coefficients().alpha1));
  for (int k = 0; k < 100; ++k) plant.step(s, 0.0, 0.01);
  EXPECT_NEAR(s.theta / 1e-6, std::cosh(lambda * 1.0), 0.01 * std::cosh(lambda * 1.0));

  auto energy = [&](const WheeledPendulumState& q) {
    const double a = p.body_mass + p.wheel_mass + p.wheel_inertia / (p.wheel_radius * p.wheel_radius);
    const double b = p.body_mass * p.com_height, c = p.body_inertia + p.body_mass * p.com_height * p.com_height;
    return 0.5 * a * q.v * q.v + b * std::cos(q.theta) * q.v * q.theta_dot + 0.5 * c * q.theta_dot * q.theta_dot +
           b * p.gravity * std::cos(q.theta);
  };
  WheeledPendulumState q{0, 0.2, 0.3, -0.5};
  const double e0 = energy(q);
  for (int k = 0; k < 200; ++k) plant.step(q, 0.0, 0.01);
  EXPECT_NEAR(energy(q), e0, 1e-6 * std::abs(e0));
}

TEST(WheeledInvertedPendulum, TorqueSaturates) {
  WheeledPendulumParams p;
  p.max_torque = 1.0;
  WheeledInvertedPendulum plant(p);
  EXPECT_EQ(plant.saturate(5.0), 1.0);
  EXPECT_EQ(plant.accelerations({}, 5.0).theta_ddot, plant.accelerations({}, 1.0).theta_ddot);
}

TEST(WheeledInvertedPendulum, EveryValidationError) {
  auto msg = [](auto mutate) {
    WheeledPendulumParams p;
    mutate(p);
    return invalid_argument_message<WheeledInvertedPendulum>(p);
  };
  EXPECT_EQ(msg([](auto& p) { p.body_mass = 0; }),
            "wheeled_inverted_pendulum: body_mass must be finite and > 0 (got 0)");
  EXPECT_EQ(msg([](auto& p) { p.com_height = -1; }),
            "wheeled_inverted_pendulum: com_height must be finite and > 0 (got -1)");
  EXPECT_EQ(msg([](auto& p) { p.body_inertia = -1; }),
            "wheeled_inverted_pendulum: body_inertia must be finite and >= 0 (got -1)");
  EXPECT_EQ(msg([](auto& p) { p.wheel_mass = NAN; }),
            "wheeled_inverted_pendulum: wheel_mass must be finite and >= 0 (got nan)");
  EXPECT_EQ(msg([](auto& p) { p.wheel_radius = 0; }),
            "wheeled_inverted_pendulum: wheel_radius must be finite and > 0 (got 0)");
  EXPECT_EQ(msg([](auto& p) { p.wheel_inertia = -2; }),
            "wheeled_inverted_pendulum: wheel_inertia must be finite and >= 0 (got -2)");
  EXPECT_EQ(msg([](auto& p) { p.gravity = 0; }), "wheeled_inverted_pendulum: gravity must be finite and > 0 (got 0)");
  EXPECT_EQ(msg([](auto& p) { p.max_torque = 0; }),
            "wheeled_inverted_pendulum: max_torque must be > 0 (infinity allowed) (got 0)");
  EXPECT_EQ(msg([](auto& p) { p.body_inertia = 0, p.wheel_mass = 0, p.wheel_inertia = 0; }),
            "wheeled_inverted_pendulum: body_inertia must be > 0 when wheel_mass and wheel_inertia are 0 (alpha1 < 1) "
            "(got 0)");
  EXPECT_EQ(msg([](auto& p) { p.max_torque = std::numeric_limits<double>::infinity(); }), "");
}

}  // namespace
}  // namespace plexus::algorithms
