// A one-line progress bar on stderr for long runs.
//
// It draws nothing until the run has lasted `delay_s` of wall time (short runs stay
// silent), redraws at most ten times a second, and erases itself at the end. It is
// enabled only when asked and stderr is a terminal.
#pragma once

#include <cstdint>

namespace plexus::scenario {

class ProgressBar {
 public:
  /// `enabled`: the caller's choice (false for --quiet); the bar also stays off when
  /// stderr is not a terminal.
  explicit ProgressBar(bool enabled, double delay_s = 2.0);
  ~ProgressBar();

  /// Progress: `step` of `steps` done.
  void update(int64_t step, int64_t steps);
  /// Erases the bar if it was drawn.
  void finish();

 private:
  bool enabled_;
  bool drawn_ = false;
  int64_t start_ns_;
  int64_t delay_ns_;
  int64_t next_draw_ns_ = 0;
};

}  // namespace plexus::scenario
