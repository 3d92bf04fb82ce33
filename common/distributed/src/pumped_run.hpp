// The run thread's side of a lockstep host or clock whose steps run on the DDS receive
// threads (work_pump.hpp): it sleeps until the work finishes or fails, waking every
// 100 ms to check the stop flag and how long the work has made no progress, and to poke the
// pump (a safety net for a signal that was not delivered as data: a writer that went away,
// a missed notification). The work reports progress with a counter, and its end once, so a
// step wakes no thread besides the one that received its sample.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <mutex>

namespace plexus::distributed::detail {

class PumpedRun {
 public:
  /// How long the run thread sleeps between its checks.
  static constexpr std::chrono::milliseconds kCheck{100};

  // --- the work (one thread at a time) ---
  /// The work moved on (a component ran, a sample was recorded).
  void progress() { progress_.fetch_add(1, std::memory_order_relaxed); }
  /// The run is over: done (`error` null) or failed. Once.
  void finish(std::exception_ptr error = nullptr) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      done_ = true;
      error_ = std::move(error);
    }
    over_.store(true);
    finished_.notify_all();
  }
  bool finished() const { return over_.load(); }

  // --- the run thread ---
  /// Sleeps up to kCheck for the end of the run. True once it is over; rethrows its error.
  bool wait() {
    std::unique_lock<std::mutex> lock(mutex_);
    finished_.wait_for(lock, kCheck, [this] { return done_; });
    if (done_ && error_) std::rethrow_exception(error_);
    return done_;
  }
  /// How long (ns) the work has made no progress, as of `now_ns` (monotonic).
  int64_t stalled_ns(int64_t now_ns) {
    const uint64_t p = progress_.load(std::memory_order_relaxed);
    if (p != seen_ || since_ns_ == 0) {
      seen_ = p;
      since_ns_ = now_ns;
    }
    return now_ns - since_ns_;
  }

 private:
  std::atomic<uint64_t> progress_{0};
  std::atomic<bool> over_{false};
  std::mutex mutex_;
  std::condition_variable finished_;
  bool done_ = false;
  std::exception_ptr error_;
  // the run thread's
  uint64_t seen_ = 0;
  int64_t since_ns_ = 0;
};

}  // namespace plexus::distributed::detail
