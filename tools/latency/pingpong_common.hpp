// Shared by pingpong_node (plexus) and raw_fast_pingpong (plain Fast DDS): options, the
// preallocated round-trip buffer and the one JSON result line both print, so that
// `plexus latency pingpong` compares like with like.
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <mutex>
#include <string>
#include <vector>

namespace plexus::latency {

/// The largest payload: LatencyProbe's bound (idl/plexus/msg/latency_probe.idl).
constexpr int kMaxPayload = 1 << 20;

struct PingPongOptions {
  std::string role;
  int domain = 180;
  int size = 0;        ///< payload bytes after the header
  double rate = 1000;  ///< pings per second; 0: next ping as soon as the pong arrives
  int count = 2000;
  int warmup = 100;
  double timeout = 15;  ///< seconds to wait for the peer to match
  double duration = 0;  ///< pong: seconds to run (0: until SIGTERM); ping: at most (0: none)
  std::string samples;  ///< ping: write every round trip (us), one per line
};

inline void add_pingpong_options(CLI::App& app, PingPongOptions& o) {
  app.add_option("role", o.role, "ping or pong")->required()->check(CLI::IsMember({"ping", "pong"}));
  app.add_option("--domain", o.domain, "DDS domain id")->check(CLI::Range(0, 232));
  app.add_option("--size", o.size, "payload bytes")->check(CLI::Range(0, kMaxPayload));
  app.add_option("--rate", o.rate, "pings per second (0: back to back)")->check(CLI::Range(0.0, 100000.0));
  app.add_option("--count", o.count, "measured round trips")->check(CLI::Range(1, 10'000'000));
  app.add_option("--warmup", o.warmup, "unmeasured round trips first")->check(CLI::Range(0, 1'000'000));
  app.add_option("--timeout", o.timeout, "seconds to wait for the peer");
  app.add_option("--duration", o.duration,
                 "pong: seconds to run (0: until SIGTERM); ping: seconds at most (0: until --count)");
  app.add_option("--samples", o.samples, "ping: file for every round trip in microseconds");
}

inline int64_t mono_ns() {
  timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
}

inline void sleep_until_ns(int64_t t) {
  timespec ts{static_cast<time_t>(t / 1'000'000'000), static_cast<long>(t % 1'000'000'000)};
  clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr);
}

/// Prints the result line and writes the samples file. rtt_ns: measured round trips.
inline void print_result(const char* implementation, const PingPongOptions& o, std::vector<int64_t>& rtt_ns, int sent,
                         double elapsed_s) {
  if (!o.samples.empty()) {
    std::ofstream f(o.samples);
    for (int64_t v : rtt_ns) f << static_cast<double>(v) * 1e-3 << '\n';
  }
  std::sort(rtt_ns.begin(), rtt_ns.end());
  auto pct = [&](double q) {
    if (rtt_ns.empty()) return 0.0;
    const auto k = static_cast<std::size_t>(std::ceil(q * static_cast<double>(rtt_ns.size())));
    return static_cast<double>(rtt_ns[std::min(rtt_ns.size() - 1, k == 0 ? 0 : k - 1)]) * 1e-3;
  };
  double sum = 0;
  for (int64_t v : rtt_ns) sum += static_cast<double>(v);
  const double n = static_cast<double>(rtt_ns.size());
  nlohmann::ordered_json j = {{"implementation", implementation},
                              {"size", o.size},
                              {"rate_hz", o.rate},
                              {"sent", sent},
                              {"received", rtt_ns.size()},
                              {"rtt_mean_us", n > 0 ? sum / n * 1e-3 : 0.0},
                              {"rtt_p50_us", pct(0.50)},
                              {"rtt_p90_us", pct(0.90)},
                              {"rtt_p99_us", pct(0.99)},
                              {"rtt_max_us", rtt_ns.empty() ? 0.0 : static_cast<double>(rtt_ns.back()) * 1e-3},
                              {"round_trips_per_s", elapsed_s > 0 ? n / elapsed_s : 0.0}};
  std::printf("%s\n", j.dump().c_str());
}

/// Where a ping side's pongs land: the thread that delivers a pong (the DDS receive thread,
/// in the reader's data callback) stamps its arrival here, as ddsperf's ping does in its
/// data-available listener. A round trip then ends when the pong is in the process, not when
/// a waiting thread has been scheduled to look at it (that wake-up is the application's,
/// on either vendor; issue 33, item 9: it was most of plexus's gap to ddsperf). The waiting
/// thread only learns that it came. No allocation.
class PongArrivals {
 public:
  /// On the delivering thread: the pong of ping `index` is here.
  void arrived(int64_t index) {
    const int64_t t = mono_ns();
    {
      std::lock_guard<std::mutex> lk(mu_);
      index_ = index;
      t_ns_ = t;
    }
    cv_.notify_one();
  }
  /// The arrival time of the pong of ping `index`, waiting for it until `deadline_ns`
  /// (monotonic); -1 if it did not come by then. Pongs of older pings are passed over.
  int64_t wait_for(int64_t index, int64_t deadline_ns) {
    std::unique_lock<std::mutex> lk(mu_);
    while (index_ != index) {
      const int64_t left = deadline_ns - mono_ns();
      if (left <= 0) return -1;
      cv_.wait_for(lk, std::chrono::nanoseconds(left));
    }
    return t_ns_;
  }

 private:
  std::mutex mu_;
  std::condition_variable cv_;
  int64_t index_ = -1, t_ns_ = 0;
};

/// The ping loop of both programs, so they measure the same way: ping k is sent by send(k)
/// at --rate on absolute deadlines (back to back at rate 0); its round trip is from just
/// before send(k) to the pong's arrival stamped by `pongs` (1 s at most). Round trips go into
/// a buffer reserved before the loop. Prints the result line; returns 0 if every measured
/// ping came back.
template <class Send>
int run_ping(const char* implementation, const PingPongOptions& o, Send&& send, PongArrivals& pongs) {
  std::vector<int64_t> rtt;
  rtt.reserve(static_cast<std::size_t>(o.count));
  const int total = o.warmup + o.count;
  const int64_t period = o.rate > 0 ? static_cast<int64_t>(1e9 / o.rate) : 0;
  int sent = 0;
  int64_t next = mono_ns(), t_start = 0;
  // A lost pong costs its 1 s wait: a lossy run ends at --duration rather than after count s.
  const int64_t stop_at = o.duration > 0 ? next + static_cast<int64_t>(o.duration * 1e9) : INT64_MAX;
  for (int k = 0; k < total && mono_ns() < stop_at; ++k) {
    if (period > 0) {
      sleep_until_ns(next);
      next += period;
      const int64_t now = mono_ns();
      while (next < now) next += period;  // overrun: skip periods, keep the phase
    }
    if (k == o.warmup) t_start = mono_ns();
    const int64_t t0 = mono_ns();
    if (!send(k)) break;
    if (k >= o.warmup) ++sent;
    const int64_t arrival = pongs.wait_for(k, std::min(t0 + 1'000'000'000, stop_at));
    if (arrival >= 0 && k >= o.warmup) rtt.push_back(arrival - t0);
  }
  const double elapsed = static_cast<double>(mono_ns() - t_start) * 1e-9;
  print_result(implementation, o, rtt, sent, elapsed);
  return static_cast<int>(rtt.size()) == o.count ? 0 : 1;
}

}  // namespace plexus::latency
