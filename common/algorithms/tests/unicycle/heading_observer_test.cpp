#include "plexus/algorithms/unicycle/heading_observer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "plexus/algorithms/unicycle/figure_eight_reference.hpp"
#include "plexus/algorithms/unicycle/unicycle_plant.hpp"

namespace plexus::algorithms {
namespace {

double lyapunov(const UnicycleState& s, const HeadingObserver& obs) {
  const Eigen::Vector2d e = Eigen::Vector2d(std::cos(s.theta), std::sin(s.theta)) - obs.state().z_hat;
  return 0.5 * e.squaredNorm();  // V_o, paper 000 eq. (9)
}

// Paper 000, section 6.1: v = v_r, theta(0) = 1.5 pi, z_hat(0) = 0, L = 1, 20 s, 100 Hz.
// The robot is driven open loop with the reference's speed and turn rate.
TEST(HeadingObserver, PaperSection61LyapunovDecaysAtLeastAtRate2LVmin) {
  FigureEightReference ref({});
  HeadingObserver obs({1.0});
  UnicycleState s{0.0, -5.0, 1.5 * std::numbers::pi};
  obs.reset({0.0, 0.0}, {s.x, s.y});
  const double h = 0.01;
  const double v_min = ref.min_speed();
  const double V0 = lyapunov(s, obs);
  ASSERT_NEAR(V0, 0.5, 1e-12);
  for (int k = 1; k <= 2000; ++k) {
    const ReferenceSample r = ref.sample((k - 1) * h);
    const double v = r.dp.norm();
    const double omega = (r.dp.x() * r.ddp.y() - r.dp.y() * r.ddp.x()) / (v * v);
    s = unicycle_step(s, {v, omega}, h);
    obs.update(h, {s.x, s.y}, {v, omega});
    const double t = k * h;
    ASSERT_LE(lyapunov(s, obs), V0 * std::exp(-2.0 * 1.0 * v_min * t) * (1 + 1e-9) + 1e-15) << "t = " << t;
  }
  EXPECT_LT(lyapunov(s, obs), V0 * 0.2);  // 20 s at v ~ 0.1 m/s: exp(-2 * 1 * 0.1 * 20) ~ 0.02
}

// Faster motion, time-varying speed and turn rate: the bound exp(-2 L v_min t) holds and
// V_o actually reaches round-off, and theta_hat converges to theta.
TEST(HeadingObserver, DecayBoundWithTimeVaryingInput) {
  const double L = 2.0;
  HeadingObserver obs({L});
  UnicycleState s{1.0, 2.0, 2.5};
  obs.reset({0.3, -0.4}, {s.x, s.y});
  const double V0 = lyapunov(s, obs);
  const double h = 0.01, v_min = 0.5;
  for (int k = 1; k <= 1500; ++k) {
    const double t = (k - 1) * h;
    const UnicycleInput u{0.5 + 0.4 * (1 + std::sin(0.7 * t)), 0.8 * std::cos(0.5 * t)};
    s = unicycle_step(s, u, h);
    obs.update(h, {s.x, s.y}, u);
    ASSERT_LE(lyapunov(s, obs), V0 * std::exp(-2.0 * L * v_min * k * h) * (1 + 1e-9) + 1e-15);
  }
  EXPECT_LT(lyapunov(s, obs), 1e-20);
  EXPECT_NEAR(wrap_angle(obs.heading() - s.theta), 0.0, 1e-9);
  // zeta is the paper's internal state: z_hat = zeta + L p (eq. (5)).
  EXPECT_TRUE((obs.zeta() + L * Eigen::Vector2d(s.x, s.y)).isApprox(obs.state().z_hat));
}

// The held-position discretisation converges too, to within its O(h) bias.
TEST(HeadingObserver, HeldPositionDiscretisationConvergesWithinItsBias) {
  HeadingObserver obs({2.0, ObserverDiscretisation::kHeldPosition});
  UnicycleState s{0.0, 0.0, -1.0};
  obs.reset({0.0, 0.0}, {0.0, 0.0});
  const double h = 0.01;
  const UnicycleInput u{1.0, 0.5};
  for (int k = 0; k < 1500; ++k) {
    s = unicycle_step(s, u, h);
    obs.update(h, {s.x, s.y}, u);
  }
  const Eigen::Vector2d e = Eigen::Vector2d(std::cos(s.theta), std::sin(s.theta)) - obs.state().z_hat;
  // Steady-state bias ~ (L v + |omega|) h / 2 (one step of held position per sample).
  EXPECT_LT(e.norm(), (2.0 * u.v + std::abs(u.omega)) * h);
  EXPECT_GT(e.norm(), 1e-6);  // it is a different (biased) discretisation, not the exact one
}

TEST(HeadingObserver, IgnoresBadStepsAndRecordsTheFirstPosition) {
  HeadingObserver obs({1.0});
  obs.update(0.01, {3.0, 4.0}, {1.0, 0.0});  // no reset: only records the position
  EXPECT_TRUE(obs.state().has_position);
  EXPECT_EQ(obs.state().z_hat, Eigen::Vector2d::Zero());
  const HeadingObserverState before = obs.state();
  obs.update(0.0, {3.1, 4.0}, {1.0, 0.0});
  obs.update(0.01, {std::nan(""), 4.0}, {1.0, 0.0});
  obs.update(0.01, {3.1, 4.0}, {std::numeric_limits<double>::infinity(), 0.0});
  EXPECT_EQ(obs.state().position, before.position);
  EXPECT_EQ(obs.state().z_hat, before.z_hat);
  // v = 0 (robot stopped): finite, estimate held and rotated only.
  obs.reset({0.6, 0.8}, {0.0, 0.0});
  obs.update(0.01, {0.0, 0.0}, {0.0, 1.0});
  EXPECT_TRUE(obs.state().z_hat.allFinite());
  EXPECT_NEAR(obs.state().z_hat.norm(), 1.0, 1e-12);
}

TEST(HeadingObserver, ValidationNamesL) {
  for (double L : {0.0, -1.0, std::nan("")}) {
    try {
      HeadingObserver obs({L});
      FAIL() << "no exception for L = " << L;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("L must be"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace plexus::algorithms
