// The statistics of `plexus sim --seeds` (seed_sweep.cpp) on series computed by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "seed_sweep.hpp"

namespace plexus::cli {
namespace {

TEST(SeedStatistics, MeanSampleStdStandardErrorAndT) {
  // 1..4: mean 2.5; squared deviations 2.25 + 0.25 + 0.25 + 2.25 = 5, sample variance 5/3;
  // std sqrt(5/3) = 1.2910; sem = std / sqrt(4) = 0.6455; t = 2.5 / 0.6455 = 3.8730.
  const SeedStatistics s = summarise({3.0, 1.0, 4.0, 2.0});
  EXPECT_DOUBLE_EQ(s.mean, 2.5);
  EXPECT_NEAR(s.std, std::sqrt(5.0 / 3.0), 1e-12);
  EXPECT_NEAR(s.sem, std::sqrt(5.0 / 3.0) / 2.0, 1e-12);
  EXPECT_NEAR(s.t, 2.5 / (std::sqrt(5.0 / 3.0) / 2.0), 1e-12);
  EXPECT_EQ(s.min, 1.0);
  EXPECT_EQ(s.max, 4.0);
  EXPECT_EQ(s.values, (std::vector<double>{3.0, 1.0, 4.0, 2.0}));  // in seed order
}

TEST(SeedStatistics, NegativeMeanGivesNegativeT) {
  const SeedStatistics s = summarise({-1.0, -2.0, -3.0});  // mean -2, std 1, sem 1/sqrt(3)
  EXPECT_NEAR(s.t, -2.0 * std::sqrt(3.0), 1e-12);
}

TEST(SeedStatistics, OneSeedOrNoSpreadHasNoT) {
  const SeedStatistics one = summarise({0.7});
  EXPECT_EQ(one.mean, 0.7);
  EXPECT_EQ(one.std, 0.0);
  EXPECT_TRUE(std::isnan(one.t));
  EXPECT_TRUE(std::isnan(summarise({0.0, 0.0, 0.0}).t));  // 0 / 0: no evidence either way
}

TEST(SeedStatistics, ANaNRunIsNeverDropped) {
  const SeedStatistics s = summarise({1.0, std::numeric_limits<double>::quiet_NaN(), 3.0});
  EXPECT_TRUE(std::isnan(s.mean));
  EXPECT_TRUE(std::isnan(s.max));
  EXPECT_EQ(s.values.size(), 3u);
  EXPECT_TRUE(s.to_json()["mean"].is_null());
}

}  // namespace
}  // namespace plexus::cli
