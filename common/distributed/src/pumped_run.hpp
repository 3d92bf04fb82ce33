// A lockstep host's or clock's run whose steps run on the DDS receive threads: the pump
// they poke (work_pump.hpp), and the run thread's side. The run thread sleeps until the work
// finishes or fails, waking every 100 ms to check the stop flag and how long the work has
// made no progress, and to poke the pump (a safety net for a signal that was not delivered
// as data: a writer that went away, a missed notification). The work reports progress with
// a counter, and its end once, so a step wakes no thread besides the one that received its
// sample.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <utility>

#include "plexus/base/clock.hpp"
#include "work_pump.hpp"

namespace plexus::distributed::detail {

class PumpedRun {
 public:
  /// How long the run thread sleeps between its checks.
  static constexpr std::chrono::milliseconds kCheck{100};
  /// A wait this long is told once (watch's `tell`), to find a stall.
  static constexpr int64_t kTellNs = 1'000'000'000;

  /// `work` runs on the threads that poke, one at a time, while watch() runs.
  explicit PumpedRun(std::function<void()> work) : pump_(std::move(work)) {}

  // --- the receive threads ---
  /// A sample arrived: run the work here, or have the thread running it go round again.
  void poke() { pump_.poke(); }

  // --- the work (one thread at a time) ---
  /// The work moved on (a component ran, a sample was recorded).
  void progress() { progress_.fetch_add(1, std::memory_order_relaxed); }
  /// The run is over: done (`error` null) or failed. Once.
  void finish(std::exception_ptr error = nullptr) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      error_ = std::move(error);
      over_.store(true);
    }
    finished_.notify_all();
  }
  bool finished() const { return over_.load(); }

  // --- the run thread ---
  /// Opens the pump, runs the work once (samples that arrived before), and watches the run
  /// until it finishes (true; its error rethrown) or `stop` is set (false). Every kCheck it
  /// pokes the pump and calls check(stalled_ns, tell): how long the work has made no
  /// progress, and true once per wait when that passes kTellNs; check may throw. No work
  /// runs once watch() has returned or thrown.
  template <class Check>
  bool watch(const std::atomic<bool>& stop, Check&& check) {
    struct Closer {
      WorkPump<std::function<void()>>& pump;
      ~Closer() { pump.close(); }
    } closer{pump_};
    pump_.open();
    pump_.poke();
    uint64_t seen = progress_.load(std::memory_order_relaxed);
    int64_t since = monotonic_ns();
    bool told = false;
    while (!wait()) {
      if (stop.load(std::memory_order_relaxed)) return false;
      pump_.poke();
      const int64_t now = monotonic_ns();
      if (const uint64_t p = progress_.load(std::memory_order_relaxed); p != seen) {
        seen = p;
        since = now;
        told = false;
      }
      const int64_t stalled = now - since;
      const bool tell = !told && stalled >= kTellNs;
      told = told || tell;
      check(stalled, tell);
    }
    return true;
  }

 private:
  /// Sleeps up to kCheck for the end of the run. True once it is over; rethrows its error.
  bool wait() {
    std::unique_lock<std::mutex> lock(mutex_);
    finished_.wait_for(lock, kCheck, [this] { return over_.load(); });
    if (over_.load() && error_) std::rethrow_exception(error_);
    return over_.load();
  }

  WorkPump<std::function<void()>> pump_;
  std::atomic<uint64_t> progress_{0};
  std::atomic<bool> over_{false};
  std::mutex mutex_;
  std::condition_variable finished_;
  std::exception_ptr error_;
};

}  // namespace plexus::distributed::detail
