#include "plexus/runtime/periodic_loop.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sched.h>
#include <sys/prctl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <thread>
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
  loop.run(
      [&](const PeriodicLoop::Tick& t) {
        EXPECT_GE(t.wake_ns, t.deadline_ns);
        deadlines.push_back(t.deadline_ns);
        return t.index < 4;
      },
      first);
  ASSERT_EQ(deadlines.size(), 5u);
  EXPECT_EQ(deadlines[0], first);
  for (std::size_t i = 1; i < deadlines.size(); ++i)
    EXPECT_EQ((deadlines[i] - first) % 1'000'000, 0) << "tick " << i << " left the grid";
}

// A device following its host's cycle re-phases its loop (docs/bridges.md, "Cycle sync").
// Judged modulo the period: on a loaded machine an overrun skips whole periods (the test
// failed under CI's load when it compared the deadlines' differences).
TEST(PeriodicLoop, ShiftMovesTheScheduleAndKeepsThePeriod) {
  constexpr int64_t kPeriod = 1'000'000;
  PeriodicLoop loop({.rate_hz = 1000});
  const int64_t first = monotonic_ns() + 20'000'000;
  std::vector<int64_t> deadlines;
  loop.run(
      [&](const PeriodicLoop::Tick& t) {
        deadlines.push_back(t.deadline_ns);
        if (t.index == 1) loop.shift(-300'000);
        if (t.index == 3) loop.shift(450'000);
        return t.index < 5;
      },
      first);
  ASSERT_EQ(deadlines.size(), 6u);
  const auto phase = [&](std::size_t i) { return ((deadlines[i] - first) % kPeriod + kPeriod) % kPeriod; };
  EXPECT_EQ(phase(0), 0);
  EXPECT_EQ(phase(1), 0);
  EXPECT_EQ(phase(2), 700'000);  // moved 0.3 ms earlier
  EXPECT_EQ(phase(3), 700'000);
  EXPECT_EQ(phase(4), 150'000);  // then 0.45 ms later
  EXPECT_EQ(phase(5), 150'000);
  for (std::size_t i = 1; i < deadlines.size(); ++i) EXPECT_GT(deadlines[i], deadlines[i - 1]);
}

TEST(PeriodicLoop, OverrunsAreCounted) {
  PeriodicLoop loop({.rate_hz = 1000});
  loop.run([&](const PeriodicLoop::Tick& t) {
    if (t.index == 2) {
      const int64_t until = t.wake_ns + 5'000'000;  // busy for 5 periods
      while (monotonic_ns() < until) {}
    }
    return t.index < 5;
  });
  EXPECT_GE(loop.stats().overruns, 1u);
}

TEST(PeriodicLoop, RejectsBadOptions) {
  EXPECT_THROW(PeriodicLoop({.rate_hz = 0}), InputError);
  EXPECT_THROW(PeriodicLoop({.rate_hz = 100, .priority = 120}), InputError);
  EXPECT_THROW(PeriodicLoop({.rate_hz = 100, .timer_slack_ns = -1}), InputError);
  EXPECT_THROW(PeriodicLoop({.rate_hz = 100, .cpu_dma_latency_us = -2}), InputError);
  EXPECT_THROW(PeriodicLoop({.rate_hz = 100, .stats_window = 8}), InputError);
}

// A thread without a loop of its own (a bridge's I/O thread) takes the same settings.
TEST(ApplyThreadSettings, RejectsBadOptionsAndAppliesTheCpu) {
  EXPECT_THROW(apply_thread_settings({.priority = 120}), InputError);
  EXPECT_THROW(apply_thread_settings({.cpu = 4096}), InputError);
  EXPECT_THROW(apply_thread_settings({.timer_slack_ns = -1}), InputError);
  std::thread t([] {
    EXPECT_EQ(apply_thread_settings({.cpu = 0}), "");
    cpu_set_t set;
    ASSERT_EQ(sched_getaffinity(0, sizeof set, &set), 0);
    EXPECT_TRUE(CPU_ISSET(0, &set));
    EXPECT_EQ(CPU_COUNT(&set), 1);
  });
  t.join();
}

// The percentiles cover the last stats_window iterations (older ones leave the histogram)
// and match the exact nearest-rank percentiles of the ticks' lateness within a bucket (1.6 %).
TEST(PeriodicLoop, PercentilesOfTheLastWindowMatchTheTicks) {
  constexpr std::size_t kWindow = 16;
  PeriodicLoop loop({.rate_hz = 2000, .stats_window = kWindow});
  std::vector<int64_t> late;
  loop.run([&](const PeriodicLoop::Tick& t) {
    late.push_back(t.wake_ns - t.deadline_ns);
    return late.size() < 5 * kWindow + 3;
  });
  std::vector<int64_t> last(late.end() - kWindow, late.end());
  std::sort(last.begin(), last.end());
  const auto exact_us = [&](double q) {
    return static_cast<double>(last[static_cast<std::size_t>(q * (kWindow - 1) + 0.5)]) * 1e-3;
  };
  const auto s = loop.stats();
  EXPECT_EQ(s.iterations, late.size());
  EXPECT_NEAR(s.jitter_p50_us, exact_us(0.50), exact_us(0.50) / 64 + 1e-3);
  EXPECT_NEAR(s.jitter_p99_us, exact_us(0.99), exact_us(0.99) / 64 + 1e-3);
  EXPECT_DOUBLE_EQ(s.jitter_max_us, static_cast<double>(*std::max_element(late.begin(), late.end())) * 1e-3);
}

// The loop thread's timer slack is 1 ns by default (Linux's 50 us default delays every
// wake-up of a loop without SCHED_FIFO), and 0 keeps what the thread had.
TEST(PeriodicLoop, SetsTheThreadTimerSlack) {
  ASSERT_EQ(prctl(PR_SET_TIMERSLACK, 50'000UL, 0, 0, 0), 0);
  {
    PeriodicLoop keep({.rate_hz = 100, .timer_slack_ns = 0});
    EXPECT_EQ(prctl(PR_GET_TIMERSLACK, 0, 0, 0, 0), 50'000);
  }
  PeriodicLoop loop({.rate_hz = 100});
  EXPECT_EQ(prctl(PR_GET_TIMERSLACK, 0, 0, 0, 0), 1);
  prctl(PR_SET_TIMERSLACK, 0UL, 0, 0, 0);  // back to the default for the other tests
}

// A CPU wake-up latency request is held while the loop exists: /dev/cpu_dma_latency then
// reads at most the requested value (the kernel keeps the smallest request of all). Without
// the permission (not root) the request is refused with a warning and the loop runs.
TEST(PeriodicLoop, HoldsACpuWakeUpLatencyRequest) {
  PeriodicLoop loop({.rate_hz = 100, .cpu_dma_latency_us = 7});
  if (!loop.refused().empty()) {
    EXPECT_NE(loop.refused().find("cpu_dma_latency"), std::string::npos) << loop.refused();
    GTEST_SKIP() << "no permission for /dev/cpu_dma_latency: " << loop.refused();
  }
  const int fd = open("/dev/cpu_dma_latency", O_RDONLY);
  ASSERT_GE(fd, 0);
  int32_t value = -1;
  ASSERT_EQ(read(fd, &value, sizeof value), static_cast<ssize_t>(sizeof value));
  close(fd);
  EXPECT_GE(value, 0);
  EXPECT_LE(value, 7);
}

}  // namespace
}  // namespace plexus::rt
