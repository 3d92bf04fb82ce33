#include "plexus/runtime/periodic_loop.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "plexus/base/clock.hpp"
#include "plexus/base/input_error.hpp"

namespace plexus::rt {
namespace {

// Functional only: no timing thresholds (the machine is shared).
TEST(PeriodicLoop, RunsUntilTheBodySaysStopAndCountsIterations) {
  PeriodicLoop loop({.rate_hz = 2000});
  uint64_t last = 0;
  loop.run([&](const PeriodicLoop::Tick& t) {
    EXPECT_GE(t.wake_ns, t.deadline_ns);
    last = t.index;
    return t.index < 19;
  });
  EXPECT_EQ(last, 19u);
  const auto s = loop.stats();
  EXPECT_EQ(s.iterations, 20u);
  EXPECT_LE(s.jitter_p50_us, s.jitter_p99_us);
  EXPECT_LE(s.jitter_p99_us, s.jitter_max_us);
}

// Realtime hosts tick on a shared grid: the first deadline is given, the next ones follow
// at whole periods from it (not from when the thread woke).
TEST(PeriodicLoop, StartsAtAGivenDeadlineAndKeepsItsPhase) {
  PeriodicLoop loop({.rate_hz = 1000});
  const int64_t first = monotonic_ns() + 20'000'000 + 123'457;
  std::vector<int64_t> deadlines;
  loop.run([&](const PeriodicLoop::Tick& t) {
    EXPECT_GE(t.wake_ns, t.deadline_ns);
    deadlines.push_back(t.deadline_ns);
    return t.index < 4;
  }, first);
  ASSERT_EQ(deadlines.size(), 5u);
  EXPECT_EQ(deadlines[0], first);
  for (std::size_t i = 1; i < deadlines.size(); ++i)
    EXPECT_EQ((deadlines[i] - first) % 1'000'000, 0) << "tick " << i << " left the grid";
}

TEST(PeriodicLoop, OverrunsAreCounted) {
  PeriodicLoop loop({.rate_hz = 1000});
  loop.run([&](const PeriodicLoop::Tick& t) {
    if (t.index == 2) {
      const int64_t until = t.wake_ns + 5'000'000;  // busy for 5 periods
      while (monotonic_ns() < until) {
      }
    }
    return t.index < 5;
  });
  EXPECT_GE(loop.stats().overruns, 1u);
}

TEST(PeriodicLoop, RejectsBadOptions) {
  EXPECT_THROW(PeriodicLoop({.rate_hz = 0}), InputError);
  EXPECT_THROW(PeriodicLoop({.rate_hz = 100, .priority = 120}), InputError);
}

}  // namespace
}  // namespace plexus::rt
