#include "latency_loop.hpp"

#include <algorithm>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <exception>
#include <mutex>
#include <regex>
#include <sstream>
#include <thread>
#include <vector>

#include "cpu_affinity.hpp"
#include "external_program.hpp"
#include "latency_stats.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/runtime/periodic_loop.hpp"

namespace plexus::cli {
namespace {

using Json = nlohmann::ordered_json;

// cyclictest's histogram: 1 us buckets 0..kHistUs-1, the overflow counted in the last one.
constexpr std::size_t kHistUs = 2000;

// The CPUs this process may run on, as a cpuset list ("0,1"), and the first of them.
// The CPUs cyclictest's main thread may use (--mainaffinity) and the first of them.
struct Allowed {
  std::string list;
  int first = 0;
};

Allowed allowed_cpu_list() {
  const std::vector<int> cpus = allowed_cpus();
  if (cpus.empty()) return {"0", 0};
  Allowed a{"", cpus.front()};
  for (int c : cpus) a.list += (a.list.empty() ? "" : ",") + std::to_string(c);
  return a;
}

// The plexus loop in its own SCHED_FIFO thread (the settings must not stick to the main
// thread), run in segments on demand: the thread blocks between them while cyclictest runs.
class PlexusSide {
 public:
  PlexusSide(const LoopOpts& o, int cpu, std::size_t samples) : lateness_(samples) {
    thread_ = std::thread([this, o, cpu] { body(o, cpu); });
  }
  ~PlexusSide() {
    {
      std::lock_guard lk(m_);
      quit_ = true;
    }
    cv_.notify_all();
    thread_.join();
  }

  /// Runs `n` more iterations; rethrows what the loop threw (a bad option: exit 2).
  void run(std::size_t n) {
    std::unique_lock lk(m_);
    ordered_ += n;
    cv_.notify_all();
    cv_.wait(lk, [&] { return done_ == ordered_ || failed_; });
    if (failed_) std::rethrow_exception(failed_);
  }

  std::vector<double>& lateness() { return lateness_; }
  std::string refused() {
    std::lock_guard lk(m_);
    return refused_;
  }

 private:
  void body(const LoopOpts& o, int cpu) {
    try {
      rt::PeriodicLoop loop({.rate_hz = o.rate,
                             .priority = o.priority,
                             .cpu = cpu,
                             .lock_memory = !o.no_mlock,
                             .timer_slack_ns = o.timer_slack,
                             .cpu_dma_latency_us = o.cpu_dma_latency});
      std::unique_lock lk(m_);
      refused_ = loop.refused();
      for (;;) {
        cv_.wait(lk, [&] { return quit_ || ordered_ > done_; });
        if (quit_) return;
        const std::size_t from = done_, to = ordered_;
        lk.unlock();
        // The same loop as cyclictest's: absolute deadlines from one period after the start,
        // lateness stored into a preallocated buffer, nothing else between the wake-ups.
        loop.start();
        for (std::size_t i = from; i < to; ++i) {
          const auto t = loop.wait_next();
          lateness_[i] = static_cast<double>(t.wake_ns - t.deadline_ns) * 1e-3;
          loop.end_compute();
        }
        lk.lock();
        done_ = to;
        cv_.notify_all();
      }
    } catch (...) {
      std::lock_guard lk(m_);
      failed_ = std::current_exception();
      cv_.notify_all();
    }
  }

  std::vector<double> lateness_;  // preallocated: the loop only stores
  std::mutex m_;
  std::condition_variable cv_;
  std::size_t ordered_ = 0, done_ = 0;
  bool quit_ = false;
  std::exception_ptr failed_;
  std::string refused_;
  std::thread thread_;
};

// cyclictest's 1 us histogram into `hist`; its "Max Latencies" (exact us) into `max`.
// Returns false if the output has no histogram.
bool add_cyclictest_histogram(const std::string& out, std::vector<double>& hist, double& max) {
  static const std::regex bucket(R"(^(\d+)\s+(\d+)\s*$)"), overflow(R"(# Histogram Overflows:\s*(\d+))"),
      maxl(R"(# Max Latencies:\s*(\d+))");
  double total = 0;
  std::istringstream in(out);
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (std::regex_match(line, m, bucket)) {
      const auto k = static_cast<std::size_t>(std::stoul(m[1]));
      const double c = std::stod(m[2]);
      if (k < hist.size()) hist[k] += c;
      total += c;
    } else if (std::regex_search(line, m, overflow)) {
      hist.back() += std::stod(m[1]);
      total += std::stod(m[1]);
    } else if (std::regex_search(line, m, maxl)) {
      max = std::max(max, std::stod(m[1]));
    }
  }
  return total > 0;
}

}  // namespace

int run_loop(const LoopOpts& o) {
  if (!(o.rate > 0 && o.rate <= 100000)) throw InputError("--rate: must be in (0, 100000] Hz");
  if (!(o.duration > 0 && o.duration <= 3600)) throw InputError("--duration: must be in (0, 3600] seconds");
  if (o.priority < 0 || o.priority > 99) throw InputError("--priority: must be in 0..99 (0: no real-time priority)");
  if (o.cpu_dma_latency < -1 || o.cpu_dma_latency > 10'000'000)
    throw InputError("--cpu-dma-latency: must be -1 (no request) or in 0..10000000 us");
  if (o.timer_slack < 0) throw InputError("--timer-slack: must be >= 0 ns (0: keep the default)");
  const auto n = static_cast<std::size_t>(o.rate * o.duration);
  if (o.rounds < 1 || o.rounds > 100 || static_cast<std::size_t>(o.rounds) > n)
    throw InputError("--rounds: must be in 1..100 and at most rate x duration (" + std::to_string(n) + ")");
  make_out_dir(o.out);
  const Allowed allowed = allowed_cpu_list();
  // cyclictest pins its thread even without -a (to the first allowed CPU): the plexus loop
  // runs on the same CPU, and a CPU the machine lacks is refused by the loop (exit 2).
  const int cpu = o.cpu >= 0 ? o.cpu : allowed.first;

  std::string ct;
  if (!o.no_cyclictest) {
    ct = find_program("cyclictest");
    if (ct.empty())
      std::fprintf(stderr, "plexus latency loop: warning: cyclictest not found (install rt-tests); plexus only\n");
  }
  PlexusSide plexus(o, cpu, n);
  std::vector<double> hist_p(kHistUs + 1, 0.0), hist_c(kHistUs + 1, 0.0);
  double ct_max = 0;
  bool have_cyclictest = !ct.empty(), prio_refused = false;
  int ct_prio = o.priority;
  auto run_cyclictest = [&](std::size_t samples) {
    if (!have_cyclictest) return;
    const int interval_us = static_cast<int>(std::lround(1e6 / o.rate));
    auto args = [&](int prio) {
      // The plexus loop's settings: priority, CPU (its main thread left free, as plexus's),
      // memory locking, the CPU wake-up latency request; -l: the same number of wake-ups.
      std::vector<std::string> a = {"-q",
                                    "-t1",
                                    "-p" + std::to_string(prio),
                                    "-i" + std::to_string(interval_us),
                                    "-l" + std::to_string(samples),
                                    "-h" + std::to_string(kHistUs),
                                    "-a" + std::to_string(cpu),
                                    "--mainaffinity=" + allowed.list};
      if (!o.no_mlock) a.push_back("-m");
      a.push_back(o.cpu_dma_latency < 0 ? std::string("--laptop") : "--latency=" + std::to_string(o.cpu_dma_latency));
      return a;
    };
    std::string out;
    int rc = run_program(ct, args(ct_prio), out, {}, true);
    if (rc != 0 && ct_prio > 0) {
      std::fprintf(stderr, "plexus latency loop: warning: cyclictest refused priority %d; running it without\n",
                   ct_prio);
      ct_prio = 0;
      out.clear();
      rc = run_program(ct, args(0), out, {}, true);
    }
    if (rc != 0 || !add_cyclictest_histogram(out, hist_c, ct_max)) {
      std::fprintf(stderr, "plexus latency loop: warning: cyclictest gave no histogram (exit %d)\n", rc);
      have_cyclictest = false;
    }
  };
  // Rounds in ABBA order: plexus first in even rounds, cyclictest first in odd ones.
  for (int r = 0; r < o.rounds; ++r) {
    const std::size_t from = n * static_cast<std::size_t>(r) / o.rounds,
                      to = n * static_cast<std::size_t>(r + 1) / o.rounds;
    if (r % 2 == 1) run_cyclictest(to - from);
    plexus.run(to - from);
    if (r == 0) {
      const std::string refused = plexus.refused();
      prio_refused = refused.find("SCHED_FIFO") != std::string::npos;
      if (prio_refused) ct_prio = 0;  // both without it, as documented
    }
    if (r % 2 == 0) run_cyclictest(to - from);
  }
  const std::string refused = plexus.refused();

  // Both through the same 1 us histogram (cyclictest truncates to whole us) and the same
  // nearest-rank percentiles; the max is each one's exact maximum.
  double p_max = 0;
  for (double us : plexus.lateness()) {
    const auto k = static_cast<std::size_t>(std::clamp(us, 0.0, static_cast<double>(kHistUs)));
    hist_p[k] += 1;
    p_max = std::max(p_max, us);
  }
  Percentiles a = histogram_percentiles(hist_p), b;
  a.max = p_max;
  if (have_cyclictest) {
    b = histogram_percentiles(hist_c);
    if (ct_max > 0) b.max = ct_max;
  }

  Json result = {{"rate_hz", o.rate},
                 {"duration_s", o.duration},
                 {"priority", prio_refused ? 0 : o.priority},
                 {"cpu", cpu},
                 {"rounds", o.rounds},
                 {"cpu_dma_latency_us", o.cpu_dma_latency},
                 {"timer_slack_ns", o.timer_slack},
                 {"mlockall", !o.no_mlock},
                 {"plexus", pct_json(a)}};
  if (!refused.empty()) result["refused"] = refused;
  if (have_cyclictest) {
    result["cyclictest"] = pct_json(b);
    result["ratio"] = {{"mean", a.mean / b.mean},
                       {"p50", a.p50 / std::max(b.p50, 1.0)},
                       {"p99", a.p99 / std::max(b.p99, 1.0)},
                       {"max", a.max / b.max}};
  }
  if (!o.out.empty()) {
    std::vector<Series> series = {{"plexus PeriodicLoop", hist_p, true}};
    if (have_cyclictest) series.push_back({"cyclictest", hist_c, true});
    const std::string png = o.out + "/loop_" + std::to_string(static_cast<int>(o.rate)) + "hz.png";
    write_histogram_png(png, "wake-up lateness at " + std::to_string(static_cast<int>(o.rate)) + " Hz", series);
    result["png"] = png;
  }
  if (o.json) {
    std::printf("%s\n", result.dump().c_str());
    return 0;
  }
  std::printf(
      "plexus latency loop: %g Hz for %g s in %d rounds, CPU %d, SCHED_FIFO priority %d, %s, CPU wake-up latency "
      "request %s, timer slack %s%s\n",
      o.rate, o.duration, o.rounds, cpu, prio_refused ? 0 : o.priority, o.no_mlock ? "no mlockall" : "mlockall",
      o.cpu_dma_latency < 0 ? "none" : (std::to_string(o.cpu_dma_latency) + " us").c_str(),
      o.timer_slack > 0 ? (std::to_string(o.timer_slack) + " ns").c_str() : "default",
      refused.empty() ? "" : (" (refused: " + refused + ")").c_str());
  if (have_cyclictest) {
    print_compare("wake-up lateness", a, b, "cyclictest", true);
  } else {
    print_compare("wake-up lateness", a, Percentiles{}, "-", false);
  }
  std::printf("(both: whole-us histogram as cyclictest's, nearest rank; max exact)\n");
  if (result.contains("png")) std::printf("histogram: %s\n", result["png"].get<std::string>().c_str());
  return 0;
}

}  // namespace plexus::cli
