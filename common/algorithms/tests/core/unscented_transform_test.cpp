#include "plexus/algorithms/core/unscented_transform.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "plexus/algorithms/core/random.hpp"

namespace plexus::algorithms {
namespace {

template <int L>
Eigen::Matrix<double, L, L> random_covariance(Rng& rng) {
  Eigen::Matrix<double, L, L> A;
  for (int i = 0; i < L; ++i)
    for (int j = 0; j < L; ++j) A(i, j) = rng.normal();
  return A * A.transpose() + 0.1 * Eigen::Matrix<double, L, L>::Identity();
}

template <int L>
std::string weights_error(const UnscentedParams& p) {
  try {
    UnscentedWeights<L>::make(p, "ut");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(UnscentedWeights, SumToOneAndMatchTheScaledFormulas) {
  for (const UnscentedParams p : {UnscentedParams{1.0, 2.0, 0.0}, UnscentedParams{1e-3, 2.0, 0.0},
                                  UnscentedParams{0.5, 0.0, -4.0}, UnscentedParams{1.0, 2.0, -4.0}}) {
    const auto w = UnscentedWeights<7>::make(p, "ut");
    EXPECT_NEAR(w.wm0 + 14 * w.wi, 1.0, 1e-12 * (1.0 + std::abs(w.wm0))) << p.alpha;
    EXPECT_NEAR(w.wc0 - w.wm0, 1.0 - p.alpha * p.alpha + p.beta, 1e-12 * (1.0 + std::abs(w.wm0)));
    EXPECT_NEAR(w.gamma * w.gamma, p.alpha * p.alpha * (7 + p.kappa), 1e-12);
  }
  EXPECT_EQ(UnscentedWeights<3>::kPoints, 7);   // paper 002: additive form, 7 points
  EXPECT_EQ(UnscentedWeights<7>::kPoints, 15);  // paper 002: augmented form, 15 points
}

TEST(UnscentedWeights, EveryValidationError) {
  EXPECT_EQ(weights_error<3>({0.0, 2.0, 0.0}), "ut: alpha must be finite and > 0 (got 0)");
  EXPECT_EQ(weights_error<3>({-1.0, 2.0, 0.0}), "ut: alpha must be finite and > 0 (got -1)");
  EXPECT_EQ(weights_error<3>({NAN, 2.0, 0.0}), "ut: alpha must be finite and > 0 (got nan)");
  EXPECT_EQ(weights_error<3>({1.0, INFINITY, 0.0}), "ut: beta must be finite (got inf)");
  EXPECT_EQ(weights_error<3>({1.0, 2.0, NAN}), "ut: kappa must be finite (got nan)");
  EXPECT_EQ(weights_error<3>({1.0, 2.0, -3.0}), "ut: kappa must be > -L = -3 (L + kappa > 0) (got -3)");
  EXPECT_EQ(weights_error<3>({1.0, 2.0, -2.5}), "");
}

// Sigma points reproduce mean and covariance exactly, and affine maps are transformed
// exactly: y = A x + b has mean A x + b, covariance A P A^T, cross-covariance P A^T.
TEST(UnscentedTransform, ExactForAffineMaps) {
  Rng rng(7);
  for (const UnscentedParams p :
       {UnscentedParams{1.0, 2.0, 0.0}, UnscentedParams{1e-2, 2.0, 0.0}, UnscentedParams{0.3, 1.0, 2.0}}) {
    for (int trial = 0; trial < 20; ++trial) {
      const auto w = UnscentedWeights<5>::make(p, "ut");
      Eigen::Matrix<double, 5, 1> x;
      for (int i = 0; i < 5; ++i) x(i) = rng.normal(0.0, 3.0);
      const Eigen::Matrix<double, 5, 5> P = random_covariance<5>(rng);
      Eigen::Matrix<double, 3, 5> A;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 5; ++j) A(i, j) = rng.normal();
      const Eigen::Vector3d b(rng.normal(), rng.normal(), rng.normal());

      // The points themselves: weighted mean and covariance are (x, P).
      Eigen::Matrix<double, 5, 11> X;
      ASSERT_TRUE(make_sigma_points<5>(x, P, w, X));
      const Eigen::Matrix<double, 5, 1> mx = sigma_mean<5, 5>(X, w);
      Eigen::Matrix<double, 5, 5> Px = Eigen::Matrix<double, 5, 5>::Zero();
      for (int i = 0; i < 11; ++i) Px += w.cov_weight(i) * (X.col(i) - mx) * (X.col(i) - mx).transpose();
      const double tol = 1e-9 * (1.0 + 1.0 / (p.alpha * p.alpha));
      EXPECT_LT((mx - x).norm(), tol);
      EXPECT_LT((Px - P).norm(), tol * P.norm());

      UnscentedTransformResult<5, 3> out;
      ASSERT_TRUE((unscented_transform<5, 3>(
          x, P, w, [&](const Eigen::Matrix<double, 5, 1>& v) -> Eigen::Vector3d { return A * v + b; }, out)));
      EXPECT_LT((out.mean - (A * x + b)).norm(), tol * (1 + x.norm()));
      EXPECT_LT((out.cov - A * P * A.transpose()).norm(), tol * (A * P * A.transpose()).norm());
      EXPECT_LT((out.cross_cov - P * A.transpose()).norm(), tol * (P * A.transpose()).norm());
    }
  }
}

// For a quadratic map the mean is exact (second order): E[x^2] = m^2 + s^2.
TEST(UnscentedTransform, MeanExactToSecondOrder) {
  const auto w = UnscentedWeights<1>::make({0.5, 2.0, 0.0}, "ut");
  UnscentedTransformResult<1, 1> out;
  const Eigen::Matrix<double, 1, 1> m(1.5), P(0.25);
  ASSERT_TRUE((unscented_transform<1, 1>(
      m, P, w, [](const Eigen::Matrix<double, 1, 1>& v) { return Eigen::Matrix<double, 1, 1>(v(0) * v(0)); }, out)));
  EXPECT_NEAR(out.mean(0), 1.5 * 1.5 + 0.25, 1e-12);
}

// A singular covariance (a zero block, as with a zero noise term) still has sigma points.
TEST(UnscentedTransform, SemiDefiniteCovarianceUsesEigenSquareRoot) {
  const auto w = UnscentedWeights<3>::make({}, "ut");
  Eigen::Matrix3d P = Eigen::Matrix3d::Zero();
  P(0, 0) = 2.0;
  Eigen::Matrix<double, 3, 7> X;
  ASSERT_TRUE(make_sigma_points<3>(Eigen::Vector3d(1, 2, 3), P, w, X));
  Eigen::Matrix3d Px = Eigen::Matrix3d::Zero();
  for (int i = 0; i < 7; ++i)
    Px += w.cov_weight(i) * (X.col(i) - Eigen::Vector3d(1, 2, 3)) * (X.col(i) - Eigen::Vector3d(1, 2, 3)).transpose();
  EXPECT_LT((Px - P).norm(), 1e-12);
  P(1, 1) = NAN;
  EXPECT_FALSE(make_sigma_points<3>(Eigen::Vector3d(1, 2, 3), P, w, X));
}

// An angular component whose points straddle +-pi averages on the circle.
TEST(UnscentedTransform, AngularMeanAcrossPi) {
  const auto w = UnscentedWeights<1>::make({}, "ut");
  const Eigen::Matrix<double, 1, 1> m(std::numbers::pi - 0.01), P(0.04);
  UnscentedTransformResult<1, 1> out;
  auto wrap = [](const Eigen::Matrix<double, 1, 1>& v) { return Eigen::Matrix<double, 1, 1>(wrap_angle(v(0))); };
  ASSERT_TRUE((unscented_transform<1, 1>(m, P, w, wrap, out, 1u, 1u)));
  EXPECT_NEAR(wrap_angle(out.mean(0) - m(0)), 0.0, 1e-12);
  EXPECT_NEAR(out.cov(0, 0), 0.04, 1e-12);
  // Without the mask the same points average to nonsense near 0.
  ASSERT_TRUE((unscented_transform<1, 1>(m, P, w, wrap, out)));
  EXPECT_GT(std::abs(wrap_angle(out.mean(0) - m(0))), 1.0);
}

}  // namespace
}  // namespace plexus::algorithms
