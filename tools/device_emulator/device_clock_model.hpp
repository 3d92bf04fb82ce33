// The emulated device's clock (docs/bridges.md, "Device time"): the host's CLOCK_REALTIME
// seen by a device that powered up at `wall0_ns` with its clock set to `offset_s` and
// running `drift_ppm` fast. The emulator stamps its samples with it and answers the
// bridge's time requests with it; the truth of a sample is the host time it was taken at.
#pragma once

#include <cstdint>

namespace plexus::emulator {

struct DeviceClockModel {
  int64_t wall0_ns = 0;  ///< host CLOCK_REALTIME when the device's clock read offset_s
  double offset_s = 0.0;
  double drift_ppm = 0.0;  ///< |drift_ppm| <= 1000
  /// The device's clock (s) at host time `wall_ns`.
  double at(int64_t wall_ns) const {
    return static_cast<double>(wall_ns - wall0_ns) * 1e-9 * (1.0 + drift_ppm * 1e-6) + offset_s;
  }
};

}  // namespace plexus::emulator
