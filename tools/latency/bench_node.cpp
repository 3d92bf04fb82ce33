// bench_node: the two ends of one group of `plexus bench` cells (tools/plexus/bench,
// docs/qos-bench.md). Both ends go through the plexus runtime, either vendor, any QoS
// profile, on loopback or on the interface of a network namespace.
//
//   bench_node reader --dds cyclone --profile sensor --dir D
//   bench_node writer --dds fast --profile sensor --sizes 64,65536 --rates 1000,0 --dir D
//
// The writer runs a plan of phases; each sample says which (header data_time_ns = phase << 32
// | index), so the reader needs no plan:
//   latency     pings on bench/ping at a rate on absolute deadlines (rate 0: the next ping
//               when the last pong is back); the reader stamps each ping's one-way latency
//               (its wall clock minus the ping's publish time) and answers on bench/pong with
//               the ping's publish time as origin; the writer stamps the round trip.
//   throughput  samples on bench/flood back to back; the reader counts them.
//   burst       (--fault-cmd) pings at the first rate while a command cuts the link for
//               --outage seconds; the writer measures what came back and when.
//   tail        pings for 0.3 s, then the writer leaves without a goodbye (_exit), as a
//               crashed process does: the reader times its deadline and liveliness events
//               from the last sample it got.
// Each end prints one JSON line per phase and writes its samples (ns, one per line) into
// --dir: rtt_<phase>.txt (writer), oneway_<phase>.txt (reader). `plexus bench` turns them
// into the cells' figures. Sample buffers are allocated before the first phase.
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <mutex>
#include <thread>

#include "pingpong_common.hpp"
#include "plexus/base/cli_style.hpp"
#include "plexus/base/clock.hpp"
#include "plexus/base/comma_list.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/base/logging.hpp"
#include "plexus/runtime/participant.hpp"

namespace {

using namespace plexus;
using Json = nlohmann::ordered_json;

std::atomic<bool> g_stop{false};
void on_signal(int) { g_stop = true; }

constexpr int kTailPhase = 0xFFFF;
constexpr int64_t kIndexMask = 0xFFFFFFFF;
int64_t code(int phase, int64_t index) { return (static_cast<int64_t>(phase) << 32) | index; }
int phase_of(int64_t c) { return static_cast<int>(c >> 32); }

double cpu_s() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec) * 1e-6;
}

void sleep_s(double s) { std::this_thread::sleep_for(std::chrono::microseconds(static_cast<int64_t>(s * 1e6))); }

template <class It>
void write_samples(const std::string& path, It begin, It end) {
  std::ofstream f(path);
  if (!f) throw std::runtime_error("cannot write " + path);
  for (It it = begin; it != end; ++it) f << *it << '\n';
}

struct Options {
  std::string role, dds = "fast", qos_file, profile = "sensor", transport = "auto", interface = "127.0.0.1";
  std::string peers, sizes = "64", rates = "1000", dir = ".", fault_cmd, heal_cmd, log_level = "error";
  int domain = 190, max_participants = 0;
  double seconds = 1.0, throughput_seconds = 1.0, outage = 0.2, timeout = 20, duration = 600;
  double reply_delay_us = 0;  ///< reader: spin this long before taking a ping in (a planted regression)
  int delay_size = -1;        ///< reader: only pings of this payload size (-1: every ping)
};

// ---------------------------------------------------------------------------------------
// reader end

struct PhaseCount {
  int64_t received = 0, bytes = 0, first_m = 0, last_m = 0;
  double cpu_first = 0, cpu_last = 0;
  std::size_t oneway_begin = 0, oneway_end = 0;  ///< its slice of the one-way buffer
};

int run_reader(rt::Participant& p, const rt::QosProfile& qos, const Options& o) {
  std::mutex mu;
  std::vector<PhaseCount> phases(kTailPhase + 1);
  std::vector<int64_t> oneway(4'000'000);  // every ping of the run (one-way ns), in arrival order
  std::size_t used = 0;
  int64_t last_arrival = 0, deadline_after = -1, liveliness_after = -1;
  bool tail_seen = false;
  int current = -1;  // the phase whose samples came last
  auto note = [&](int phase, std::size_t bytes, int64_t oneway_ns, bool ping) {
    const int64_t now = monotonic_ns();
    std::lock_guard<std::mutex> lk(mu);
    PhaseCount& c = phases[static_cast<std::size_t>(phase)];
    if (c.received == 0) {  // a phase starts: the one before it ends (its CPU up to here)
      c.first_m = now;
      c.cpu_first = cpu_s();
      c.oneway_begin = c.oneway_end = used;
      if (current >= 0) phases[static_cast<std::size_t>(current)].cpu_last = c.cpu_first;
      current = phase;
    }
    ++c.received;
    c.bytes += static_cast<int64_t>(bytes);
    c.last_m = now;
    if (ping && used < oneway.size() && c.oneway_end == used) oneway[used++] = oneway_ns, c.oneway_end = used;
    last_arrival = now;
    deadline_after = liveliness_after = -1;  // events count from the last sample
    tail_seen = tail_seen || phase == kTailPhase;
  };
  p.on_event([&](const rt::Event& e) {
    if (e.on_writer || e.topic != "bench/ping") return;
    const bool deadline = e.kind == rt::EventKind::deadline_missed;
    const bool lost = e.kind == rt::EventKind::liveliness_changed && !e.alive;
    if (!deadline && !lost) return;
    const int64_t now = monotonic_ns();
    std::lock_guard<std::mutex> lk(mu);
    int64_t& after = deadline ? deadline_after : liveliness_after;
    if (last_arrival > 0 && after < 0) after = now - last_arrival;
  });
  auto pong = p.publisher<msg::LatencyProbe>("bench/pong", qos);
  auto ping = p.subscriber<msg::LatencyProbe>("bench/ping", qos);
  auto flood = p.subscriber<msg::LatencyProbe>("bench/flood", qos);
  msg::LatencyProbe ping_buffer, flood_buffer;
  ping_buffer.payload().reserve(latency::kMaxPayload);
  flood_buffer.payload().reserve(latency::kMaxPayload);
  const int64_t spin_ns = static_cast<int64_t>(o.reply_delay_us * 1e3);
  ping.on_sample(
      [&](msg::LatencyProbe& m, const rt::SampleMeta&) {
        if (spin_ns > 0 && (o.delay_size < 0 || m.payload().size() == static_cast<std::size_t>(o.delay_size)))
          for (const int64_t until = monotonic_ns() + spin_ns; monotonic_ns() < until;) {}
        const int64_t arrived = wall_time_ns();
        note(phase_of(m.header().data_time_ns()), m.payload().size(), arrived - m.header().publish_time_ns(), true);
        m.header().origin_time_ns(m.header().publish_time_ns());  // the ping's publish time goes back
        pong.publish(m);
      },
      std::move(ping_buffer));
  flood.on_sample(
      [&](msg::LatencyProbe& m, const rt::SampleMeta&) {
        note(phase_of(m.header().data_time_ns()), m.payload().size(), 0, false);
      },
      std::move(flood_buffer));

  // The end: after the writer's tail, once each event its QoS asks for has come (or long
  // after it should have).
  const double wait_s = std::max(3 * qos.deadline_s, 2 * qos.liveliness_lease_s) + 1.0;
  const int64_t hard_end = monotonic_ns() + static_cast<int64_t>(o.duration * 1e9);
  while (!g_stop && monotonic_ns() < hard_end) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    std::lock_guard<std::mutex> lk(mu);
    if (!tail_seen) continue;
    const bool deadline_done = qos.deadline_s <= 0 || deadline_after >= 0;
    const bool liveliness_done = qos.liveliness_lease_s <= 0 || liveliness_after >= 0;
    const double quiet = static_cast<double>(monotonic_ns() - last_arrival) * 1e-9;
    if ((deadline_done && liveliness_done && quiet > 0.3) || quiet > wait_s) break;
  }
  std::lock_guard<std::mutex> lk(mu);
  for (int ph = 0; ph < kTailPhase; ++ph) {
    const PhaseCount& c = phases[static_cast<std::size_t>(ph)];
    if (c.received == 0) continue;
    const std::string file = o.dir + "/oneway_" + std::to_string(ph) + ".txt";
    write_samples(file, oneway.begin() + static_cast<std::ptrdiff_t>(c.oneway_begin),
                  oneway.begin() + static_cast<std::ptrdiff_t>(c.oneway_end));
    const double wall = static_cast<double>(c.last_m - c.first_m) * 1e-9;
    std::printf("%s\n", Json{{"phase", ph},
                             {"received", c.received},
                             {"bytes", c.bytes},
                             {"window_s", wall},
                             {"cpu_s", c.cpu_last > 0 ? c.cpu_last - c.cpu_first : 0.0},
                             {"oneway_file", c.oneway_end > c.oneway_begin ? file : ""}}
                            .dump()
                            .c_str());
  }
  auto seconds_or_null = [](int64_t ns) { return ns >= 0 ? Json(static_cast<double>(ns) * 1e-9) : Json(nullptr); };
  std::printf("%s\n", Json{{"events",
                            {{"deadline_after_s", seconds_or_null(deadline_after)},
                             {"liveliness_after_s", seconds_or_null(liveliness_after)}}},
                           {"cpu_s", cpu_s()}}
                          .dump()
                          .c_str());
  std::fflush(stdout);
  return 0;
}

// ---------------------------------------------------------------------------------------
// writer end

/// What the writer knows of each ping of the current phase. The pong callback (a DDS
/// thread) fills arrivals under the lock; the main thread reads after the phase.
struct Pings {
  std::vector<int64_t> t1_m, t1_w, t4_m, t4_w, t3_w;
  std::mutex mu;
  std::condition_variable cv;
  int phase = 0;
  int64_t pongs = 0, last_index = -1;
  explicit Pings(std::size_t n) : t1_m(n), t1_w(n), t4_m(n), t4_w(n), t3_w(n) {}
  std::size_t capacity() const { return t1_m.size(); }
  void start(int ph, std::size_t n) {
    std::lock_guard<std::mutex> lk(mu);
    phase = ph;
    pongs = 0;
    last_index = -1;
    std::fill_n(t4_m.begin(), n, 0);
  }
  void arrived(const msg::LatencyProbe& m) {
    const int64_t now_m = monotonic_ns(), now_w = wall_time_ns();
    const int64_t c = m.header().data_time_ns(), k = c & kIndexMask;
    {
      std::lock_guard<std::mutex> lk(mu);
      if (phase_of(c) != phase || k >= static_cast<int64_t>(capacity()) || t4_m[static_cast<std::size_t>(k)] != 0)
        return;
      const auto i = static_cast<std::size_t>(k);
      t4_m[i] = now_m;
      t4_w[i] = now_w;
      t3_w[i] = m.header().publish_time_ns();
      ++pongs;
      last_index = k;
    }
    cv.notify_one();
  }
  /// Unpaced: waits for ping k's pong until `deadline_m`.
  bool wait_for(int64_t k, int64_t deadline_m) {
    std::unique_lock<std::mutex> lk(mu);
    while (t4_m[static_cast<std::size_t>(k)] == 0) {
      const int64_t left = deadline_m - monotonic_ns();
      if (left <= 0) return false;
      cv.wait_for(lk, std::chrono::nanoseconds(left));
    }
    return true;
  }
  /// Waits until `sent` pongs are in, or `grace_s`.
  void drain(int64_t sent, double grace_s) {
    const int64_t end = monotonic_ns() + static_cast<int64_t>(grace_s * 1e9);
    std::unique_lock<std::mutex> lk(mu);
    while (pongs < sent && monotonic_ns() < end) cv.wait_for(lk, std::chrono::milliseconds(5));
  }
};

class Writer {
 public:
  Writer(rt::Participant& p, const rt::QosProfile& qos, const Options& o, std::size_t capacity)
      : o_(o), pings_(capacity) {
    ping_ = p.publisher<msg::LatencyProbe>("bench/ping", qos);
    flood_ = p.publisher<msg::LatencyProbe>("bench/flood", qos);
    pong_ = p.subscriber<msg::LatencyProbe>("bench/pong", qos);
    msg::LatencyProbe in;
    in.payload().reserve(latency::kMaxPayload);
    pong_.on_sample([this](msg::LatencyProbe& m, const rt::SampleMeta&) { pings_.arrived(m); }, std::move(in));
    out_.payload().reserve(latency::kMaxPayload);
  }

  bool matched(double timeout_s) {
    const int64_t end = monotonic_ns() + static_cast<int64_t>(timeout_s * 1e9);
    while (ping_.matched_count() == 0 || flood_.matched_count() == 0 || pong_.matched_count() == 0) {
      if (g_stop || monotonic_ns() > end) return false;
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    // Matched here is not matched there: the reader's pong writer may not know this end's
    // pong reader yet (discovery repairs its own losses on a lossy link, Fast DDS's every
    // few seconds). Phase 0 pings until three pongs have come back: the loop is closed.
    pings_.start(0, pings_.capacity());
    out_.payload().assign(8, 0);
    for (int64_t k = 0;; ++k) {
      if (g_stop || monotonic_ns() > end || static_cast<std::size_t>(k) >= pings_.capacity()) return false;
      out_.header().origin_time_ns(0);
      out_.header().data_time_ns(code(0, k));
      ping_.publish(out_);
      sleep_s(0.02);
      std::lock_guard<std::mutex> lk(pings_.mu);
      if (pings_.pongs >= 3) break;
    }
    sleep_s(0.2);
    return true;
  }

  /// Pings at `rate` (0: back to back) for `seconds`; with a fault, the link is cut from
  /// 0.3 s for `outage` s by `fault_cmd` / `heal_cmd` on a thread of their own.
  void latency(int phase, int size, double rate, double seconds, bool burst) {
    const std::size_t n =
        std::min(pings_.capacity(), rate > 0 ? static_cast<std::size_t>(rate * seconds) + 1 : pings_.capacity());
    pings_.start(phase, n);
    out_.payload().assign(static_cast<std::size_t>(size), 0x5a);
    std::atomic<int64_t> fault_m{0}, heal_m{0};
    std::thread fault;
    const int64_t t0 = monotonic_ns();
    if (burst)
      fault = std::thread([&] {
        sleep_s(0.3);
        if (std::system(o_.fault_cmd.c_str()) != 0) std::fprintf(stderr, "bench_node: fault command failed\n");
        fault_m = monotonic_ns();
        sleep_s(o_.outage);
        if (std::system(o_.heal_cmd.c_str()) != 0) std::fprintf(stderr, "bench_node: heal command failed\n");
        heal_m = monotonic_ns();
      });
    const double cpu0 = cpu_s();
    const int64_t period = rate > 0 ? static_cast<int64_t>(1e9 / rate) : 0;
    const int64_t end = t0 + static_cast<int64_t>(seconds * 1e9);
    int64_t next = t0, sent = 0;
    while (static_cast<std::size_t>(sent) < n && !g_stop) {
      if (period > 0) {
        latency::sleep_until_ns(next);
        next += period;
        for (const int64_t now = monotonic_ns(); next < now;) next += period;  // overrun: keep the phase
      }
      const int64_t now = monotonic_ns();
      if (now >= end) break;
      const auto i = static_cast<std::size_t>(sent);
      pings_.t1_m[i] = now;
      pings_.t1_w[i] = wall_time_ns();
      out_.header().origin_time_ns(0);
      out_.header().data_time_ns(code(phase, sent));
      ping_.publish(out_);
      ++sent;
      if (period == 0) pings_.wait_for(sent - 1, now + 100'000'000);
    }
    const double wall = static_cast<double>(monotonic_ns() - t0) * 1e-9, cpu = cpu_s() - cpu0;
    if (fault.joinable()) fault.join();
    pings_.drain(sent, burst ? 1.5 : 0.5);
    report_latency(phase, burst ? "burst" : "latency", size, rate, sent, wall, cpu, fault_m, heal_m);
  }

  /// Samples on bench/flood back to back for `seconds`.
  void throughput(int phase, int size, double seconds) {
    out_.payload().assign(static_cast<std::size_t>(size), 0xa5);
    const double cpu0 = cpu_s();
    const int64_t t0 = monotonic_ns(), end = t0 + static_cast<int64_t>(seconds * 1e9);
    int64_t sent = 0, refused = 0;
    for (int64_t k = 0; monotonic_ns() < end && !g_stop; ++k) {
      out_.header().origin_time_ns(0);
      out_.header().data_time_ns(code(phase, k));
      if (flood_.publish(out_))
        ++sent;
      else
        ++refused;
    }
    const double wall = static_cast<double>(monotonic_ns() - t0) * 1e-9, cpu = cpu_s() - cpu0;
    std::printf("%s\n", Json{{"phase", phase},
                             {"kind", "throughput"},
                             {"size", size},
                             {"sent", sent},
                             {"refused", refused},
                             {"wall_s", wall},
                             {"cpu_s", cpu}}
                            .dump()
                            .c_str());
    std::fflush(stdout);
    sleep_s(0.5);  // the reader drains before the next phase
  }

  /// Pings for 0.3 s at 1 kHz: the reader's last samples before this end leaves.
  void tail() {
    out_.payload().assign(8, 0);
    int64_t next = monotonic_ns();
    for (int k = 0; k < 300 && !g_stop; ++k) {
      latency::sleep_until_ns(next += 1'000'000);
      out_.header().origin_time_ns(0);
      out_.header().data_time_ns(code(kTailPhase, k));
      ping_.publish(out_);
    }
  }

 private:
  void report_latency(int phase, const char* kind, int size, double rate, int64_t sent, double wall, double cpu,
                      int64_t fault_m, int64_t heal_m) {
    std::lock_guard<std::mutex> lk(pings_.mu);
    const auto n = static_cast<std::size_t>(sent);
    // Round trips, and the clock offset (reader minus writer) from the fastest round trip:
    // t3 - (t1 + t4) / 2, the reader answering at once (t2 = t3), as NTP does.
    std::vector<int64_t> rtt;
    rtt.reserve(n);
    int64_t best = INT64_MAX, offset = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (pings_.t4_m[i] == 0) continue;
      const int64_t r = pings_.t4_m[i] - pings_.t1_m[i];
      rtt.push_back(r);
      if (r < best) best = r, offset = pings_.t3_w[i] - (pings_.t1_w[i] + pings_.t4_w[i]) / 2;
    }
    const std::string file = o_.dir + "/rtt_" + std::to_string(phase) + ".txt";
    write_samples(file, rtt.begin(), rtt.end());
    Json j = {{"phase", phase},      {"kind", kind},        {"size", size},   {"rate_hz", rate}, {"sent", sent},
              {"pongs", rtt.size()}, {"offset_ns", offset}, {"wall_s", wall}, {"cpu_s", cpu},    {"rtt_file", file}};
    if (fault_m > 0 && heal_m > 0) {
      // Pings sent while the link was cut: repaired (their pong came) or lost. Recovery: from
      // the heal to the last pong of a ping sent before it, or, if none came after the heal,
      // to the first pong after it (the stream flows again).
      int64_t repaired = 0, lost = 0, last_old = 0, first_after = 0;
      for (std::size_t i = 0; i < n; ++i) {
        const int64_t t1 = pings_.t1_m[i], t4 = pings_.t4_m[i];
        if (t1 >= fault_m && t1 < heal_m) (t4 != 0 ? repaired : lost) += 1;
        if (t4 > heal_m && t1 < heal_m) last_old = std::max(last_old, t4);
        if (t4 > heal_m && (first_after == 0 || t4 < first_after)) first_after = t4;
      }
      const int64_t back = last_old != 0 ? last_old : first_after;
      j["recovery"] = {{"outage_s", static_cast<double>(heal_m - fault_m) * 1e-9},
                       {"recovery_s", back != 0 ? Json(static_cast<double>(back - heal_m) * 1e-9) : Json(nullptr)},
                       {"repaired", repaired},
                       {"lost", lost}};
    }
    std::printf("%s\n", j.dump().c_str());
    std::fflush(stdout);
  }

  const Options& o_;
  Pings pings_;
  rt::Publisher<msg::LatencyProbe> ping_, flood_;
  rt::Subscriber<msg::LatencyProbe> pong_;
  msg::LatencyProbe out_;
};

std::vector<double> numbers(const std::string& list, const char* what) {
  std::vector<double> v;
  for (const auto& s : split_comma_list(list)) {
    try {
      std::size_t used = 0;
      v.push_back(std::stod(s, &used));
      if (used != s.size()) throw std::invalid_argument(s);
    } catch (const std::exception&) {
      throw InputError(std::string(what) + ": '" + s + "' is not a number");
    }
  }
  if (v.empty()) throw InputError(std::string(what) + ": empty list");
  return v;
}

int run_writer(rt::Participant& p, const rt::QosProfile& qos, const Options& o) {
  std::vector<int> sizes;
  for (double s : numbers(o.sizes, "--sizes")) {
    if (!(s >= 0 && s <= latency::kMaxPayload)) throw InputError("--sizes: each must be in 0..1048576 bytes");
    sizes.push_back(static_cast<int>(s));
  }
  const std::vector<double> rates = numbers(o.rates, "--rates");
  for (double r : rates)
    if (!(r >= 0 && r <= 100000)) throw InputError("--rates: each must be in 0..100000 Hz (0: unpaced)");
  const bool burst = !o.fault_cmd.empty();
  if (burst && o.heal_cmd.empty()) throw InputError("--fault-cmd needs --heal-cmd");
  // Room for every ping of the longest phase: the fastest rate, or unpaced at up to 100 k/s.
  double most = 0;
  for (double r : rates) most = std::max(most, r > 0 ? r * o.seconds : 100000 * o.seconds);
  if (burst) most = std::max(most, rates.front() * (0.3 + o.outage + 1.0));
  Writer w(p, qos, o, static_cast<std::size_t>(most) + 16);
  if (!w.matched(o.timeout)) {
    std::fprintf(stderr, "bench_node writer: no reader matched within %.0f s\n", o.timeout);
    return 1;
  }
  int phase = 1;
  for (int size : sizes) {
    for (double rate : rates) w.latency(phase++, size, rate, o.seconds, false);
    if (o.throughput_seconds > 0) w.throughput(phase++, size, o.throughput_seconds);
  }
  if (burst) {
    const double rate = rates.front() > 0 ? rates.front() : 1000;
    w.latency(phase++, sizes.front(), rate, 0.3 + o.outage + 1.0, true);
  }
  std::printf("{\"done\": true}\n");
  std::fflush(stdout);
  w.tail();
  // Gone without a goodbye, as a crashed writer: the reader's events come from the QoS.
  std::_Exit(0);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"bench_node: one end of a plexus bench group (docs/qos-bench.md)"};
  app.set_version_flag("--version", std::string("bench_node") + " " + PLEXUS_VERSION);
  Options o;
  app.add_option("role", o.role, "writer or reader")->required()->check(CLI::IsMember({"writer", "reader"}));
  app.add_option("--dds", o.dds, "DDS vendor: fast or cyclone");
  app.add_option("--domain", o.domain, "DDS domain id")->check(CLI::Range(0, 232));
  app.add_option("--qos-file", o.qos_file, "QoS profiles (default: deploy/qos.yaml)");
  app.add_option("--profile", o.profile, "QoS profile name");
  app.add_option("--transport", o.transport, "auto, udp or shm (docs/runtime.md, Transports)");
  app.add_option("--interface", o.interface, "address of the interface DDS uses");
  app.add_option("--peers", o.peers, "unicast discovery peers, comma-separated (default: the interface)");
  app.add_option("--max-participants", o.max_participants, "participants per host (0: the runtime's default)");
  app.add_option("--sizes", o.sizes, "writer: payload sizes in bytes, comma-separated");
  app.add_option("--rates", o.rates, "writer: ping rates in Hz, comma-separated (0: unpaced)");
  app.add_option("--seconds", o.seconds, "writer: seconds per latency phase")->check(CLI::Range(0.05, 60.0));
  app.add_option("--throughput-seconds", o.throughput_seconds, "writer: seconds per throughput phase (0: none)")
      ->check(CLI::Range(0.0, 60.0));
  app.add_option("--fault-cmd", o.fault_cmd, "writer: shell command that cuts the link (a burst phase)");
  app.add_option("--heal-cmd", o.heal_cmd, "writer: shell command that restores it");
  app.add_option("--outage", o.outage, "writer: seconds the link stays cut")->check(CLI::Range(0.01, 10.0));
  app.add_option("--timeout", o.timeout, "writer: seconds to wait for the reader");
  app.add_option("--duration", o.duration, "reader: seconds at most");
  app.add_option("--reply-delay-us", o.reply_delay_us, "reader: spin before taking each ping in (a planted delay)")
      ->check(CLI::Range(0.0, 100000.0));
  app.add_option("--delay-size", o.delay_size, "reader: delay only pings of this payload size (-1: all)");
  app.add_option("--dir", o.dir, "directory for the sample files");
  app.add_option("--log-level", o.log_level, "trace, debug, info, warn, error, critical or off");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return plexus::parse_error_exit(app, e, "bench_node");
  }
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  try {
    init_logging("bench_" + o.role, "", o.log_level);
    rt::ParticipantOptions po;
    po.vendor = rt::parse_vendor(o.dds);
    po.domain_id = o.domain;
    po.name = "bench_" + o.role;
    po.network.transport = rt::parse_transport(o.transport);
    po.network.interface_address = o.interface;
    po.network.peers = o.peers.empty() ? std::vector<std::string>{o.interface} : split_comma_list(o.peers);
    if (o.max_participants > 0) po.network.max_participants_per_host = o.max_participants;
    const auto profiles = rt::QosProfiles::load(o.qos_file.empty() ? rt::default_qos_file() : o.qos_file);
    const auto& qos = profiles.get(o.profile);
    auto participant = rt::Participant::create(po);
    return o.role == "reader" ? run_reader(*participant, qos, o) : run_writer(*participant, qos, o);
  } catch (const InputError& e) {
    std::fprintf(stderr, "bench_node: error: %s\n", e.what());
    return kExitBadInput;
  }
}
