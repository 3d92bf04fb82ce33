#include "bench/bench_vendor_tools.hpp"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "bench/bench_stats.hpp"
#include "child_process.hpp"
#include "cpu_affinity.hpp"
#include "ddsperf.hpp"
#include "external_program.hpp"
#include "plexus/scenario/format.hpp"

namespace plexus::cli::bench {
namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;
using plexus::scenario::format_number;

VendorResult raw_fast_baseline(const Group& g, int size, double rate, const Matrix& m, const std::string& dir) {
  VendorResult v{"raw Fast DDS", nullptr, nullptr};
  const std::string d = std::to_string(m.domain);
  const int count = rate > 0 ? std::max(50, static_cast<int>(rate * m.seconds_per_phase)) : 2000;
  std::vector<std::string> base = {"--domain", d,
                                   "--depth",  std::to_string(g.qos.depth),
                                   "--size",   std::to_string(size),
                                   "--rate",   format_number(rate),
                                   "--count",  std::to_string(count)};
  if (g.qos.reliability == rt::QosProfile::Reliability::best_effort) base.push_back("--best-effort");
  if (g.transport == "shm") base.push_back("--shm");
  std::vector<std::string> pa = {"pong", "--duration", format_number(count / std::max(rate, 1000.0) + 30)};
  pa.insert(pa.end(), base.begin(), base.end());
  const Placement cpus = placement(m.pin);
  pid_t pong = -1;
  {
    PinnedTo pinned(cpus.reader);
    pong = spawn("raw_fast_pingpong", pa);
  }
  const std::string samples = dir + "/raw_fast_rtt.txt";
  // Ten unmeasured pings (not 100: at 1 MiB each lost one costs its 1 s wait), then the phase.
  std::vector<std::string> qa = {
      "ping", "--samples", samples, "--warmup", "10", "--duration", format_number(m.seconds_per_phase + 1)};
  qa.insert(qa.end(), base.begin(), base.end());
  std::string out;
  {
    PinnedTo pinned(cpus.writer);
    run_capture("raw_fast_pingpong", qa, out);
  }
  stop(pong);
  std::vector<double> us;
  std::ifstream f(samples);
  for (double x; f >> x;) us.push_back(x);
  if (!us.empty()) v.round_trip = distribution(us);
  return v;
}

VendorResult ddsperf_baseline(const Group& g, int size, double rate, const Matrix& m) {
  VendorResult v{"ddsperf", nullptr, nullptr};
  const std::string exe = find_program("ddsperf");
  if (exe.empty()) return v;
  const std::vector<std::string> env = {ddsperf_uri()};
  std::vector<std::string> base = {"-i", std::to_string(m.domain)};
  if (g.qos.reliability == rt::QosProfile::Reliability::best_effort) base.push_back("-u");
  const std::string sz = std::to_string(std::max(size, 12));  // ddsperf's smallest sample
  const Placement cpus = placement(m.pin);
  const std::string secs = std::to_string(std::max(2, static_cast<int>(std::ceil(m.seconds_per_phase)) + 1));
  // Round trips: ping at the cell's rate against a pong.
  {
    std::vector<std::string> pa = base;
    pa.insert(pa.end(), {"-D", std::to_string(std::stoi(secs) + 12), "pong"});
    pid_t pong = -1;
    {
      PinnedTo pinned(cpus.reader);
      pong = spawn_program(exe, pa, env, {.file = "/dev/null", .fd = -1});
    }
    std::vector<std::string> qa = base;
    qa.insert(qa.end(), {"-Qminmatch:1", "-Qinitwait:10", "-D", secs, "ping"});
    if (rate > 0) qa.push_back(std::to_string(static_cast<long>(rate)) + "Hz");  // else back to back
    qa.insert(qa.end(), {"size", sz});
    std::string out;
    {
      PinnedTo pinned(cpus.writer);
      run_program(exe, qa, out, env, true);
    }
    kill(pong, SIGTERM);
    wait_program(pong);
    try {
      const Json p = parse_ddsperf_ping(out);
      v.round_trip = {{"count", p["received"]}, {"p50", p["rtt_p50_us"]}, {"p90", p["rtt_p90_us"]},
                      {"p99", p["rtt_p99_us"]}, {"p999", nullptr},        {"max", p["rtt_max_us"]},
                      {"cdf", Json::array()}};
    } catch (const std::exception&) {}
  }
  // Saturation: pub as fast as it can against a sub; the fastest whole second.
  if (m.throughput_seconds > 0) {
    std::vector<std::string> sa = base;
    sa.insert(sa.end(), {"-D", std::to_string(std::stoi(secs) + 2), "sub"});
    const std::string sub_log =
        (fs::temp_directory_path() / ("plexus_bench_ddsperf_" + std::to_string(getpid()))).string();
    pid_t sub = -1;
    {
      PinnedTo pinned(cpus.reader);
      sub = spawn_program(exe, sa, env, {.file = sub_log, .fd = -1});
    }
    std::vector<std::string> pa = base;
    pa.insert(pa.end(), {"-Qminmatch:1", "-Qinitwait:10", "-D", secs, "pub", "size", sz});
    std::string out;
    {
      PinnedTo pinned(cpus.writer);
      run_program(exe, pa, out, env, true);
    }
    kill(sub, SIGTERM);
    wait_program(sub);
    v.throughput = parse_ddsperf_sub(read_file(sub_log));
    fs::remove(sub_log);
  }
  return v;
}

}  // namespace plexus::cli::bench
