#include "plexus/algorithms/core/ekf.hpp"

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
using V1 = Eigen::Matrix<double, 1, 1>;

using testing::rel;

// With a linear model the EKF is the Kalman filter, in both covariance update forms,
// through both the callable and the pre-evaluated interfaces.
TEST(Ekf, EqualsKalmanFilterOnLinearGaussianProblem) {
  for (const bool joseph : {true, false}) {
    Rng rng(2);
    const Mat3 A = Mat3::Identity() + random_matrix<3, 3>(rng, 0.1);
    const Vec3 b = random_matrix<3, 1>(rng);
    const Mat3 Q = random_spd<3>(rng, 0.1);
    const Eigen::Matrix<double, 2, 3> H = random_matrix<2, 3>(rng);
    const Mat2 R = random_spd<2>(rng, 0.3);
    const Vec3 x0 = random_matrix<3, 1>(rng);
    const Mat3 P0 = random_spd<3>(rng);
    LinearKalman<3> kf{x0, P0};
    EkfOptions o;
    o.joseph_form = joseph;
    ExtendedKalmanFilter<3> a(o), c(o);
    a.reset(x0, P0);
    c.reset(x0, P0);
    for (int k = 0; k < 50; ++k) {
      kf.predict(A, b, Q);
      ASSERT_TRUE(a.predict(
          [&](const Vec3& x, Mat3& F) -> Vec3 {
            F = A;
            return A * x + b;
          },
          Q));
      ASSERT_TRUE(c.predict(A * c.state() + b, A, Q));
      const Vec2 z = random_matrix<2, 1>(rng, 2.0);
      kf.update<2>(z, H, R);
      ASSERT_TRUE(a.update<2>(
          z,
          [&](const Vec3& x, Eigen::Matrix<double, 2, 3>& Hx) -> Vec2 {
            Hx = H;
            return H * x;
          },
          R));
      ASSERT_TRUE(c.update<2>(z, H * c.state(), H, R));
      ASSERT_LT(rel(a.state(), kf.x), 1e-10) << k;
      ASSERT_LT(rel(a.covariance(), kf.P), 1e-10) << k;
      ASSERT_EQ(a.state(), c.state());
      ASSERT_EQ(a.covariance(), c.covariance());
    }
    // NIS of the last update: r^T S^-1 r, S from the prior (recomputed by the reference).
    EXPECT_GT(a.last_nis(), 0.0);
  }
}

// The Joseph form keeps P SPD with a near-perfect sensor where the short form loses it.
// The structured forms (random-walk rows of F, a direct measurement of consecutive states)
// compute what the general forms compute, in both covariance update forms; only rounding
// may differ.
TEST(Ekf, StructuredPredictAndUpdateEqualTheGeneralForms) {
  plexus::algorithms::Rng rng(11);
  for (const bool joseph : {true, false}) {
    for (int trial = 0; trial < 20; ++trial) {
      using Vec6 = Eigen::Matrix<double, 6, 1>;
      using Mat6 = Eigen::Matrix<double, 6, 6>;
      ExtendedKalmanFilter<6> general({.angular_states = 1u << 2, .joseph_form = joseph});
      ExtendedKalmanFilter<6> structured({.angular_states = 1u << 2, .joseph_form = joseph});
      const Vec6 x0 = random_matrix<6, 1>(rng);
      const Mat6 P0 = random_spd<6>(rng, 0.3);
      general.reset(x0, P0);
      structured.reset(x0, P0);
      const Eigen::Matrix<double, 3, 6> F_top = random_matrix<3, 6>(rng, 0.5);
      Mat6 F = Mat6::Identity();
      F.topRows<3>() = F_top;
      const Vec6 x_pred = random_matrix<6, 1>(rng);
      const Vec6 q = random_matrix<6, 1>(rng).cwiseAbs() * 0.01;
      const Mat6 Q = q.asDiagonal();
      ASSERT_TRUE(general.predict(x_pred, F, Q));
      ASSERT_TRUE(structured.predict_partial<3>(x_pred, F_top, q));
      EXPECT_LT(rel(structured.state(), general.state()), 1e-14);
      EXPECT_LT(rel(structured.covariance(), general.covariance()), 1e-12) << "prediction, trial " << trial;
      ExtendedKalmanFilter<6> full_q = structured;
      full_q.reset(x0, P0);
      ASSERT_TRUE(full_q.predict_partial<3>(x_pred, F_top, Q));
      EXPECT_LT(rel(full_q.covariance(), general.covariance()), 1e-12);

      // z measures states 1..3 (the heading, state 2, is an angle).
      const Vec3 z = random_matrix<3, 1>(rng) + Vec3(0, 3.0, 0);  // a residual that needs wrapping
      const Mat3 R = random_spd<3>(rng, 0.1);
      Eigen::Matrix<double, 3, 6> H = Eigen::Matrix<double, 3, 6>::Zero();
      H.middleCols<3>(1).setIdentity();
      const Vec3 z_pred = general.state().segment<3>(1);
      ASSERT_TRUE(general.update<3>(z, z_pred, H, R, 1u << 1));
      ASSERT_TRUE(structured.update_segment<3>(z, 1, R, 1u << 1));
      EXPECT_LT(rel(structured.state(), general.state()), 1e-12) << "update, trial " << trial;
      EXPECT_LT(rel(structured.covariance(), general.covariance()), 1e-12) << "update, trial " << trial;
      EXPECT_NEAR(structured.last_nis(), general.last_nis(), 1e-10 * (1.0 + general.last_nis()));
      EXPECT_NEAR(structured.last_log_det_s(), general.last_log_det_s(), 1e-10);
    }
  }
  ExtendedKalmanFilter<6> ekf;
  EXPECT_THROW(ekf.update_segment<3>(Vec3::Zero(), 4, Mat3::Identity()), std::invalid_argument);
  EXPECT_FALSE(ekf.update_segment<3>(Vec3(NAN, 0, 0), 0, Mat3::Identity()));
}

TEST(Ekf, JosephFormKeepsCovariancePositiveDefinite) {
  ExtendedKalmanFilter<2> ekf;
  ekf.reset(Vec2(0, 0), Vec2(1e6, 1e-6).asDiagonal());
  const Eigen::Matrix<double, 1, 2> H(1.0, 1.0);
  for (int k = 0; k < 100; ++k) {
    ASSERT_TRUE(ekf.predict(ekf.state(), Mat2::Identity(), Mat2::Identity() * 1e-14));
    ASSERT_TRUE(ekf.update<1>(V1(0.0), V1(H * ekf.state()), H, V1(1e-12)));
    ASSERT_TRUE(is_symmetric_positive_definite<2>(ekf.covariance())) << k;
  }
}

// The covariance guard floors the eigenvalues: a rank-deficient predicted covariance
// (F singular, Q = 0) is repaired and counted.
TEST(Ekf, CovarianceGuardRepairsRankDeficiency) {
  EkfOptions o;
  o.min_eigenvalue = 1e-9;
  ExtendedKalmanFilter<2> ekf(o);
  ekf.reset(Vec2(1, 1), Mat2::Identity());
  Mat2 F;
  F << 1, 1, 1, 1;  // rank 1
  ASSERT_TRUE(ekf.predict(F * ekf.state(), F, Mat2::Zero()));
  EXPECT_EQ(ekf.guard_repairs(), 1);
  Eigen::SelfAdjointEigenSolver<Mat2> es(ekf.covariance());
  EXPECT_GE(es.eigenvalues().minCoeff(), 1e-9 * (1 - 1e-6));
  EXPECT_NEAR(es.eigenvalues().maxCoeff(), 4.0, 1e-9);
}

TEST(Ekf, AngularResidualAndStateWrap) {
  EkfOptions o;
  o.angular_states = 0b01;
  ExtendedKalmanFilter<2> ekf(o);
  const double pi = std::numbers::pi;
  ekf.reset(Vec2(pi - 0.01, 0.0), Vec2(0.01, 0.01).asDiagonal());
  const Eigen::Matrix<double, 1, 2> H(1.0, 0.0);
  // Measured -pi + 0.01 (0.02 rad away across the cut): the estimate moves across, not back.
  ASSERT_TRUE(ekf.update<1>(V1(-pi + 0.01), V1(ekf.state()(0)), H, V1(0.01), 0b1));
  EXPECT_NEAR(ekf.state()(0), pi, 1e-9);
  ASSERT_TRUE(ekf.predict(Vec2(ekf.state()(0) + 0.5, 0), Mat2::Identity(), Mat2::Zero()));
  EXPECT_NEAR(ekf.state()(0), -pi + 0.5, 1e-9);
}

TEST(Ekf, ResetCovarianceReplacesPOnly) {
  ExtendedKalmanFilter<2> ekf;
  ekf.reset(Vec2(1, 2), Mat2::Identity());
  ekf.reset_covariance(Mat2::Identity() * 4.0);
  EXPECT_EQ(ekf.state(), Vec2(1, 2));
  EXPECT_EQ(ekf.covariance(), Mat2::Identity() * 4.0);
}

TEST(Ekf, RejectsNonFiniteInputsAndKeepsEstimate) {
  ExtendedKalmanFilter<2> ekf;
  ekf.reset(Vec2(1, 2), Mat2::Identity());
  const Eigen::Matrix<double, 1, 2> H(1.0, 0.0);
  EXPECT_FALSE(ekf.predict(Vec2(NAN, 0), Mat2::Identity(), Mat2::Zero()));
  EXPECT_FALSE(ekf.predict(Vec2(0, 0), Mat2::Constant(INFINITY), Mat2::Zero()));
  EXPECT_FALSE(ekf.update<1>(V1(NAN), V1(1.0), H, V1(1.0)));
  EXPECT_FALSE(ekf.update<1>(V1(1.0), V1(1.0), H, V1(-3.0)));  // S = 1 - 3 < 0
  EXPECT_EQ(ekf.state(), Vec2(1, 2));
  EXPECT_EQ(ekf.covariance(), Mat2::Identity());
}

TEST(Ekf, EveryValidationError) {
  EkfOptions o;
  o.min_eigenvalue = -1.0;
  EXPECT_EQ(error_of([&] { ExtendedKalmanFilter<2> f(o); }), "ekf: min_eigenvalue must be finite and > 0 (got -1)");
  o.min_eigenvalue = INFINITY;
  EXPECT_EQ(error_of([&] { ExtendedKalmanFilter<2> f(o); }), "ekf: min_eigenvalue must be finite and > 0 (got inf)");
  ExtendedKalmanFilter<2> f;
  EXPECT_EQ(error_of([&] { f.reset(Vec2(INFINITY, 0), Mat2::Identity()); }), "ekf: x0 must be finite");
  EXPECT_EQ(error_of([&] { f.reset(Vec2(0, 0), Mat2::Zero()); }),
            "ekf: covariance must be finite, symmetric and positive definite");
  Mat2 asym = Mat2::Identity();
  asym(1, 0) = 0.3;
  EXPECT_EQ(error_of([&] { f.reset_covariance(asym); }),
            "ekf: covariance must be finite, symmetric and positive definite");
  EXPECT_EQ(error_of([&] { f.reset_covariance(Mat2::Constant(NAN)); }),
            "ekf: covariance must be finite, symmetric and positive definite");
}

}  // namespace
}  // namespace plexus::algorithms
