#include "plexus/algorithms/unicycle/position_sensor.hpp"

#include <gtest/gtest.h>

#include "../support/validation_message.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "plexus/algorithms/core/random.hpp"

namespace plexus::algorithms {
namespace {

TEST(Rng, SameSeedSameSequenceAndUniformInUnitInterval) {
  Rng a(42), b(42), c(43);
  bool differs = false;
  for (int i = 0; i < 1000; ++i) {
    const double ua = a.uniform01();
    EXPECT_EQ(ua, b.uniform01());
    differs |= ua != c.uniform01();
    EXPECT_GT(ua, 0.0);
    EXPECT_LE(ua, 1.0);
  }
  EXPECT_TRUE(differs);
}

TEST(Rng, BoxMullerNormalHasUnitMomentsAndIsPinnedToTheEngine) {
  Rng rng(7);
  const int n = 200000;
  double sum = 0, sum2 = 0;
  for (int i = 0; i < n; ++i) {
    const double x = rng.normal();
    sum += x;
    sum2 += x * x;
  }
  const double mean = sum / n;
  const double var = sum2 / n - mean * mean;
  EXPECT_NEAR(mean, 0.0, 5.0 / std::sqrt(n));
  EXPECT_NEAR(var, 1.0, 0.02);
  // Each normal() consumes exactly two engine draws and applies the documented transform.
  Rng r1(3), r2(3);
  const double u1 = r2.uniform01(), u2 = r2.uniform01();
  EXPECT_EQ(r1.normal(), std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2));
  EXPECT_EQ(r1.uniform01(), r2.uniform01());
}

TEST(PositionSensor, ExactReturnsTruth) {
  PositionSensor s({});
  Rng rng(1);
  const Eigen::Vector2d p(1.23456789, -9.87654321);
  EXPECT_EQ(s.measure(p, rng), p);
}

TEST(PositionSensor, RfidRoundsEachCoordinateToTheNearestTag) {
  PositionSensorParams params;
  params.kind = PositionSensorKind::kRfidGrid;
  params.grid_spacing = 0.1;
  PositionSensor s(params);
  Rng rng(1);
  EXPECT_NEAR(s.measure({0.04, -0.06}, rng).x(), 0.0, 1e-15);
  EXPECT_NEAR(s.measure({0.04, -0.06}, rng).y(), -0.1, 1e-15);
  EXPECT_NEAR(s.measure({1.26, 3.349}, rng).x(), 1.3, 1e-12);
  EXPECT_NEAR(s.measure({1.26, 3.349}, rng).y(), 3.3, 1e-12);
  // Property over many points: on the grid, within half a spacing per axis, idempotent.
  Rng draw(5);
  for (int i = 0; i < 2000; ++i) {
    const Eigen::Vector2d p(draw.uniform(-7, 7), draw.uniform(-7, 7));
    const Eigen::Vector2d m = s.measure(p, rng);
    for (int k = 0; k < 2; ++k) {
      EXPECT_LE(std::abs(m[k] - p[k]), 0.05 + 1e-12);
      EXPECT_NEAR(m[k] / 0.1, std::round(m[k] / 0.1), 1e-9);
    }
    EXPECT_TRUE(s.measure(m, rng).isApprox(m, 1e-12));
  }
}

TEST(PositionSensor, RfidGridOriginAndSpacingAreHonoured) {
  PositionSensorParams params;
  params.kind = PositionSensorKind::kRfidGrid;
  params.grid_spacing = 0.25;
  params.grid_origin = {0.05, -0.1};
  PositionSensor s(params);
  Rng rng(1);
  const Eigen::Vector2d m = s.measure({0.2, 0.1}, rng);
  EXPECT_NEAR(m.x(), 0.3, 1e-12);   // 0.05 + 0.25 * round(0.6)
  EXPECT_NEAR(m.y(), 0.15, 1e-12);  // -0.1 + 0.25 * round(0.8)
}

TEST(PositionSensor, GaussianIsReproducibleWithTheSeedAndHasTheRightSpread) {
  PositionSensorParams params;
  params.kind = PositionSensorKind::kGaussian;
  params.sigma = 0.02;
  params.seed = 99;
  PositionSensor s(params);
  Rng a = s.make_rng(), b = s.make_rng();
  double sum2 = 0;
  const int n = 50000;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d ma = s.measure({1.0, 2.0}, a);
    EXPECT_EQ(ma, s.measure({1.0, 2.0}, b));
    sum2 += (ma - Eigen::Vector2d(1.0, 2.0)).squaredNorm();
  }
  EXPECT_NEAR(std::sqrt(sum2 / (2 * n)), 0.02, 0.0005);
  EXPECT_DOUBLE_EQ(s.period(), 0.01);
}

TEST(PositionSensor, ValidationNamesTheParameter) {
  auto expect_throw = [](const PositionSensorParams& p, const std::string& name) {
    const std::string msg = testing::invalid_argument_message<PositionSensor>(p);
    EXPECT_NE(msg.find(name), std::string::npos) << "message: \"" << msg << "\"";
  };
  PositionSensorParams p;
  p.sigma = -0.1;
  expect_throw(p, "sigma");
  p = {};
  p.grid_spacing = 0.0;
  expect_throw(p, "grid_spacing");
  p = {};
  p.rate_hz = -5;
  expect_throw(p, "rate_hz");
  EXPECT_EQ(position_sensor_kind_from_string("rfid_grid"), PositionSensorKind::kRfidGrid);
  EXPECT_THROW(position_sensor_kind_from_string("sonar"), std::invalid_argument);
}

}  // namespace
}  // namespace plexus::algorithms
