// Helpers shared by the metric files: a time window's bounds, and a trace read held at
// increasing steps.
#pragma once

#include <cstddef>
#include <cstdint>

#include "plexus/scenario/metric.hpp"

namespace plexus::scenario::metric_detail {

/// t within [from, to], with a tolerance of a billionth of a step for rounding.
inline bool in_window(double t, double from, double to, double step) {
  const double eps = 1e-9 * step;
  return t >= from - eps && t <= to + eps;
}

/// Reads `trace` held at increasing steps: the latest row at or before the step, or -1.
struct Held {
  const SignalTrace* trace;
  std::size_t next = 0;
  long row(int64_t step) {
    while (next < trace->size() && trace->steps[next] <= step) ++next;
    return static_cast<long>(next) - 1;
  }
};

}  // namespace plexus::scenario::metric_detail
