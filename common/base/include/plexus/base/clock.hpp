// Clocks used for timestamps and loops.
#pragma once

#include <cstdint>
#include <ctime>

namespace plexus {

/// Wall clock (CLOCK_REALTIME) in ns: header origin/publish times, comparable across hosts
/// that synchronise their clocks.
inline int64_t wall_time_ns() {
  timespec ts{};
  clock_gettime(CLOCK_REALTIME, &ts);
  return static_cast<int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
}

/// Monotonic clock in ns: loop deadlines, timeouts and durations.
inline int64_t monotonic_ns() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
}

}  // namespace plexus
