// Device time mapped to host time (docs/bridges.md, "Device time"): a line fitted to the
// two-way exchanges a bridge makes over the link, the on-wire exchange of NTP (RFC 5905,
// section 8):
//   t1  the host sends a request        (host clock)
//   t2  the device receives it          (device clock)
//   t3  the device sends the response   (device clock)
//   t4  the host receives the response  (host clock)
// The map g from device time to host time is a line, g(d) = a + b (d - d_ref), with
// b = 1 / (1 + drift). Each exchange bounds it: g(t2) >= t1 (the request arrived after it
// left) and g(t3) <= t4 (the response left before it arrived). Over the last `window`
// exchanges the clock takes the slope whose band of feasible intercepts is widest and the
// middle of that band (the line farthest from both sets of bounds). With random link delays
// the exchanges that happened to be fastest carry the information: the middle of the
// extremes converges as 1/N, where a least-squares mean of per-exchange offsets converges as
// 1/sqrt(N) (measured on 0-2 ms uniform jitter: tests/link_test.cpp, DeviceClock.*).
//   The half-width of that band is the uncertainty: a bound on the map's error when the
// link's smallest delays are equal both ways. An unequal minimum (a request shorter on the
// wire than the response) biases the map by half the difference; nothing measured over one
// link can see it, so the protocol makes both frames the same length.
//   An exchange that contradicts the others (no line satisfies every bound: the device's
// clock jumped, or it was reset) starts the fit again from that exchange (`restarts`).
// No allocation after construction.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace plexus::link {

struct DeviceClockOptions {
  std::size_t window = 1536;    ///< exchanges fitted (1536: ~30 s at 50 Hz), >= 2
  double max_drift_ppm = 1000;  ///< slopes searched: 1 / (1 + drift) for |drift| <= this, > 0
};

class DeviceClock {
 public:
  explicit DeviceClock(DeviceClockOptions options = {});

  /// One exchange: host times t1, t4 (s, any epoch the caller keeps), device times t2, t3
  /// (s). False, and ignored, if it cannot be one: not finite, t4 < t1 or t3 < t2.
  bool add(double t1, double t2, double t3, double t4);

  /// At least one exchange since the start (or the last restart).
  bool valid() const { return count_ > 0; }
  /// g(d): the host time of device time d (s). Requires valid().
  double to_host(double device_s) const { return a_ + b_ * (device_s - d_ref_); }
  /// g^-1(h): the device time of host time h (s). Requires valid().
  double to_device(double host_s) const { return d_ref_ + (host_s - a_) / b_; }
  /// How far the device's clock is ahead of the host's at the last exchange, s.
  double offset_s() const { return offset_; }
  /// How much faster the device's clock runs than the host's, in parts per million.
  double drift_ppm() const { return (1.0 / b_ - 1.0) * 1e6; }
  /// Half the width of the feasible band, s (see the header).
  double uncertainty_s() const { return half_width_; }
  std::size_t exchanges() const { return count_; }
  uint64_t restarts() const { return restarts_; }

 private:
  struct Exchange {
    double t1, t2, t3, t4;
  };
  void fit();
  /// The feasible band of intercepts at slope b: [lo, hi] (hi < lo: none).
  void band(double b, double& lo, double& hi) const;

  DeviceClockOptions opt_;
  std::vector<Exchange> ring_;
  std::size_t head_ = 0, count_ = 0;
  double d_ref_ = 0, a_ = 0, b_ = 1, offset_ = 0, half_width_ = 0;
  uint64_t restarts_ = 0;
};

}  // namespace plexus::link
