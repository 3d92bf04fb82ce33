#include "plexus/link/device_clock.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace plexus::link {

DeviceClock::DeviceClock(DeviceClockOptions options) : opt_(options) {
  opt_.window = std::max<std::size_t>(opt_.window, 2);
  ring_.resize(opt_.window);
}

bool DeviceClock::add(double t1, double t2, double t3, double t4) {
  if (!std::isfinite(t1) || !std::isfinite(t2) || !std::isfinite(t3) || !std::isfinite(t4) || t4 < t1 || t3 < t2)
    return false;
  ring_[head_] = {t1, t2, t3, t4};
  head_ = (head_ + 1) % ring_.size();
  count_ = std::min(count_ + 1, ring_.size());
  d_ref_ = t3;
  fit();
  double lo = 0, hi = 0;
  band(b_, lo, hi);
  if (hi < lo) {  // no line meets every bound: start again from this exchange
    ++restarts_;
    ring_[0] = {t1, t2, t3, t4};
    head_ = 1 % ring_.size();
    count_ = 1;
    fit();
  }
  offset_ = d_ref_ - a_;
  return true;
}

void DeviceClock::band(double b, double& lo, double& hi) const {
  lo = -std::numeric_limits<double>::infinity();
  hi = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < count_; ++i) {
    const Exchange& e = ring_[i];
    lo = std::max(lo, e.t1 - b * (e.t2 - d_ref_));
    hi = std::min(hi, e.t4 - b * (e.t3 - d_ref_));
  }
}

void DeviceClock::fit() {
  double lo = 0, hi = 0;
  if (count_ < 2) {  // one exchange fixes no slope
    b_ = 1.0;
  } else {
    // The band's width hi(b) - lo(b) is concave in b (a minimum of lines minus a maximum of
    // lines): a ternary search finds its widest point.
    const double m = opt_.max_drift_ppm * 1e-6;
    double left = 1.0 / (1.0 + m), right = 1.0 / (1.0 - std::min(m, 0.5));
    for (int it = 0; it < 80 && right - left > 1e-10; ++it) {  // 1e-10 over 10 s: 1 ns
      const double m1 = left + (right - left) / 3, m2 = right - (right - left) / 3;
      double l1, h1, l2, h2;
      band(m1, l1, h1);
      band(m2, l2, h2);
      if (h1 - l1 < h2 - l2)
        left = m1;
      else
        right = m2;
    }
    b_ = 0.5 * (left + right);
  }
  band(b_, lo, hi);
  a_ = 0.5 * (lo + hi);
  half_width_ = std::max(0.0, 0.5 * (hi - lo));
}

}  // namespace plexus::link
