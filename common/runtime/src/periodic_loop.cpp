#include "plexus/runtime/periodic_loop.hpp"

#include <fcntl.h>
#include <sched.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <ctime>

#include <spdlog/spdlog.h>

#include "plexus/base/clock.hpp"
#include "plexus/base/input_error.hpp"

namespace plexus::rt {
namespace {

void sleep_until(int64_t deadline_ns) {
  timespec ts{static_cast<time_t>(deadline_ns / 1'000'000'000), static_cast<long>(deadline_ns % 1'000'000'000)};
  while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) == EINTR) {}
}

// Percentiles from log-linear histograms kept up to date as samples enter and leave the
// window, so stats() costs a scan of kBuckets counters instead of copying and partially
// sorting the window (nth_element over 2 x 16384 samples: 120-230 us on this machine, inside
// the loop body of every service, once a second for its heartbeat). Below 128 ns a bucket is
// 1 ns; above, each power of two has 64 buckets: a bucket spans at most 1/64 (1.6 %) of its
// values, and a percentile is reported as its bucket's middle, never above the maximum.
constexpr int kSubBits = 6;
constexpr int64_t kLinearNs = int64_t{2} << kSubBits;  // 128
constexpr int kTopBit = 36;                            // 2^36 ns (69 s) and above share the last bucket

std::size_t bucket_of(int64_t ns) {
  if (ns < kLinearNs) return ns < 0 ? 0 : static_cast<std::size_t>(ns);
  const int e = std::min(63 - __builtin_clzll(static_cast<unsigned long long>(ns)), kTopBit);
  const int64_t sub =
      e == kTopBit ? (int64_t{1} << kSubBits) - 1 : (ns >> (e - kSubBits)) & ((int64_t{1} << kSubBits) - 1);
  return static_cast<std::size_t>(kLinearNs + (e - kSubBits - 1) * (int64_t{1} << kSubBits) + sub);
}

constexpr std::size_t kBuckets = static_cast<std::size_t>(kLinearNs + (kTopBit - kSubBits) * (int64_t{1} << kSubBits));

double bucket_middle_ns(std::size_t b) {
  if (b < static_cast<std::size_t>(kLinearNs)) return static_cast<double>(b);
  const auto j = static_cast<int64_t>(b) - kLinearNs;
  const int shift = static_cast<int>(j >> kSubBits) + 1;  // e - kSubBits
  const int64_t low = ((int64_t{1} << kSubBits) + (j & ((int64_t{1} << kSubBits) - 1))) << shift;
  return static_cast<double>(low) + static_cast<double>(int64_t{1} << shift) / 2.0;
}

// The nearest-rank percentile (index round(q (n - 1)) of the sorted window), in us.
double percentile_us(const std::vector<uint32_t>& hist, std::size_t n, double q, int64_t max_ns) {
  if (n == 0) return 0.0;
  const auto k = static_cast<std::size_t>(q * static_cast<double>(n - 1) + 0.5);
  std::size_t seen = 0;
  for (std::size_t b = 0; b < hist.size(); ++b) {
    seen += hist[b];
    if (seen > k) return std::min(bucket_middle_ns(b), static_cast<double>(max_ns)) * 1e-3;
  }
  return static_cast<double>(max_ns) * 1e-3;
}

}  // namespace

namespace {
// A refusal the system may lift: a warning, with the advice that fits why it was refused.
void refuse(std::string& refused, const std::string& what, int err, const char* capability, const char* limit) {
  const std::string msg = what + " refused (" + std::strerror(err) + ")";
  refused += (refused.empty() ? "" : "; ") + msg;
  if (err == EPERM || err == EACCES)
    spdlog::warn("{}: the loop runs without it. Grant {} or raise {} in /etc/security/limits.conf to enable it.", msg,
                 capability, limit);
  else
    spdlog::warn("{}: the loop runs without it.", msg);
}
}  // namespace

std::string apply_thread_settings(const LoopOptions& o) {
  if (o.priority < 0 || o.priority > 99)
    throw InputError("loop priority must be in 0..99, got " + std::to_string(o.priority));
  if (o.timer_slack_ns < 0)
    throw InputError("loop timer_slack_ns must be >= 0 (0: keep), got " + std::to_string(o.timer_slack_ns));
  // A CPU that does not exist is a wrong argument, not a missing permission.
  const long cpus = sysconf(_SC_NPROCESSORS_CONF);
  if (o.cpu >= 0 && cpus > 0 && o.cpu >= cpus)
    throw InputError("loop CPU " + std::to_string(o.cpu) + ": no such CPU (this machine has CPUs 0.." +
                     std::to_string(cpus - 1) + ")");
  std::string refused;
  if (o.lock_memory && mlockall(MCL_CURRENT | MCL_FUTURE) != 0)
    refuse(refused, "mlockall", errno, "CAP_IPC_LOCK", "memlock");
  if (o.timer_slack_ns > 0 && prctl(PR_SET_TIMERSLACK, static_cast<unsigned long>(o.timer_slack_ns), 0, 0, 0) != 0)
    refuse(refused, "timer slack " + std::to_string(o.timer_slack_ns) + " ns", errno, "CAP_SYS_NICE", "rtprio");
  if (o.cpu >= 0) {
    cpu_set_t set;
    CPU_ZERO(&set);
    CPU_SET(o.cpu, &set);
    if (sched_setaffinity(0, sizeof(set), &set) != 0)
      refuse(refused, "CPU affinity to CPU " + std::to_string(o.cpu), errno, "CAP_SYS_NICE", "rtprio");
  }
  if (o.priority > 0) {
    sched_param sp{};
    sp.sched_priority = o.priority;
    if (sched_setscheduler(0, SCHED_FIFO, &sp) != 0)
      refuse(refused, "SCHED_FIFO priority " + std::to_string(o.priority), errno, "CAP_SYS_NICE", "rtprio");
  }
  return refused;
}

PeriodicLoop::PeriodicLoop(const LoopOptions& o) {
  if (!(o.rate_hz > 0.0 && o.rate_hz <= 100'000.0))
    throw InputError("loop rate must be in (0, 100000] Hz, got " + std::to_string(o.rate_hz));
  if (o.stats_window < 16 || o.stats_window > (std::size_t{1} << 24))
    throw InputError("loop stats_window must be in 16..16777216, got " + std::to_string(o.stats_window));
  if (o.cpu_dma_latency_us < -1 || o.cpu_dma_latency_us > 10'000'000)
    throw InputError("loop cpu_dma_latency_us must be -1 (none) or in 0..10000000, got " +
                     std::to_string(o.cpu_dma_latency_us));
  period_ns_ = static_cast<int64_t>(1e9 / o.rate_hz + 0.5);
  lateness_.assign(o.stats_window, 0);
  compute_.assign(o.stats_window, 0);
  lateness_hist_.assign(kBuckets, 0);
  compute_hist_.assign(kBuckets, 0);
  refused_ = apply_thread_settings(o);
  if (o.cpu_dma_latency_us >= 0) {
    // The kernel keeps the request while the file stays open (Documentation/power/pm_qos_interface).
    dma_latency_fd_ = open("/dev/cpu_dma_latency", O_RDWR | O_CLOEXEC);
    const auto value = static_cast<int32_t>(o.cpu_dma_latency_us);
    if (dma_latency_fd_ < 0 || write(dma_latency_fd_, &value, sizeof value) != static_cast<ssize_t>(sizeof value)) {
      refuse(refused_,
             "CPU wake-up latency request of " + std::to_string(o.cpu_dma_latency_us) + " us (/dev/cpu_dma_latency)",
             errno, "root access to /dev/cpu_dma_latency", "nothing (the file is root's)");
      if (dma_latency_fd_ >= 0) close(dma_latency_fd_);
      dma_latency_fd_ = -1;
    }
  }
}

PeriodicLoop::~PeriodicLoop() {
  if (dma_latency_fd_ >= 0) close(dma_latency_fd_);
}

void PeriodicLoop::start(int64_t first_deadline_ns) {
  next_deadline_ns_ = first_deadline_ns > 0 ? first_deadline_ns : monotonic_ns() + period_ns_;
  index_ = 0;
}

PeriodicLoop::Tick PeriodicLoop::wait_next() {
  sleep_until(next_deadline_ns_);
  wake_ns_ = monotonic_ns();
  late_ns_ = wake_ns_ - next_deadline_ns_;
  lateness_max_ = std::max(lateness_max_, late_ns_);
  return Tick{index_, next_deadline_ns_, wake_ns_};
}

void PeriodicLoop::end_compute() {
  const int64_t now = monotonic_ns();
  const int64_t took = now - wake_ns_;
  // The iteration's samples enter the window, the oldest ones leave it (after the wake-up
  // time was taken: none of this delays it).
  const std::size_t slot = count_ % lateness_.size();
  if (count_ >= lateness_.size()) {
    --lateness_hist_[bucket_of(lateness_[slot])];
    --compute_hist_[bucket_of(compute_[slot])];
  }
  lateness_[slot] = late_ns_;
  compute_[slot] = took;
  ++lateness_hist_[bucket_of(late_ns_)];
  ++compute_hist_[bucket_of(took)];
  compute_max_ = std::max(compute_max_, took);
  ++count_;
  ++index_;
  next_deadline_ns_ += period_ns_;
  if (now > next_deadline_ns_) {
    // Overrun: skip the periods already missed, keep the phase of the original schedule.
    const int64_t missed = (now - next_deadline_ns_) / period_ns_ + 1;
    next_deadline_ns_ += missed * period_ns_;
    ++overruns_;
  }
}

LoopStats PeriodicLoop::stats() const {
  LoopStats s;
  s.iterations = count_;
  s.overruns = overruns_;
  const std::size_t n = std::min(count_, lateness_.size());
  s.jitter_p50_us = percentile_us(lateness_hist_, n, 0.50, lateness_max_);
  s.jitter_p99_us = percentile_us(lateness_hist_, n, 0.99, lateness_max_);
  s.compute_p50_us = percentile_us(compute_hist_, n, 0.50, compute_max_);
  s.compute_p99_us = percentile_us(compute_hist_, n, 0.99, compute_max_);
  s.jitter_max_us = static_cast<double>(lateness_max_) * 1e-3;
  s.compute_max_us = static_cast<double>(compute_max_) * 1e-3;
  return s;
}

}  // namespace plexus::rt
