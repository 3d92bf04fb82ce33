// Properties of the 6-D VDC algebra (paper 004, eqs. (2)-(3), (7)-(8)).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "arm_test_helpers.hpp"
#include "plexus/algorithms/arm/spatial.hpp"

namespace plexus::algorithms::spatial {
namespace {

Vector6 random6(Rng& rng) {
  Vector6 v;
  for (int i = 0; i < 6; ++i) v(i) = rng.uniform(-2.0, 2.0);
  return v;
}

Transform random_transform(Rng& rng) {
  Transform t;
  t.rotation =
      Eigen::AngleAxisd(rng.uniform(-3, 3), Eigen::Vector3d(rng.uniform(-1, 1), rng.uniform(-1, 1), 1).normalized())
          .toRotationMatrix();
  t.origin = Eigen::Vector3d(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
  return t;
}

Vector13 random_theta(Rng& rng) {
  return link_parameters(rng.uniform(1, 5),
                         Eigen::Vector3d(rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3)),
                         Eigen::Vector3d(rng.uniform(0.1, 0.2), rng.uniform(0.1, 0.2), rng.uniform(0.1, 0.2)));
}

TEST(Spatial, TransformsConservePowerAndMatchTheMatrixForm) {
  Rng rng(1);
  for (int trial = 0; trial < 50; ++trial) {
    const Transform t = random_transform(rng);
    const Vector6 va = random6(rng), fb = random6(rng);
    const Vector6 vb = velocity_to_child(t, va), fa = force_to_parent(t, fb);
    EXPECT_NEAR(va.dot(fa), vb.dot(fb), 1e-12);                            // virtual power is frame independent
    EXPECT_TRUE(vb.isApprox(force_transform(t).transpose() * va, 1e-12));  // eq. (2)
    EXPECT_TRUE(fa.isApprox(force_transform(t) * fb, 1e-12));              // eq. (3)
  }
}

TEST(Spatial, InertiaRegressorIsLinearInTheParameters) {
  Rng rng(2);
  for (int trial = 0; trial < 50; ++trial) {
    const Vector13 th = random_theta(rng);
    const Vector6 x = random6(rng);
    EXPECT_TRUE((inertia_regressor(x) * th).isApprox(spatial_inertia(th) * x, 1e-12));
    const Matrix6 m = spatial_inertia(th);
    EXPECT_TRUE(m.isApprox(m.transpose(), 1e-14));
    EXPECT_GT(Eigen::SelfAdjointEigenSolver<Matrix6>(m).eigenvalues().minCoeff(), 0.0);
  }
}

TEST(Spatial, RegressorMatchesNewtonEulerAndCoriolisIsSkew) {
  Rng rng(3);
  for (int trial = 0; trial < 50; ++trial) {
    const Vector13 th = random_theta(rng);
    const Matrix6 m = spatial_inertia(th);
    const Vector6 v = random6(rng), vr = random6(rng), dvr = random6(rng);
    const Eigen::Vector3d g(rng.uniform(-10, 10), rng.uniform(-10, 10), rng.uniform(-10, 10));
    // C(V) = crf(V) M + M crm(V), built column by column from the cross products.
    Matrix6 crm, crf;
    for (int c = 0; c < 6; ++c) {
      crm.col(c) = cross_motion(v, Vector6::Unit(c));
      crf.col(c) = cross_force(v, Vector6::Unit(c));
    }
    const Matrix6 c = crf * m + m * crm;
    EXPECT_TRUE((c + c.transpose()).isZero(1e-12));  // skew: (Vr - V)^T C (Vr - V) = 0
    EXPECT_TRUE(crf.isApprox(-crm.transpose(), 1e-14));
    Vector6 gvec = Vector6::Zero();
    gvec.head<3>() = -g;
    const Vector6 expected = m * dvr + c * vr + m * gvec;  // eq. (8) with G = M [-g; 0]
    EXPECT_TRUE((link_regressor(dvr, vr, v, g) * th).isApprox(expected, 1e-11));
    // C(V) V is the Newton-Euler velocity term crf(V) M V.
    EXPECT_TRUE((c * v).isApprox(cross_force(v, m * v), 1e-11));
  }
}

}  // namespace
}  // namespace plexus::algorithms::spatial
