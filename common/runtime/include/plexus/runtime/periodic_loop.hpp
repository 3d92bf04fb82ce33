// A periodic loop on absolute deadlines (clock_nanosleep, CLOCK_MONOTONIC, TIMER_ABSTIME),
// with statistics: wake-up lateness (period jitter), compute time and overruns.
//
//   PeriodicLoop loop({.rate_hz = 1000, .priority = 80});
//   loop.run([&](const PeriodicLoop::Tick& t) { ...; return keep_going; });
//
// Real-time settings (SCHED_FIFO priority, CPU affinity, mlockall, a CPU wake-up latency
// request) are optional. When the system refuses one, the loop logs a clear warning saying
// what was refused and why, and runs anyway. The thread's timer slack is set to 1 ns by
// default (Linux's default of 50 us delays every wake-up of a loop without SCHED_FIFO by up
// to that much; docs/performance.md has the measurements). The steady-state loop does not allocate: statistics go into
// ring buffers sized at construction.
#pragma once

#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

namespace plexus::rt {

struct LoopOptions {
  double rate_hz = 100.0;    ///< > 0, at most 100 kHz
  int priority = 0;          ///< SCHED_FIFO priority 1..99; 0 keeps normal scheduling
  int cpu = -1;              ///< pin the calling thread to this CPU; -1: no affinity
  bool lock_memory = false;  ///< mlockall(MCL_CURRENT | MCL_FUTURE)
  /// PR_SET_TIMERSLACK of the calling thread, ns (>= 1); 0 keeps the thread's slack.
  int64_t timer_slack_ns = 1;
  /// >= 0: hold a PM QoS request on /dev/cpu_dma_latency for this CPU wake-up latency (us)
  /// while the loop exists, as cyclictest does (0 keeps idle CPUs out of their halt states,
  /// at the price of idle CPUs polling); -1: no request.
  int cpu_dma_latency_us = -1;
  std::size_t stats_window = 16384;  ///< samples kept for percentiles (most recent)
};

struct LoopStats {
  uint64_t iterations = 0;
  uint64_t overruns = 0;  ///< iterations that ended after the next deadline (periods skipped)
  double jitter_p50_us = 0, jitter_p99_us = 0, jitter_max_us = 0;     ///< wake-up lateness
  double compute_p50_us = 0, compute_p99_us = 0, compute_max_us = 0;  ///< body run time
};

/// Applies the thread settings of `o` (priority, cpu, lock_memory, timer_slack_ns; not the
/// rate, nor the CPU wake-up latency request, which a loop holds) to the calling thread,
/// warning for each one the system refuses; returns the refusals, "" if none. InputError for
/// out-of-range values. PeriodicLoop does this at construction; a thread that serves a loop
/// without one of its own (a bridge's I/O thread) calls it itself. Threads it creates after
/// inherit the priority and the CPU.
std::string apply_thread_settings(const LoopOptions& o);

class PeriodicLoop {
 public:
  struct Tick {
    uint64_t index;       ///< 0, 1, 2, ...
    int64_t deadline_ns;  ///< CLOCK_MONOTONIC deadline this iteration was scheduled for
    int64_t wake_ns;      ///< when the thread actually woke
  };

  /// Validates the options (InputError for out-of-range values) and applies the real-time
  /// settings to the calling thread, warning for each one the system refuses.
  explicit PeriodicLoop(const LoopOptions& options);
  ~PeriodicLoop();
  PeriodicLoop(const PeriodicLoop&) = delete;
  PeriodicLoop& operator=(const PeriodicLoop&) = delete;

  /// Calls body(tick) once per period until it returns false or stop() is called. The first
  /// deadline is `first_deadline_ns` (CLOCK_MONOTONIC) if given, else one period from now;
  /// the next ones follow at whole periods from it.
  template <class Body>
  void run(Body&& body, int64_t first_deadline_ns = 0) {
    start(first_deadline_ns);
    while (!stop_.load(std::memory_order_relaxed)) {
      const Tick t = wait_next();
      const bool go = body(t);
      end_compute();
      if (!go) break;
    }
  }

  /// Lower-level use: start(), then for each iteration wait_next() ... end_compute().
  void start(int64_t first_deadline_ns = 0);
  Tick wait_next();
  void end_compute();

  /// From the loop's body: moves the schedule by `ns` (the next deadline and every one after
  /// it), keeping the period. A loop that follows another's cycle (a device following its
  /// host's, docs/bridges.md "Cycle sync") re-phases with it.
  void shift(int64_t ns) { next_deadline_ns_ += ns; }

  /// Thread-safe: makes run() return after the current iteration.
  void stop() { stop_.store(true, std::memory_order_relaxed); }

  /// Statistics so far: percentiles of the last stats_window iterations (within 1.6 %, from
  /// histograms kept as they run: a few microseconds), maxima of all. Call from the loop thread.
  LoopStats stats() const;

  int64_t period_ns() const { return period_ns_; }
  /// The real-time settings that were refused, for heartbeats and reports ("" if none).
  const std::string& refused() const { return refused_; }

 private:
  int64_t period_ns_;
  int64_t next_deadline_ns_ = 0;
  int64_t wake_ns_ = 0;
  uint64_t index_ = 0;
  uint64_t overruns_ = 0;
  std::atomic<bool> stop_{false};
  std::string refused_;
  int dma_latency_fd_ = -1;  ///< the PM QoS request lives as long as this file is open

  // Ring buffers of the most recent samples (ns), their histograms, and all-time maxima.
  std::vector<int64_t> lateness_, compute_;
  std::vector<uint32_t> lateness_hist_, compute_hist_;
  std::size_t count_ = 0;
  int64_t late_ns_ = 0;  ///< this iteration's lateness, entered with its compute time
  int64_t lateness_max_ = 0, compute_max_ = 0;
};

}  // namespace plexus::rt
