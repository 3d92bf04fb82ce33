// The filter steps must not allocate: this binary counts every heap allocation (operator new
// and malloc, support/count_allocations.hpp) and checks the count around predict/update of
// all three filters. The counter itself is checked first: a counter that missed a way onto
// the heap would let every NoAllocation test pass.
#include <gtest/gtest.h>

#include "../support/count_allocations.hpp"

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>

#include "plexus/algorithms/core/ekf.hpp"
#include "plexus/algorithms/core/ukf.hpp"

namespace plexus::algorithms {
namespace {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using V1 = Eigen::Matrix<double, 1, 1>;

TEST(NoAllocation, TheCounterSeesEveryWayOntoTheHeap) {
  // (volatile: the compiler may elide a new/delete pair whose memory nothing reads)
  long before = plexus::test::allocations();
  double* volatile n = new double[8];
  EXPECT_EQ(plexus::test::allocations() - before, 1);  // operator new
  delete[] n;
  before = plexus::test::allocations();
  {
    Eigen::VectorXd v(64);  // Eigen's dynamic storage: aligned malloc
    v.setZero();
    EXPECT_EQ(v.size(), 64);
  }
  EXPECT_EQ(plexus::test::allocations() - before, 1);
  before = plexus::test::allocations();
  void* volatile p = std::calloc(4, 8);
  p = std::realloc(p, 64);
  std::free(p);
  EXPECT_EQ(plexus::test::allocations() - before, 2);  // calloc, realloc
}

TEST(NoAllocation, FilterStepsDoNotAllocate) {
  ExtendedKalmanFilter<3> ekf;
  AdditiveUkf<3> add;
  AugmentedUkf<3, 3, 1> aug;
  const Mat3 Q = Vec3(1e-4, 1e-3, 1e-5).asDiagonal();
  const V1 R(1e-3);
  ekf.reset(Vec3(0.1, 0, 0), Mat3::Identity() * 0.01);
  add.reset(Vec3(0.1, 0, 0), Mat3::Identity() * 0.01);
  aug.reset(Vec3(0.1, 0, 0), Mat3::Identity() * 0.01);
  auto f = [](const Vec3& x) -> Vec3 { return {x(0) + 0.01 * x(1), x(1) + 0.01 * std::sin(x(0)), x(2)}; };
  auto h = [](const Vec3& x) { return V1(x(0) + x(2)); };

  const long before = plexus::test::allocations();
  for (int k = 0; k < 100; ++k) {
    const V1 z(0.1 + 0.001 * k);
    ekf.predict(
        [&](const Vec3& x, Mat3& F) {
          F << 1, 0.01, 0, 0.01 * std::cos(x(0)), 1, 0, 0, 0, 1;
          return f(x);
        },
        Q);
    ekf.update<1>(
        z,
        [&](const Vec3& x, Eigen::Matrix<double, 1, 3>& H) {
          H << 1, 0, 1;
          return h(x);
        },
        R);
    add.predict(f, Q);
    add.update<1>(z, h, R);
    aug.predict([&](const Vec3& x, const Vec3& w) -> Vec3 { return f(x) + w; }, Q, R);
    aug.update<1>(z, [&](const Vec3& x, const V1& v) { return V1(h(x) + v); });
  }
  const long after = plexus::test::allocations();
  EXPECT_EQ(after - before, 0);
  EXPECT_TRUE(ekf.state().allFinite() && add.state().allFinite() && aug.state().allFinite());
}

}  // namespace
}  // namespace plexus::algorithms
