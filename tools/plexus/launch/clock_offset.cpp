#include "clock_offset.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace plexus::cli {

ClockOffset estimate_offset(const std::vector<ClockSample>& samples) {
  if (samples.empty()) throw std::invalid_argument("no clock sample");
  const ClockSample* best = nullptr;
  for (const auto& s : samples) {
    if (s.delay_ns() < 0)
      throw std::invalid_argument("a clock sample with a negative round trip (a clock was stepped)");
    if (!best || s.delay_ns() < best->delay_ns()) best = &s;
  }
  ClockOffset o;
  o.offset_ns = best->offset_ns();
  o.delay_ns = best->delay_ns();
  o.uncertainty_ns = (o.delay_ns + 1) / 2;
  o.samples = static_cast<int>(samples.size());
  return o;
}

int64_t offset_bound_ns(double base_step_s) { return std::llround(base_step_s * 1e9 / 10.0); }

std::string describe(const ClockOffset& o) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "%+.3f ms +- %.3f ms (round trip %.3f ms, best of %d)",
                static_cast<double>(o.offset_ns) * 1e-6, static_cast<double>(o.uncertainty_ns) * 1e-6,
                static_cast<double>(o.delay_ns) * 1e-6, o.samples);
  return buf;
}

}  // namespace plexus::cli
