#include "plexus/algorithms/unicycle/velocity_heading_observer.hpp"

#include <gtest/gtest.h>

#include "../support/validation_message.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "plexus/algorithms/unicycle/unicycle_plant.hpp"

namespace plexus::algorithms {
namespace {

struct Case {
  double L2, L4, u1;
  double u2_mean, u2_amp;  // u2(t) = mean + amp sin(0.3 t)
};

class VelocityObserverRate : public ::testing::TestWithParam<Case> {};

// Paper 003, Theorem 1 / eq. (13): |e(t)| <= |e(0)| exp(-min(L2, L4) t) for any u2(t).
// Cases cover L2 = L4, L2 != L4 with |L2 - L4| / 2 above and below |u2| (both branches
// of the closed-form exponential) and a negative speed.
TEST_P(VelocityObserverRate, ErrorNormDecaysAtMinGain) {
  const Case c = GetParam();
  VelocityHeadingObserver obs({c.L2, c.L4});
  UnicycleState s{0.5, -1.0, 0.3};
  obs.reset({-0.2, 0.4}, {s.x, s.y});
  auto error = [&] {
    return (Eigen::Vector2d(c.u1 * std::cos(s.theta), c.u1 * std::sin(s.theta)) - obs.state().z_hat).norm();
  };
  const double e0 = error();
  const double rate = std::min(c.L2, c.L4), h = 0.01;
  for (int k = 1; k <= 1000; ++k) {
    const double u2 = c.u2_mean + c.u2_amp * std::sin(0.3 * (k - 1) * h);
    s = unicycle_step(s, {c.u1, u2}, h);
    obs.update(h, {s.x, s.y}, u2);
    ASSERT_LE(error(), e0 * std::exp(-rate * k * h) * (1 + 1e-9) + 1e-13) << "t = " << k * h;
  }
  EXPECT_LT(error(), 1e-6);
  // eq. (14): theta_hat, u1_hat (u1 < 0 shows up as theta + pi with |u1|).
  const double theta = c.u1 > 0 ? s.theta : s.theta + std::numbers::pi;
  EXPECT_NEAR(wrap_angle(obs.heading() - theta), 0.0, 1e-5);
  EXPECT_NEAR(obs.speed(), std::abs(c.u1), 1e-6);
}

INSTANTIATE_TEST_SUITE_P(PaperAndVariants, VelocityObserverRate,
                         ::testing::Values(Case{2.0, 2.0, 1.0, 1.0, 0.0},  // paper 003, section 5
                                           Case{2.0, 3.0, 0.8, 0.2, 0.5},  // u2 above |L2 - L4| / 2
                                           Case{1.5, 6.0, 1.2, 0.3, 0.2},  // |L2 - L4| / 2 > |u2|
                                           Case{3.0, 2.0, -0.7, -2.0, 1.0}));

TEST(VelocityHeadingObserver, PaperStatesAndHeldPositionVariant) {
  VelocityHeadingObserver obs({2.0, 3.0, ObserverDiscretisation::kHeldPosition});
  obs.reset({0.0, 0.0}, {1.0, 2.0});
  EXPECT_TRUE(obs.z_bar().isApprox(Eigen::Vector2d(-2.0, -6.0)));
  UnicycleState s{1.0, 2.0, 1.0};
  const double h = 0.01;
  for (int k = 0; k < 1000; ++k) {
    s = unicycle_step(s, {1.0, 0.5}, h);
    obs.update(h, {s.x, s.y}, 0.5);
  }
  const Eigen::Vector2d z(std::cos(s.theta), std::sin(s.theta));
  EXPECT_LT((z - obs.state().z_hat).norm(), (3.0 + 0.5) * h);  // O((L + |u2|) h) discretisation bias
  EXPECT_GT((z - obs.state().z_hat).norm(), 1e-6);
}

TEST(VelocityHeadingObserver, ValidationNamesTheGain) {
  auto message = [](double L2, double L4) {
    return testing::invalid_argument_message<VelocityHeadingObserver>(VelocityHeadingObserverParams{L2, L4});
  };
  EXPECT_NE(message(0.0, 1.0).find("L2"), std::string::npos);
  EXPECT_NE(message(1.0, -2.0).find("L4"), std::string::npos);
  EXPECT_NE(message(1.0, -2.0).find("-2"), std::string::npos);
  EXPECT_EQ(message(1.0, 2.0), "");
}

}  // namespace
}  // namespace plexus::algorithms
