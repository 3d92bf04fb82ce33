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
  while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) == EINTR) {
  }
}

double percentile_us(std::vector<int64_t>& v, std::size_t n, double q) {
  if (n == 0) return 0.0;
  const auto k = static_cast<std::size_t>(q * static_cast<double>(n - 1) + 0.5);
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.begin() + static_cast<std::ptrdiff_t>(n));
  return static_cast<double>(v[k]) * 1e-3;
}

}  // namespace

PeriodicLoop::PeriodicLoop(const LoopOptions& o) {
  if (!(o.rate_hz > 0.0 && o.rate_hz <= 100'000.0))
    throw InputError("loop rate must be in (0, 100000] Hz, got " + std::to_string(o.rate_hz));
  if (o.priority < 0 || o.priority > 99) throw InputError("loop priority must be in 0..99, got " + std::to_string(o.priority));
  if (o.stats_window < 16) throw InputError("loop stats_window must be >= 16");
  if (o.timer_slack_ns < 0) throw InputError("loop timer_slack_ns must be >= 0 (0: keep), got " + std::to_string(o.timer_slack_ns));
  if (o.cpu_dma_latency_us < -1 || o.cpu_dma_latency_us > 10'000'000)
    throw InputError("loop cpu_dma_latency_us must be -1 (none) or in 0..10000000, got " +
                     std::to_string(o.cpu_dma_latency_us));
  period_ns_ = static_cast<int64_t>(1e9 / o.rate_hz + 0.5);
  lateness_.assign(o.stats_window, 0);
  compute_.assign(o.stats_window, 0);
  scratch_.assign(o.stats_window, 0);

  // A refusal the system may lift: a warning, with the advice that fits why it was refused.
  auto refuse = [this](const std::string& what, int err, const char* capability, const char* limit) {
    const std::string msg = what + " refused (" + std::strerror(err) + ")";
    refused_ += (refused_.empty() ? "" : "; ") + msg;
    if (err == EPERM || err == EACCES)
      spdlog::warn("{}: the loop runs without it. Grant {} or raise {} in /etc/security/limits.conf to enable it.", msg,
                   capability, limit);
    else
      spdlog::warn("{}: the loop runs without it.", msg);
  };
  // A CPU that does not exist is a wrong argument, not a missing permission.
  const long cpus = sysconf(_SC_NPROCESSORS_CONF);
  if (o.cpu >= 0 && cpus > 0 && o.cpu >= cpus)
    throw InputError("loop CPU " + std::to_string(o.cpu) + ": no such CPU (this machine has CPUs 0.." +
                     std::to_string(cpus - 1) + ")");
  if (o.lock_memory && mlockall(MCL_CURRENT | MCL_FUTURE) != 0) refuse("mlockall", errno, "CAP_IPC_LOCK", "memlock");
  if (o.timer_slack_ns > 0 && prctl(PR_SET_TIMERSLACK, static_cast<unsigned long>(o.timer_slack_ns), 0, 0, 0) != 0)
    refuse("timer slack " + std::to_string(o.timer_slack_ns) + " ns", errno, "CAP_SYS_NICE", "rtprio");
  if (o.cpu_dma_latency_us >= 0) {
    // The kernel keeps the request while the file stays open (Documentation/power/pm_qos_interface).
    dma_latency_fd_ = open("/dev/cpu_dma_latency", O_RDWR | O_CLOEXEC);
    const auto value = static_cast<int32_t>(o.cpu_dma_latency_us);
    if (dma_latency_fd_ < 0 || write(dma_latency_fd_, &value, sizeof value) != static_cast<ssize_t>(sizeof value)) {
      refuse("CPU wake-up latency request of " + std::to_string(o.cpu_dma_latency_us) + " us (/dev/cpu_dma_latency)",
             errno, "root access to /dev/cpu_dma_latency", "nothing (the file is root's)");
      if (dma_latency_fd_ >= 0) close(dma_latency_fd_);
      dma_latency_fd_ = -1;
    }
  }
  if (o.cpu >= 0) {
    cpu_set_t set;
    CPU_ZERO(&set);
    CPU_SET(o.cpu, &set);
    if (sched_setaffinity(0, sizeof(set), &set) != 0)
      refuse("CPU affinity to CPU " + std::to_string(o.cpu), errno, "CAP_SYS_NICE", "rtprio");
  }
  if (o.priority > 0) {
    sched_param sp{};
    sp.sched_priority = o.priority;
    if (sched_setscheduler(0, SCHED_FIFO, &sp) != 0)
      refuse("SCHED_FIFO priority " + std::to_string(o.priority), errno, "CAP_SYS_NICE", "rtprio");
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
  const int64_t late = wake_ns_ - next_deadline_ns_;
  lateness_[count_ % lateness_.size()] = late;
  lateness_max_ = std::max(lateness_max_, late);
  return Tick{index_, next_deadline_ns_, wake_ns_};
}

void PeriodicLoop::end_compute() {
  const int64_t now = monotonic_ns();
  const int64_t took = now - wake_ns_;
  compute_[count_ % compute_.size()] = took;
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

LoopStats PeriodicLoop::stats() {
  LoopStats s;
  s.iterations = count_;
  s.overruns = overruns_;
  const std::size_t n = std::min(count_, lateness_.size());
  std::copy_n(lateness_.begin(), n, scratch_.begin());
  s.jitter_p50_us = percentile_us(scratch_, n, 0.50);
  s.jitter_p99_us = percentile_us(scratch_, n, 0.99);
  std::copy_n(compute_.begin(), n, scratch_.begin());
  s.compute_p50_us = percentile_us(scratch_, n, 0.50);
  s.compute_p99_us = percentile_us(scratch_, n, 0.99);
  s.jitter_max_us = static_cast<double>(lateness_max_) * 1e-3;
  s.compute_max_us = static_cast<double>(compute_max_) * 1e-3;
  return s;
}

}  // namespace plexus::rt
