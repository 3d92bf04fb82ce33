#include "plexus/algorithms/core/ukf.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "kalman_reference.hpp"

namespace plexus::algorithms {
namespace {

using testing::error_of;
using testing::LinearKalman;
using testing::random_matrix;
using testing::random_spd;
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Vec2 = Eigen::Vector2d;
using Mat2 = Eigen::Matrix2d;

using testing::rel;

// Both UKF forms equal the Kalman filter on a linear-Gaussian problem, step by step,
// for several sigma-point scalings (paper 002's alpha range included).
TEST(Ukf, EqualsKalmanFilterOnLinearGaussianProblem) {
  for (const UnscentedParams p :
       {UnscentedParams{1.0, 2.0, 0.0}, UnscentedParams{0.1, 2.0, 0.0}, UnscentedParams{0.5, 2.0, 1.0}}) {
    Rng rng(11);
    const Mat3 A = Mat3::Identity() + random_matrix<3, 3>(rng, 0.1);
    const Vec3 b = random_matrix<3, 1>(rng);
    const Mat3 Q = random_spd<3>(rng, 0.1);
    const Eigen::Matrix<double, 2, 3> H = random_matrix<2, 3>(rng);
    const Mat2 R = random_spd<2>(rng, 0.3);
    const Vec3 x0 = random_matrix<3, 1>(rng);
    const Mat3 P0 = random_spd<3>(rng);
    LinearKalman<3> kf{x0, P0};
    UkfOptions o;
    o.sigma = p;
    AdditiveUkf<3> add(o);
    AugmentedUkf<3, 3, 2> aug(o);
    add.reset(x0, P0);
    aug.reset(x0, P0);
    for (int k = 0; k < 50; ++k) {
      kf.predict(A, b, Q);
      ASSERT_TRUE(add.predict([&](const Vec3& x) -> Vec3 { return A * x + b; }, Q));
      ASSERT_TRUE(aug.predict([&](const Vec3& x, const Vec3& w) -> Vec3 { return A * x + b + w; }, Q, R));
      const Vec2 z = random_matrix<2, 1>(rng, 2.0);
      kf.update<2>(z, H, R);
      ASSERT_TRUE(add.update<2>(
          z, [&](const Vec3& x) -> Vec2 { return H * x; }, R));
      ASSERT_TRUE(aug.update<2>(z, [&](const Vec3& x, const Vec2& v) -> Vec2 { return H * x + v; }));
      const double tol = 1e-9 / (p.alpha * p.alpha);
      ASSERT_LT(rel(add.state(), kf.x), tol) << "alpha " << p.alpha << " k " << k;
      ASSERT_LT(rel(add.covariance(), kf.P), tol) << "alpha " << p.alpha << " k " << k;
      ASSERT_LT(rel(aug.state(), kf.x), tol) << "alpha " << p.alpha << " k " << k;
      ASSERT_LT(rel(aug.covariance(), kf.P), tol) << "alpha " << p.alpha << " k " << k;
    }
    EXPECT_EQ(add.guard_repairs(), 0);
    EXPECT_EQ(aug.guard_repairs(), 0);
  }
}

// Nonlinear process with additive noise, x+ = g(x) + w: the augmented prediction equals
// the additive one exactly when both use the same spread alpha^2 (L + kappa) (the extra
// noise points then contribute exactly Q). The full cycles agree closely, not exactly:
// the additive form redraws the points before the update, the augmented form reuses them.
TEST(Ukf, AugmentedAndAdditiveAgreeWhenNoiseIsAdditive) {
  auto g = [](const Vec3& x) -> Vec3 {
    return {x(0) + 0.01 * x(1), x(1) + 0.01 * (9.8 * std::sin(x(0)) - 0.3 * x(1) * x(1)), 0.99 * x(2)};
  };
  const Mat3 Q = Vec3(1e-5, 4e-4, 1e-6).asDiagonal();
  const Eigen::Matrix<double, 1, 1> R(1e-4);
  UkfOptions oa, ob;
  oa.sigma = {0.8, 2.0, 0.0};  // L = 3 + 3 + 1 = 7: alpha^2 (7 + 0)
  ob.sigma = {0.8, 2.0, 4.0};  // L = 3: alpha^2 (3 + 4), same spread
  AugmentedUkf<3, 3, 1> aug(oa);
  AdditiveUkf<3> add(ob);
  const Vec3 x0(0.2, -0.5, 0.01);
  const Mat3 P0 = Vec3(0.02, 0.1, 0.001).asDiagonal();
  aug.reset(x0, P0);
  add.reset(x0, P0);
  ASSERT_TRUE(aug.predict([&](const Vec3& x, const Vec3& w) -> Vec3 { return g(x) + w; }, Q, R));
  ASSERT_TRUE(add.predict(g, Q));
  EXPECT_LT(rel(aug.state(), add.state()), 1e-12);
  EXPECT_LT(rel(aug.covariance(), add.covariance()), 1e-12);

  // Full cycles with a nonlinear measurement: close agreement.
  auto h = [](const Vec3& x) { return Eigen::Matrix<double, 1, 1>(std::sin(x(0)) + x(2)); };
  Rng rng(3);
  for (int k = 0; k < 200; ++k) {
    const Eigen::Matrix<double, 1, 1> z(std::sin(0.2 + 0.001 * k) + rng.normal(0.0, 0.01));
    ASSERT_TRUE(aug.update<1>(
        z,
        [&](const Vec3& x, const Eigen::Matrix<double, 1, 1>& v) -> Eigen::Matrix<double, 1, 1> { return h(x) + v; }));
    ASSERT_TRUE(add.update<1>(z, h, R));
    ASSERT_TRUE(aug.predict([&](const Vec3& x, const Vec3& w) -> Vec3 { return g(x) + w; }, Q, R));
    ASSERT_TRUE(add.predict(g, Q));
  }
  EXPECT_LT((aug.state() - add.state()).cwiseQuotient(add.covariance().diagonal().cwiseSqrt()).norm(), 0.05);
  EXPECT_LT(rel(aug.covariance(), add.covariance()), 0.05);
}

// Non-additive noise enters through f: for a multiplicative process noise x+ = x (1 + w)
// the true variance is P + m^2 Q + P Q. The symmetric sigma set is exact to second order:
// it gets P + m^2 Q and misses the fourth-order product term P Q (points lie on the axes).
TEST(Ukf, AugmentedHandlesNonAdditiveNoise) {
  AugmentedUkf<1, 1, 1> ukf;
  using V1 = Eigen::Matrix<double, 1, 1>;
  ukf.reset(V1(2.0), V1(0.1));
  ASSERT_TRUE(ukf.predict([](const V1& x, const V1& w) { return V1(x(0) * (1.0 + w(0))); }, V1(0.01), V1(1.0)));
  EXPECT_NEAR(ukf.state()(0), 2.0, 1e-12);
  EXPECT_NEAR(ukf.covariance()(0, 0), 0.1 + 4.0 * 0.01, 1e-12);
}

// Covariance stays symmetric positive definite over a long nonlinear run with a
// near-perfect sensor and a small alpha (negative W_0): the guard may fire, P never fails.
TEST(Ukf, CovarianceStaysSymmetricPositiveDefinite) {
  UkfOptions o;
  o.sigma = {1e-3, 2.0, 0.0};
  AdditiveUkf<2> ukf(o);
  ukf.reset(Vec2(1.0, 0.0), Mat2::Identity());
  Rng rng(5);
  for (int k = 0; k < 2000; ++k) {
    ASSERT_TRUE(ukf.predict(
        [](const Vec2& x) -> Vec2 {
          return {x(0) + 0.01 * x(1), x(1) - 0.01 * std::sin(x(0))};
        },
        Vec2(1e-10, 1e-8).asDiagonal()));
    const Eigen::Matrix<double, 1, 1> z(rng.normal(0.0, 1e-6));
    ASSERT_TRUE(ukf.update<1>(
        z, [](const Vec2& x) { return Eigen::Matrix<double, 1, 1>(x(0)); }, Eigen::Matrix<double, 1, 1>(1e-12)));
    const Mat2& P = ukf.covariance();
    ASSERT_EQ(P, P.transpose());
    ASSERT_TRUE(is_symmetric_positive_definite<2>(P)) << k;
  }
}

// An angular state whose points straddle +-pi: mean and residuals on the circle.
TEST(Ukf, AngularStateAcrossPi) {
  UkfOptions o;
  o.angular_states = 0b1;
  AdditiveUkf<2> ukf(o);
  const double pi = std::numbers::pi;
  ukf.reset(Vec2(pi - 0.02, 0.5), Vec2(0.01, 0.01).asDiagonal());
  ASSERT_TRUE(ukf.predict([](const Vec2& x) -> Vec2 { return {x(0) + 0.1 * x(1), x(1)}; }, Mat2::Identity() * 1e-6));
  EXPECT_NEAR(ukf.state()(0), -pi + 0.03, 1e-9);
  EXPECT_LT(ukf.covariance()(0, 0), 0.02);
  // Measuring the angle (wrapped) near -pi + 0.03 with a reading of pi - 0.01 is a residual of -0.04.
  ASSERT_TRUE(ukf.update<1>(
      Eigen::Matrix<double, 1, 1>(pi - 0.01), [](const Vec2& x) { return Eigen::Matrix<double, 1, 1>(x(0)); },
      Eigen::Matrix<double, 1, 1>(1e-4), 0b1));
  EXPECT_NEAR(ukf.state()(0), pi - 0.0099, 2e-3);
}

TEST(Ukf, AugmentedUpdateNeedsAPredict) {
  AugmentedUkf<1, 1, 1> ukf;
  using V1 = Eigen::Matrix<double, 1, 1>;
  auto h = [](const V1& x, const V1& v) { return V1(x(0) + v(0)); };
  EXPECT_FALSE(ukf.update<1>(V1(1.0), h));
  ASSERT_TRUE(ukf.predict([](const V1& x, const V1& w) { return V1(x(0) + w(0)); }, V1(0.1), V1(0.1)));
  EXPECT_TRUE(ukf.update<1>(V1(1.0), h));
  EXPECT_FALSE(ukf.update<1>(V1(1.0), h));  // the points are consumed
}

TEST(Ukf, RejectsNonFiniteInputsAndKeepsEstimate) {
  AdditiveUkf<2> ukf;
  ukf.reset(Vec2(1, 2), Mat2::Identity());
  EXPECT_FALSE(ukf.predict([](const Vec2& x) -> Vec2 { return x; }, Mat2::Constant(NAN)));
  EXPECT_FALSE(ukf.predict([](const Vec2&) -> Vec2 { return Vec2(NAN, 0); }, Mat2::Identity()));
  const auto h = [](const Vec2& x) { return Eigen::Matrix<double, 1, 1>(x(0)); };
  EXPECT_FALSE(ukf.update<1>(Eigen::Matrix<double, 1, 1>(NAN), h, Eigen::Matrix<double, 1, 1>(1.0)));
  EXPECT_FALSE(ukf.update<1>(Eigen::Matrix<double, 1, 1>(1.0), h, Eigen::Matrix<double, 1, 1>(-2.0)));  // P_zz < 0
  EXPECT_EQ(ukf.state(), Vec2(1, 2));
  EXPECT_EQ(ukf.covariance(), Mat2::Identity());
}

TEST(Ukf, EveryValidationError) {
  UkfOptions o;
  o.sigma.alpha = 0.0;
  EXPECT_EQ(error_of([&] { AdditiveUkf<3> f(o); }), "additive_ukf: alpha must be finite and > 0 (got 0)");
  EXPECT_EQ(error_of([&] { AugmentedUkf<3, 3, 1> f(o); }), "augmented_ukf: alpha must be finite and > 0 (got 0)");
  o = {};
  o.sigma.beta = NAN;
  EXPECT_EQ(error_of([&] { AdditiveUkf<3> f(o); }), "additive_ukf: beta must be finite (got nan)");
  o = {};
  o.sigma.kappa = -3.0;  // fine for L = 7, not for L = 3
  EXPECT_EQ(error_of([&] { AdditiveUkf<3> f(o); }), "additive_ukf: kappa must be > -L = -3 (L + kappa > 0) (got -3)");
  EXPECT_EQ(error_of([&] { AugmentedUkf<3, 3, 1> f(o); }), "");
  o = {};
  o.min_eigenvalue = 0.0;
  EXPECT_EQ(error_of([&] { AdditiveUkf<3> f(o); }), "additive_ukf: min_eigenvalue must be finite and > 0 (got 0)");
  AdditiveUkf<2> f;
  EXPECT_EQ(error_of([&] { f.reset(Vec2(NAN, 0), Mat2::Identity()); }), "additive_ukf: x0 must be finite");
  EXPECT_EQ(error_of([&] { f.reset(Vec2(0, 0), -Mat2::Identity()); }),
            "additive_ukf: covariance must be finite, symmetric and positive definite");
  Mat2 asym = Mat2::Identity();
  asym(0, 1) = 0.5;
  EXPECT_EQ(error_of([&] { f.reset_covariance(asym); }),
            "additive_ukf: covariance must be finite, symmetric and positive definite");
  AugmentedUkf<2, 1, 1> g;
  EXPECT_EQ(error_of([&] { g.reset_covariance(Mat2::Zero()); }),
            "augmented_ukf: covariance must be finite, symmetric and positive definite");
}

}  // namespace
}  // namespace plexus::algorithms
