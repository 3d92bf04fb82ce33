#include "plexus/algorithms/unicycle/figure_eight_reference.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace plexus::algorithms {
namespace {

TEST(FigureEightReference, PaperClockOffsetStartsAtTheBottomPoint) {
  FigureEightReference ref({});
  const ReferenceSample r = ref.sample(0.0);
  EXPECT_NEAR(r.p.x(), 0.0, 1e-12);
  EXPECT_NEAR(r.p.y(), -5.0, 1e-12);
  EXPECT_DOUBLE_EQ(FigureEightParams{}.t0, FigureEightParams::paper_t0(0.02));
}

TEST(FigureEightReference, DerivativesMatchCentralDifferences) {
  FigureEightReference ref({5.0, 0.02, 12.3});
  const double eps = 1e-3;
  for (double t : {0.0, 17.0, 80.0, 155.5, 400.0}) {
    const ReferenceSample r = ref.sample(t), rp = ref.sample(t + eps), rm = ref.sample(t - eps);
    EXPECT_TRUE(r.dp.isApprox((rp.p - rm.p) / (2 * eps), 1e-6)) << t;
    EXPECT_TRUE(r.ddp.isApprox((rp.dp - rm.dp) / (2 * eps), 1e-6)) << t;
  }
}

TEST(FigureEightReference, AnalyticSpeedBoundsMatchADenseScan) {
  for (auto [h1, h2] : {std::pair{5.0, 0.02}, std::pair{2.0, 0.3}}) {
    FigureEightReference ref({h1, h2, 0.0});
    double lo = 1e9, hi = 0;
    const double period = 2 * std::numbers::pi / h2;
    for (int i = 0; i <= 200000; ++i) {
      const double v = ref.speed(period * i / 200000.0);
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
    EXPECT_NEAR(ref.min_speed(), lo, 1e-6 * h1 * h2);
    EXPECT_NEAR(ref.max_speed(), hi, 1e-6 * h1 * h2);
  }
  EXPECT_NEAR(FigureEightReference({}).min_speed(), 0.0696, 5e-5);  // paper 000, docs/papers.md
}

TEST(FigureEightReference, ValidationNamesTheParameter) {
  EXPECT_THROW(FigureEightReference({0.0, 0.02, 0.0}), std::invalid_argument);
  EXPECT_THROW(FigureEightReference({5.0, -0.02, 0.0}), std::invalid_argument);
  try {
    FigureEightReference({5.0, 0.02, std::nan("")});
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("t0"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace plexus::algorithms
