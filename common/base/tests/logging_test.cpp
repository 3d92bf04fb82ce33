#include "plexus/base/logging.hpp"

#include <gtest/gtest.h>

#include "plexus/base/input_error.hpp"

namespace plexus {
namespace {

TEST(RateLimiter, LetsOneThroughPerIntervalAndCountsTheRest) {
  RateLimiter rl(1000);
  uint64_t suppressed = 99;
  EXPECT_TRUE(rl.allow(0, suppressed));
  EXPECT_EQ(suppressed, 0u);
  EXPECT_FALSE(rl.allow(10, suppressed));
  EXPECT_FALSE(rl.allow(999, suppressed));
  EXPECT_TRUE(rl.allow(1000, suppressed));
  EXPECT_EQ(suppressed, 2u);
}

TEST(Logging, UnknownLevelIsInputError) {
  EXPECT_THROW(parse_log_level("loud", "--log-level"), InputError);
  EXPECT_EQ(parse_log_level("debug", "x"), spdlog::level::debug);
}

}  // namespace
}  // namespace plexus
