#include "plexus/evaluation/progress_bar.hpp"

#include <unistd.h>

#include <cstdio>

#include "plexus/base/clock.hpp"

namespace plexus::scenario {

ProgressBar::ProgressBar(bool enabled, double delay_s)
    : enabled_(enabled && isatty(STDERR_FILENO) == 1),
      start_ns_(monotonic_ns()),
      delay_ns_(static_cast<int64_t>(delay_s * 1e9)) {}

ProgressBar::~ProgressBar() { finish(); }

void ProgressBar::update(int64_t step, int64_t steps) {
  if (!enabled_ || steps <= 0) return;
  const int64_t now = monotonic_ns();
  if (now - start_ns_ < delay_ns_ || now < next_draw_ns_) return;
  next_draw_ns_ = now + 100'000'000;
  constexpr int kWidth = 40;
  const double done = static_cast<double>(step) / static_cast<double>(steps);
  const int filled = static_cast<int>(done * kWidth);
  char bar[kWidth + 1];
  for (int i = 0; i < kWidth; ++i) bar[i] = i < filled ? '#' : '.';
  bar[kWidth] = '\0';
  const double elapsed = static_cast<double>(now - start_ns_) * 1e-9;
  const double eta = done > 0 ? elapsed * (1.0 - done) / done : 0.0;
  std::fprintf(stderr, "\r[%s] %3d%%  %.0f s elapsed, ~%.0f s left ", bar, static_cast<int>(done * 100), elapsed, eta);
  std::fflush(stderr);
  drawn_ = true;
}

void ProgressBar::finish() {
  if (!drawn_) return;
  std::fprintf(stderr, "\r%*s\r", 80, "");
  std::fflush(stderr);
  drawn_ = false;
}

}  // namespace plexus::scenario
