// The runtime tests' wait for something DDS does in its own time (discovery, delivery).
#pragma once

#include <chrono>
#include <functional>
#include <thread>

#include "plexus/base/clock.hpp"

namespace plexus::rt::testing {

/// Polls `cond` every 10 ms for up to `seconds`; its last value.
inline bool eventually(const std::function<bool()>& cond, double seconds) {
  const int64_t end = monotonic_ns() + static_cast<int64_t>(seconds * 1e9);
  while (monotonic_ns() < end) {
    if (cond()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return cond();
}

}  // namespace plexus::rt::testing
