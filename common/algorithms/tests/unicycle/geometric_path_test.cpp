#include "plexus/algorithms/unicycle/geometric_path.hpp"

#include <gtest/gtest.h>

#include "../support/validation_message.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "plexus/algorithms/core/random.hpp"

namespace plexus::algorithms {
namespace {

std::vector<GeometricPath> all_shapes() {
  PolynomialPath poly;  // x^3 y - 2 x y^2 + 0.5 y^4 + x - 3 + 0.1 x^2 y^4
  poly.c(3, 1) = 1.0;
  poly.c(1, 2) = -2.0;
  poly.c(0, 4) = 0.5;
  poly.c(1, 0) = 1.0;
  poly.c(0, 0) = -3.0;
  poly.c(2, 4) = 0.1;
  return {GeometricPath(CirclePath{{0.3, -0.2}, 1.5}), GeometricPath(LinePath{{1.0, 2.0}, {0.6, -0.8}}),
          GeometricPath(EllipsePath{{0.5, 0.5}, 3.0, 1.2, 0.7}), GeometricPath(poly)};
}

TEST(GeometricPath, GradientAndHessianMatchFiniteDifferences) {
  Rng rng(11);
  const double eps = 1e-5;
  for (const GeometricPath& path : all_shapes()) {
    for (int i = 0; i < 50; ++i) {
      const Eigen::Vector2d p(rng.uniform(-2, 2), rng.uniform(-2, 2));
      const PathEvaluation e = path.evaluate(p);
      for (int k = 0; k < 2; ++k) {
        const Eigen::Vector2d d = eps * Eigen::Vector2d::Unit(k);
        const PathEvaluation ep = path.evaluate(p + d), em = path.evaluate(p - d);
        const double scale = 1.0 + std::abs(e.h) + e.gradient.norm() + e.hessian.norm();
        EXPECT_NEAR(e.gradient[k], (ep.h - em.h) / (2 * eps), 1e-7 * scale) << path.shape().index();
        EXPECT_TRUE(((ep.gradient - em.gradient) / (2 * eps) - e.hessian.col(k)).norm() < 1e-6 * scale)
            << path.shape().index();
      }
      EXPECT_DOUBLE_EQ(e.hessian(0, 1), e.hessian(1, 0));
    }
  }
}

TEST(GeometricPath, ZeroSetsAreTheIntendedCurves) {
  GeometricPath unit(CirclePath{});
  GeometricPath ellipse(EllipsePath{{1.0, -1.0}, 3.0, 1.0, std::numbers::pi / 2});
  GeometricPath line(LinePath{{0.0, 1.0}, {0.0, 2.0}});
  for (double a = 0; a < 6.3; a += 0.3) {
    EXPECT_NEAR(unit.evaluate({std::cos(a), std::sin(a)}).h, 0.0, 1e-14);
    // phi = pi / 2: the major axis (3) is along y.
    EXPECT_NEAR(ellipse.evaluate({1.0 + std::cos(a), -1.0 + 3.0 * std::sin(a)}).h, 0.0, 1e-12);
    EXPECT_NEAR(line.evaluate({a, 1.0}).h, 0.0, 1e-14);
  }
  EXPECT_NEAR(unit.evaluate({0, 0}).h, -1.0, 0.0);
}

TEST(GeometricPath, ValidationNamesTheParameter) {
  auto message = [](const PathShape& s) { return testing::invalid_argument_message<GeometricPath>(s); };
  EXPECT_NE(message(CirclePath{{0, 0}, -1.0}).find("radius"), std::string::npos);
  EXPECT_NE(message(LinePath{{0, 0}, {0, 0}}).find("normal"), std::string::npos);
  EXPECT_NE(message(EllipsePath{{0, 0}, 1.0, 0.0, 0.0}).find("ellipse.b"), std::string::npos);
  PolynomialPath constant;
  constant.c(0, 0) = 1.0;
  EXPECT_NE(message(constant).find("non-constant"), std::string::npos);
  PolynomialPath too_high;
  too_high.c(6, 6) = 1.0;
  EXPECT_NE(message(too_high).find("c(6, 6)"), std::string::npos);
}

}  // namespace
}  // namespace plexus::algorithms
