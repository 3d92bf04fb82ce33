#include "bench/bench_runner.hpp"

#include <signal.h>
#include <sys/utsname.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>

#include "bench/bench_netns.hpp"
#include "bench/bench_stats.hpp"
#include "child_process.hpp"
#include "cpu_affinity.hpp"
#include "ddsperf.hpp"
#include "external_program.hpp"
#include "plexus/runtime/qos.hpp"

namespace plexus::cli::bench {
namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

std::string cell_id(const std::string& pair, const std::string& transport, const std::string& profile, int size,
                    const std::string& topology) {
  return pair + "/" + transport + "/" + profile + "/" + std::to_string(size) + "/" + topology;
}

namespace {

double now_s() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

std::vector<Json> json_lines(const std::string& text) {
  std::vector<Json> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line.front() == '{') try {
        out.push_back(Json::parse(line));
      } catch (const Json::parse_error&) {}
  return out;
}

std::string read_file(const std::string& path) {
  std::ifstream f(path);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

std::string last_line(const std::string& text) {
  std::string last, line;
  std::istringstream in(text);
  while (std::getline(in, line))
    if (!line.empty() && line.front() != '{') last = line;
  return last;
}

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ",") + x;
  return s;
}

std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// ---------------------------------------------------------------------------------------
// The machine

std::string first_match(const std::string& file, const std::string& key) {
  std::ifstream f(file);
  for (std::string line; std::getline(f, line);)
    if (line.rfind(key, 0) == 0) {
      const auto colon = line.find(':');
      std::string v = colon == std::string::npos ? "" : line.substr(colon + 1);
      v.erase(0, v.find_first_not_of(" \t"));
      return v;
    }
  return "";
}

Json load_average() {
  std::ifstream f("/proc/loadavg");
  double a = 0, b = 0, c = 0;
  f >> a >> b >> c;
  return Json::array({a, b, c});
}

std::string package_version(const std::string& package) {
  if (find_program("dpkg-query").empty()) return "unknown";
  std::string out;
  if (run_program(find_program("dpkg-query"), {"-W", "-f=${Version}", package}, out) != 0 || out.empty())
    return "unknown";
  return out;
}

Json machine() {
  char host[256] = {};
  gethostname(host, sizeof host - 1);
  utsname u{};
  uname(&u);
  const std::string mem = first_match("/proc/meminfo", "MemTotal");
  return {{"hostname", host},
          {"cpu_model", first_match("/proc/cpuinfo", "model name")},
          {"cpus", sysconf(_SC_NPROCESSORS_ONLN)},
          {"kernel", u.release},
          {"memory_mb", mem.empty() ? 0L : std::stol(mem) / 1024},
          {"load_before", load_average()},
          {"fastdds_version", package_version("libfastrtps2.9")},
          {"cyclonedds_version", package_version("libddsc0debian")},
          {"plexus_version", PLEXUS_VERSION}};
}

// ---------------------------------------------------------------------------------------
// One group: a bench_node writer and reader

struct Group {
  VendorPair pair;
  std::string transport, profile, topology;
  rt::QosProfile qos;
  int domain = 0;
  std::string pair_name() const { return pair.name(); }
};

struct SizeResult {
  std::map<double, std::vector<double>> oneway_raw_us, rtt_us;  ///< by rate
  std::map<double, long> sent, received;
  long flood_sent = 0, flood_received = 0;
  double flood_bytes = 0, flood_window_s = 0, flood_wall_s = 0;
  /// CPU seconds of each end and the writer's phase time: per rate, and of the flood.
  struct Cpu {
    double writer_s = 0, reader_s = 0, wall_s = 0;
  };
  std::map<double, Cpu> cpu;
  Cpu flood_cpu;
};

/// The CPUs of the writer and the reader (-1: not pinned), from Matrix::pin.
struct Placement {
  int writer = -1, reader = -1;
};

Placement placement(const std::string& pin) {
  const std::vector<int> cpus = allowed_cpus();
  if (pin == "none" || cpus.empty()) return {};
  if (pin == "same" || cpus.size() < 2) return {cpus[0], cpus[0]};
  return {cpus[0], cpus[1]};
}

struct GroupRun {
  bool ok = false;
  std::string reason;
  std::map<int, SizeResult> sizes;
  double offset_us = 0;
  Json recovery, deadline_after, liveliness_after;
};

GroupRun run_group(const Group& g, const Matrix& m, const NetnsPair* ns, const Plant& plant, const std::string& dir,
                   int size_to_delay) {
  GroupRun r;
  fs::create_directories(dir);
  const bool two = ns != nullptr;
  const std::string node = program_path("bench_node");
  auto argv = [&](int end, const std::string& role) {
    std::vector<std::string> a;
    if (two) a = ns->exec_prefix(end), a.push_back(node);
    const std::string dds = rt::to_string(end == 1 ? g.pair.writer : g.pair.reader);
    const std::string iface = two ? NetnsPair::address(end) : "127.0.0.1";
    const std::string peers = two ? std::string(NetnsPair::address(1)) + "," + NetnsPair::address(2) : "127.0.0.1";
    a.insert(a.end(), {role, "--dds", dds, "--domain", std::to_string(g.domain), "--qos-file", m.qos_file, "--profile",
                       g.profile, "--transport", g.transport, "--interface", iface, "--peers", peers, "--dir", dir});
    return a;
  };
  const std::string program = two ? find_program("ip") : node;
  // The plan's length, for the reader's own limit.
  const double plan_s =
      static_cast<double>(m.sizes.size()) *
          (static_cast<double>(m.rates_hz.size()) * (m.seconds_per_phase + 0.5) + m.throughput_seconds + 0.5) +
      10;
  auto reader_args = argv(2, "reader");
  reader_args.insert(reader_args.end(), {"--duration", number(plan_s + 60)});
  if (plant.delay_us > 0 && size_to_delay >= 0)
    reader_args.insert(reader_args.end(),
                       {"--reply-delay-us", number(plant.delay_us), "--delay-size", std::to_string(size_to_delay)});
  const std::string reader_log = dir + "/reader.log";
  const Placement cpus = placement(m.pin);
  pid_t reader = -1;
  {
    PinnedTo pinned(cpus.reader);  // the child inherits it
    reader = spawn_program(program, reader_args, {}, {.file = reader_log, .fd = -1});
  }
  auto writer_args = argv(1, "writer");
  std::vector<std::string> sizes, rates;
  for (int s : m.sizes) sizes.push_back(std::to_string(s));
  for (double x : m.rates_hz) rates.push_back(number(x));
  writer_args.insert(writer_args.end(),
                     {"--sizes", join(sizes), "--rates", join(rates), "--seconds", number(m.seconds_per_phase),
                      "--throughput-seconds", number(m.throughput_seconds), "--timeout", "20"});
  if (two)
    writer_args.insert(writer_args.end(), {"--fault-cmd", ns->cut_command(), "--heal-cmd", ns->heal_command(),
                                           "--outage", number(m.outage_s)});
  std::string wout;
  int wrc = 0;
  {
    PinnedTo pinned(cpus.writer);
    wrc = run_program(program, writer_args, wout, {}, true);
  }
  const std::vector<Json> wlines = json_lines(wout);
  const bool done = std::any_of(wlines.begin(), wlines.end(), [](const Json& j) { return j.contains("done"); });
  if (!done) kill(reader, SIGTERM);
  wait_program(reader);
  const std::vector<Json> rlines = json_lines(read_file(reader_log));
  if (!done) {
    r.reason = "bench_node writer exit " + std::to_string(wrc) + ": " + last_line(wout);
    return r;
  }
  std::map<int, Json> by_phase;
  Json events;
  for (const auto& j : rlines) {
    if (j.contains("phase")) by_phase[j["phase"].get<int>()] = j;
    if (j.contains("events")) events = j["events"];
  }
  if (events.is_null()) {
    r.reason = "bench_node reader printed no result: " + last_line(read_file(reader_log));
    return r;
  }
  // The clock offset from the smallest payload's first latency phase (the fastest round trips
  // are the most symmetric).
  int offset_size = INT32_MAX;
  for (const auto& w : wlines) {
    if (w.value("kind", "") != "latency") continue;
    const int phase = w["phase"].get<int>(), size = w["size"].get<int>();
    const double rate = w["rate_hz"].get<double>();
    SizeResult& s = r.sizes[size];
    const Json reader_phase = by_phase.count(phase) ? by_phase[phase] : Json::object();
    s.oneway_raw_us[rate] = read_samples_us(reader_phase.value("oneway_file", ""));
    s.rtt_us[rate] = read_samples_us(w.value("rtt_file", ""));
    s.sent[rate] = w["sent"].get<long>();
    s.received[rate] = reader_phase.value("received", 0L);
    s.cpu[rate] = {w["cpu_s"].get<double>(), reader_phase.value("cpu_s", 0.0), w["wall_s"].get<double>()};
    if (size < offset_size && w["pongs"].get<long>() > 0) {
      offset_size = size;
      r.offset_us = static_cast<double>(w["offset_ns"].get<long long>()) * 1e-3;
    }
  }
  for (const auto& w : wlines) {
    const std::string kind = w.value("kind", "");
    const int phase = w.value("phase", 0);
    const Json reader_phase = by_phase.count(phase) ? by_phase[phase] : Json::object();
    if (kind == "throughput") {
      SizeResult& s = r.sizes[w["size"].get<int>()];
      s.flood_sent = w["sent"].get<long>();
      s.flood_received = reader_phase.value("received", 0L);
      s.flood_bytes = reader_phase.value("bytes", 0.0);
      s.flood_window_s = reader_phase.value("window_s", 0.0);
      s.flood_wall_s = w["wall_s"].get<double>();
      s.flood_cpu = {w["cpu_s"].get<double>(), reader_phase.value("cpu_s", 0.0), w["wall_s"].get<double>()};
    } else if (kind == "burst" && w.contains("recovery")) {
      r.recovery = w["recovery"];
    }
  }
  r.deadline_after = events["deadline_after_s"];
  r.liveliness_after = events["liveliness_after_s"];
  r.ok = true;
  return r;
}

// ---------------------------------------------------------------------------------------
// The vendors' own tools, one host

struct VendorResult {
  std::string name;
  Json round_trip, throughput;  ///< null when not measured
};

VendorResult raw_fast(const Group& g, int size, double rate, const Matrix& m, const std::string& dir) {
  VendorResult v{"raw Fast DDS", nullptr, nullptr};
  const std::string d = std::to_string(m.domain);
  const int count = rate > 0 ? std::max(50, static_cast<int>(rate * m.seconds_per_phase)) : 2000;
  std::vector<std::string> base = {"--domain", d,
                                   "--depth",  std::to_string(g.qos.depth),
                                   "--size",   std::to_string(size),
                                   "--rate",   number(rate),
                                   "--count",  std::to_string(count)};
  if (g.qos.reliability == rt::QosProfile::Reliability::best_effort) base.push_back("--best-effort");
  if (g.transport == "shm") base.push_back("--shm");
  std::vector<std::string> pa = {"pong", "--duration", number(count / std::max(rate, 1000.0) + 30)};
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
      "ping", "--samples", samples, "--warmup", "10", "--duration", number(m.seconds_per_phase + 1)};
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

VendorResult ddsperf(const Group& g, int size, double rate, const Matrix& m) {
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

// ---------------------------------------------------------------------------------------
// Cells

Json cell_keys(const Group& g, int size, double loss, double delay_ms) {
  return {{"id", cell_id(g.pair_name(), g.transport, g.profile, size, g.topology)},
          {"pair", g.pair_name()},
          {"writer_dds", rt::to_string(g.pair.writer)},
          {"reader_dds", rt::to_string(g.pair.reader)},
          {"transport", g.transport},
          {"profile", g.profile},
          {"reliability", rt::to_string(g.qos.reliability)},
          {"size", size},
          {"topology", g.topology},
          {"loss_percent", g.topology == "two_ns" ? loss : 0.0},
          {"delay_ms", g.topology == "two_ns" ? delay_ms : 0.0}};
}

/// Why a group cannot run, or "".
std::string not_applicable(const Group& g, const std::string& topology_problem) {
  if (!topology_problem.empty()) return topology_problem;
  if (g.transport == "shm") {
    if (g.pair.writer != rt::Vendor::fast || g.pair.reader != rt::Vendor::fast)
      return "shared memory carries samples between Fast DDS participants only (Cyclone DDS 0.10 as Debian "
             "builds it has none; docs/runtime.md, Transports)";
    if (g.topology == "two_ns") return "two hosts share no memory";
  }
  return "";
}

Json cell_of(const Group& g, int size, const std::vector<GroupRun>& runs, const Matrix& m, bool first_size) {
  Json c = cell_keys(g, size, m.loss_percent, m.delay_ms);
  c["status"] = "ok";
  c["reason"] = "";
  // On one host both ends read one clock: the measured offset is shown, not applied (it is
  // the method's own error). Across the namespaces it is applied, as across hosts.
  double offset = 0;
  for (const auto& r : runs) offset += r.offset_us / static_cast<double>(runs.size());
  const double applied = g.topology == "two_ns" ? offset : 0.0;
  Json latency = Json::array();
  auto percent = [](const SizeResult::Cpu& used) {
    return Json{{"writer", used.wall_s > 0 ? 100 * used.writer_s / used.wall_s : 0.0},
                {"reader", used.wall_s > 0 ? 100 * used.reader_s / used.wall_s : 0.0}};
  };
  auto range = [](const std::vector<double>& v) {
    return v.size() > 1 ? *std::max_element(v.begin(), v.end()) - *std::min_element(v.begin(), v.end()) : 0.0;
  };
  const double headline = m.headline_rate();
  Json cpu_at_headline, spread_at_headline;
  for (double rate : m.rates_hz) {
    std::vector<double> oneway, rtt;
    long sent = 0, received = 0;
    double oneway_spread = 0, rtt_spread = 0;
    SizeResult::Cpu cpu;
    std::vector<double> p50s_oneway, p50s_rtt;
    for (const auto& r : runs) {
      const SizeResult& s = r.sizes.at(size);
      std::vector<double> ow = s.oneway_raw_us.count(rate) ? s.oneway_raw_us.at(rate) : std::vector<double>{};
      for (double& x : ow) x -= applied;
      const std::vector<double>& rt_us = s.rtt_us.count(rate) ? s.rtt_us.at(rate) : std::vector<double>{};
      oneway_spread = std::max(oneway_spread, median_spread(ow));
      rtt_spread = std::max(rtt_spread, median_spread(rt_us));
      p50s_oneway.push_back(distribution(ow)["p50"].get<double>());
      p50s_rtt.push_back(distribution(rt_us)["p50"].get<double>());
      oneway.insert(oneway.end(), ow.begin(), ow.end());
      rtt.insert(rtt.end(), rt_us.begin(), rt_us.end());
      sent += s.sent.count(rate) ? s.sent.at(rate) : 0;
      received += s.received.count(rate) ? s.received.at(rate) : 0;
      if (s.cpu.count(rate)) {
        const auto& c1 = s.cpu.at(rate);
        cpu = {cpu.writer_s + c1.writer_s, cpu.reader_s + c1.reader_s, cpu.wall_s + c1.wall_s};
      }
    }
    // Between chunks of each run, and between the runs.
    oneway_spread = std::max(oneway_spread, range(p50s_oneway));
    rtt_spread = std::max(rtt_spread, range(p50s_rtt));
    // Late: a sample that arrives after the next one is due (one-way latency over the period).
    long late = 0;
    if (rate > 0)
      for (double x : oneway) late += x > 1e6 / rate;
    latency.push_back({{"rate_hz", rate},
                       {"one_way_us", distribution(oneway)},
                       {"round_trip_us", distribution(rtt)},
                       {"sent", sent},
                       {"received", received},
                       {"lost", std::max(0L, sent - received)},
                       {"late", late},
                       {"cpu_percent", percent(cpu)},
                       {"spread", {{"one_way_p50_us", oneway_spread}, {"round_trip_p50_us", rtt_spread}}}});
    if (rate == headline || cpu_at_headline.is_null()) {
      cpu_at_headline = latency.back()["cpu_percent"];
      spread_at_headline = latency.back()["spread"];
    }
  }
  c["latency"] = latency;
  long f_sent = 0, f_recv = 0;
  double f_bytes = 0, f_window = 0, f_wall = 0;
  std::vector<double> rates_per_run;
  SizeResult::Cpu flood_cpu;
  for (const auto& r : runs) {
    const SizeResult& s = r.sizes.at(size);
    f_sent += s.flood_sent;
    f_recv += s.flood_received;
    f_bytes += s.flood_bytes;
    f_window += s.flood_window_s;
    f_wall += s.flood_wall_s;
    if (s.flood_window_s > 0) rates_per_run.push_back(static_cast<double>(s.flood_received) / s.flood_window_s);
    flood_cpu = {flood_cpu.writer_s + s.flood_cpu.writer_s, flood_cpu.reader_s + s.flood_cpu.reader_s,
                 flood_cpu.wall_s + s.flood_cpu.wall_s};
  }
  c["throughput"] = m.throughput_seconds > 0 && f_window > 0
                        ? Json{{"samples_per_s", static_cast<double>(f_recv) / f_window},
                               {"mb_per_s", f_bytes / f_window / 1e6},
                               {"sent", f_sent},
                               {"received", f_recv},
                               {"lost", std::max(0L, f_sent - f_recv)},
                               {"seconds", f_wall},
                               {"cpu_percent", percent(flood_cpu)}}
                        : Json(nullptr);
  // What the loop costs: the CPU at the summary's rate (each rate's is in its entry, the
  // saturation's in throughput).
  c["cpu_percent"] = cpu_at_headline;
  c["clock_offset_us"] = offset;
  c["clock_offset_applied"] = applied != 0.0;
  // Recovery and the QoS events are measured once per group: on its first size's cell.
  c["recovery"] = first_size && !runs.front().recovery.is_null() ? runs.front().recovery : Json(nullptr);
  Json events = {{"deadline", nullptr}, {"liveliness", nullptr}};
  if (first_size && g.qos.deadline_s > 0)
    events["deadline"] = {{"period_s", g.qos.deadline_s}, {"detected_after_s", runs.front().deadline_after}};
  if (first_size && g.qos.liveliness_lease_s > 0)
    events["liveliness"] = {{"lease_s", g.qos.liveliness_lease_s}, {"detected_after_s", runs.front().liveliness_after}};
  c["events"] = events;
  // The summary's rate's spreads (what --baseline compares), and the throughput's between runs.
  c["spread"] = spread_at_headline;
  c["spread"]["throughput_samples_per_s"] = range(rates_per_run);
  c["vendor_tool"] = nullptr;
  c["ratio"] = nullptr;
  return c;
}

const Json* headline(const Json& cell, double rate) {
  for (const auto& l : cell["latency"])
    if (l["rate_hz"].get<double>() == rate) return &l;
  return nullptr;
}

Json ratio_or_null(const Json& a, const Json& b) {
  if (!a.is_number() || !b.is_number() || !(b.get<double>() > 0)) return nullptr;
  return a.get<double>() / b.get<double>();
}

}  // namespace

Json run_bench(const RunOptions& o) {
  const Matrix& m = o.matrix;
  const double t0 = now_s();
  const std::time_t started = std::time(nullptr);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&started));
  Json run = {{"plexus_bench", 1}, {"started_utc", stamp}, {"duration_s", 0}, {"command", o.command}};
  run["machine"] = machine();
  Json pairs = Json::array();
  for (const auto& p : m.pairs) pairs.push_back(p.name());
  run["matrix"] = {{"pairs", pairs},
                   {"transports", m.transports},
                   {"profiles", m.profiles},
                   {"sizes", m.sizes},
                   {"rates_hz", m.rates_hz},
                   {"topologies", m.topologies},
                   {"loss_percent", m.loss_percent},
                   {"delay_ms", m.delay_ms},
                   {"outage_s", m.outage_s},
                   {"seconds_per_phase", m.seconds_per_phase},
                   {"throughput_seconds", m.throughput_seconds},
                   {"repeats", m.repeats},
                   {"vendor_tools", m.vendor_tools},
                   {"pin", m.pin},
                   {"qos_file", m.qos_file}};
  const auto profiles = rt::QosProfiles::load(m.qos_file);
  const std::string scratch = (fs::temp_directory_path() / ("plexus_bench_" + std::to_string(getpid()))).string();
  Json cells = Json::array();
  Json link_counters = Json::object();
  std::map<std::string, VendorResult> vendor_cache;
  const double rate = m.headline_rate();  // the vendor tools' (0: back to back)
  int group_index = 0;
  for (const auto& topology : m.topologies) {
    std::unique_ptr<NetnsPair> ns;
    std::string topology_problem;
    if (topology == "two_ns") {
      if (NetnsPair::possible(topology_problem)) try {
          ns = std::make_unique<NetnsPair>(m.delay_ms);
          ns->set_loss(m.loss_percent);
        } catch (const std::exception& e) {
          topology_problem = e.what();
          ns.reset();
        }
    }
    for (const auto& pair : m.pairs)
      for (const auto& transport : m.transports)
        for (const auto& profile : m.profiles) {
          Group g{pair, transport, profile, topology, profiles.get(profile), m.domain};
          const std::string why = not_applicable(g, topology_problem);
          if (!why.empty()) {
            for (int size : m.sizes) {
              Json c = cell_keys(g, size, m.loss_percent, m.delay_ms);
              c["status"] = "not_applicable";
              c["reason"] = why;
              cells.push_back(c);
            }
            continue;
          }
          ++group_index;
          const std::string group = g.pair_name() + "/" + transport + "/" + profile + "/" + topology;
          std::fprintf(stderr, "plexus bench: %s ...", group.c_str());
          std::fflush(stderr);
          const double tg = now_s();
          std::vector<GroupRun> runs;
          std::string failure;
          for (int k = 0; k < m.repeats && failure.empty(); ++k) {
            int delay_size = -1;
            for (int size : m.sizes)
              if (o.plant.cell == cell_id(g.pair_name(), transport, profile, size, topology)) delay_size = size;
            const std::string dir = scratch + "/g" + std::to_string(group_index) + "_" + std::to_string(k);
            GroupRun r = run_group(g, m, ns.get(), o.plant, dir, delay_size);
            fs::remove_all(dir);
            if (!r.ok) failure = r.reason;
            runs.push_back(std::move(r));
          }
          std::fprintf(stderr, " %.1f s%s\n", now_s() - tg, failure.empty() ? "" : (" FAILED: " + failure).c_str());
          if (ns) link_counters[group] = ns->counters();
          if (ns) ns->set_loss(m.loss_percent);  // counters from zero for the next group
          for (std::size_t i = 0; i < m.sizes.size(); ++i) {
            const int size = m.sizes[i];
            if (!failure.empty()) {
              Json c = cell_keys(g, size, m.loss_percent, m.delay_ms);
              c["status"] = "failed";
              c["reason"] = failure;
              cells.push_back(c);
              continue;
            }
            Json c = cell_of(g, size, runs, m, i == 0);
            // The vendor's own tool, same pair of vendors, one host, the headline rate.
            const bool same = g.pair.writer == g.pair.reader;
            if (m.vendor_tools && same && topology == "one_host") {
              const std::string key = g.pair_name() + transport + rt::to_string(g.qos.reliability) +
                                      std::to_string(g.qos.depth) + "/" + std::to_string(size);
              if (!vendor_cache.count(key)) {
                fs::create_directories(scratch);
                vendor_cache[key] =
                    g.pair.writer == rt::Vendor::fast ? raw_fast(g, size, rate, m, scratch) : ddsperf(g, size, rate, m);
              }
              const VendorResult& v = vendor_cache[key];
              c["vendor_tool"] = {{"name", v.name}, {"round_trip_us", v.round_trip}, {"throughput", v.throughput}};
              const Json* h = headline(c, m.headline_rate());
              Json ratio = {{"round_trip_p50", nullptr}, {"round_trip_p99", nullptr}, {"throughput", nullptr}};
              if (h && !v.round_trip.is_null()) {
                ratio["round_trip_p50"] = ratio_or_null((*h)["round_trip_us"]["p50"], v.round_trip["p50"]);
                ratio["round_trip_p99"] = ratio_or_null((*h)["round_trip_us"]["p99"], v.round_trip["p99"]);
              }
              if (!c["throughput"].is_null() && !v.throughput.is_null())
                ratio["throughput"] = ratio_or_null(c["throughput"]["samples_per_s"], v.throughput["samples_per_s"]);
              c["ratio"] = ratio;
            }
            cells.push_back(c);
          }
        }
  }
  fs::remove_all(scratch);
  run["cells"] = cells;
  run["link_counters"] = link_counters;
  run["machine"]["load_after"] = load_average();
  run["duration_s"] = now_s() - t0;
  return run;
}

}  // namespace plexus::cli::bench
