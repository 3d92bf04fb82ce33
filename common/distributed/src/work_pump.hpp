// Runs one piece of work on whichever thread asks for it, one thread at a time, without a
// lock: the DDS receive threads that deliver a lockstep run's samples run its steps
// themselves, so no loop thread is woken per sample (as ddsperf's pong answers on its
// receive thread; docs/performance.md, section 4).
//
// A thread that pokes while another runs the work returns at once, and the running thread
// goes round once more: a sample that arrives during a round is never left unprocessed.
// The counter's read-modify-writes order each round after the pokes it handles, so a round
// sees everything the poking threads saw.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <thread>
#include <utility>

namespace plexus::distributed::detail {

template <class Work>
class WorkPump {
 public:
  explicit WorkPump(Work work) : work_(std::move(work)) {}

  /// Pokes do the work from now on (before: they are counted and do nothing).
  void open() { open_.store(true); }

  /// Runs the work now, or has the thread that is running it go round once more. Never
  /// waits. The work must not throw.
  void poke() {
    if (pending_.fetch_add(1) != 0) return;
    uint32_t handled = 1;
    for (;;) {
      if (open_.load()) work_();
      const uint32_t left = pending_.fetch_sub(handled) - handled;
      if (left == 0) return;
      handled = left;
    }
  }

  /// No work runs after it returns: waits for a round in progress to end. A later poke
  /// sees the pump closed (sequentially consistent: it either counted before the wait saw
  /// zero, and was waited for, or it loads `open_` after the store here).
  void close() {
    open_.store(false);
    while (pending_.load() != 0) std::this_thread::sleep_for(std::chrono::microseconds(100));
  }

 private:
  Work work_;
  std::atomic<uint32_t> pending_{0};
  std::atomic<bool> open_{false};
};

}  // namespace plexus::distributed::detail
