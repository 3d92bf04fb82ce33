// A device that follows its host's cycle (docs/bridges.md, "Cycle sync"): from a cycle frame
// (0x8D: the device time at which one of the run's steps falls, that step, and the step's
// length in device seconds) and the device's clock, how far to move the loop's next tick so
// that it falls on the run's nearest step, and which step that is. A fieldbus device does
// the same with its distributed clock's SYNC0 event.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "device_clock_model.hpp"
#include "plexus/link/frame.hpp"
#include "plexus/link/protocol.hpp"

namespace plexus::emulator {

class CycleFollower {
 public:
  /// `step_ns`: the device's own step (host ns); a cycle more than 0.1 % off it is refused.
  explicit CycleFollower(int64_t step_ns) : step_ns_(step_ns) {}

  /// The shift (ns, at most half a step either way) that puts the loop's next tick, at host
  /// time `next_tick_wall_ns` (CLOCK_REALTIME), on the cycle, and the run's step there. False
  /// (counted) for a payload that is no cycle: the wrong length, not finite, a step that is no
  /// integer, or a step's length not the device's own.
  bool shift_for(const uint8_t* payload, std::size_t n, const DeviceClockModel& clock, int64_t next_tick_wall_ns,
                 int64_t& shift_ns, int64_t& step) {
    if (n != link::kCyclePayload) return refuse();
    const double origin = link::get_f64_le(payload), period = link::get_f64_le(payload + 8),
                 origin_step = link::get_f64_le(payload + 16);
    if (!(std::abs(origin_step) <= 1e15) || origin_step != std::nearbyint(origin_step)) return refuse();
    const double rate = 1.0 + clock.drift_ppm * 1e-6;  // device s per host s
    const double step_host_s = static_cast<double>(step_ns_) * 1e-9;
    if (!std::isfinite(origin) || !std::isfinite(period) || !(std::abs(period / rate / step_host_s - 1.0) <= 1e-3))
      return refuse();
    // In device seconds (small numbers: no CLOCK_REALTIME nanoseconds in a double).
    const double next = clock.at(next_tick_wall_ns);
    const double steps = std::nearbyint((next - origin) / period);
    const double target = origin + steps * period;
    shift_ns = std::llround((target - next) / rate * 1e9);
    step = static_cast<int64_t>(origin_step + steps);
    const double us = static_cast<double>(shift_ns) * 1e-3;
    if (syncs_ == 0)
      first_shift_us_ = us;
    else
      max_shift_us_ = std::max(max_shift_us_, std::abs(us));
    ++syncs_;
    return true;
  }

  uint64_t syncs() const { return syncs_; }
  uint64_t refused() const { return refused_; }
  /// The first re-phase (the device's phase before it followed), us.
  double first_shift_us() const { return first_shift_us_; }
  /// The largest re-phase after the first (how far the device drifted off between two), us.
  double max_shift_us() const { return max_shift_us_; }

 private:
  bool refuse() {
    ++refused_;
    return false;
  }
  int64_t step_ns_;
  uint64_t syncs_ = 0, refused_ = 0;
  double first_shift_us_ = 0, max_shift_us_ = 0;
};

}  // namespace plexus::emulator
