// Clock offset of another host from timestamp exchanges (NTP's on-wire calculation,
// RFC 5905 section 8, with the minimum-delay selection of its clock filter, section 10).
// Pure arithmetic: the exchange itself goes over the ssh channel (remote_share.hpp).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace plexus::cli {

/// One exchange, wall-clock nanoseconds: t1 the request leaves here, t2 the other host
/// receives it, t3 it answers, t4 the answer arrives here.
struct ClockSample {
  int64_t t1 = 0, t2 = 0, t3 = 0, t4 = 0;
  /// RFC 5905 eq. for delta: (t4 - t1) - (t3 - t2), the round trip less the time spent there.
  int64_t delay_ns() const { return (t4 - t1) - (t3 - t2); }
  /// RFC 5905 eq. for theta: ((t2 - t1) + (t3 - t4)) / 2, the other clock minus ours.
  int64_t offset_ns() const { return ((t2 - t1) + (t3 - t4)) / 2; }
};

/// The estimate: the sample with the smallest delay (the least queueing, so the least
/// asymmetry). Its error is at most half its delay, whatever the asymmetry of the path.
struct ClockOffset {
  int64_t offset_ns = 0;       ///< other host's clock minus ours
  int64_t uncertainty_ns = 0;  ///< |true offset - offset_ns| <= this (delay / 2)
  int64_t delay_ns = 0;        ///< round trip of the chosen sample
  int samples = 0;
};

/// Throws std::invalid_argument for no sample or a sample with a negative delay (a clock
/// stepped during the exchange).
ClockOffset estimate_offset(const std::vector<ClockSample>& samples);

/// The largest offset realtime accepts between hosts: a tenth of the base step (1 ms at
/// 100 Hz, 100 us at 1 kHz). Loops tick at quarter-period phases (docs/distributed.md), so
/// this leaves most of each hop's quarter period to the network and the computation.
int64_t offset_bound_ns(double base_step_s);

/// "+0.012 ms +- 0.150 ms (round trip 0.300 ms, best of 16)"
std::string describe(const ClockOffset& o);

}  // namespace plexus::cli
