#include "bench/bench_group.hpp"

#include <signal.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "bench/bench_netns.hpp"
#include "bench/bench_runner.hpp"
#include "bench/bench_stats.hpp"
#include "child_process.hpp"
#include "cpu_affinity.hpp"
#include "external_program.hpp"
#include "plexus/scenario/format.hpp"

namespace plexus::cli::bench {
namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;
using plexus::scenario::format_number;

namespace {

std::vector<Json> json_lines(const std::string& text) {
  std::vector<Json> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line.front() == '{') try {
        out.push_back(Json::parse(line));
      } catch (const Json::parse_error&) {}
  return out;
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

}  // namespace

std::string read_file(const std::string& path) {
  std::ifstream f(path);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

Placement placement(const std::string& pin) {
  const std::vector<int> cpus = allowed_cpus();
  if (pin == "none" || cpus.empty()) return {};
  if (pin == "same" || cpus.size() < 2) return {cpus[0], cpus[0]};
  return {cpus[0], cpus[1]};
}

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
  reader_args.insert(reader_args.end(), {"--duration", format_number(plan_s + 60)});
  if (plant.delay_us > 0 && size_to_delay >= 0)
    reader_args.insert(reader_args.end(), {"--reply-delay-us", format_number(plant.delay_us), "--delay-size",
                                           std::to_string(size_to_delay)});
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
  for (double x : m.rates_hz) rates.push_back(format_number(x));
  writer_args.insert(writer_args.end(),
                     {"--sizes", join(sizes), "--rates", join(rates), "--seconds", format_number(m.seconds_per_phase),
                      "--throughput-seconds", format_number(m.throughput_seconds), "--timeout", "20"});
  if (two)
    writer_args.insert(writer_args.end(), {"--fault-cmd", ns->cut_command(), "--heal-cmd", ns->heal_command(),
                                           "--outage", format_number(m.outage_s)});
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

}  // namespace plexus::cli::bench
