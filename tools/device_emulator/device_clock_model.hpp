// The emulated device's clock (docs/bridges.md, "Device time"): the host's CLOCK_REALTIME
// seen by a device that powered up at `wall0_ns` with its clock set to `offset_s` and
// running `drift_ppm` fast. The emulator stamps its samples with it and answers the
// bridge's time requests with it; the truth of a sample is the host time it was taken at.
#pragma once

#include <cstdint>
#include <cstring>

#include "plexus/base/clock.hpp"
#include "plexus/link/frame.hpp"

namespace plexus::emulator {

struct DeviceClockModel {
  int64_t wall0_ns = 0;  ///< host CLOCK_REALTIME when the device's clock read offset_s
  double offset_s = 0.0;
  double drift_ppm = 0.0;  ///< |drift_ppm| <= 1000
  /// The device's clock (s) at host time `wall_ns`.
  double at(int64_t wall_ns) const {
    return static_cast<double>(wall_ns - wall0_ns) * 1e-9 * (1.0 + drift_ppm * 1e-6) + offset_s;
  }
  /// The payload of the time response (0x0E) to a request's payload: t1 echoed, t2 = the
  /// device clock at `arrived_ns` (CLOCK_REALTIME), t3 = the clock now, as the answer leaves.
  void answer(const uint8_t* request_payload, int64_t arrived_ns, uint8_t out[24]) const {
    std::memcpy(out, request_payload, 8);
    link::put_f64_le(out + 8, at(arrived_ns));
    link::put_f64_le(out + 16, at(wall_time_ns()));
  }
};

}  // namespace plexus::emulator
