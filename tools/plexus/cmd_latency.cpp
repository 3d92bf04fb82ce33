// plexus latency pingpong | loop | pipeline: transport round trips against the vendors' own
// tools, periodic-loop wake-up jitter against cyclictest, and per-hop latency of a recorded
// (or live) system from the header times. Each writes PNG histograms with --out DIR.
#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "child_process.hpp"
#include "command.hpp"
#include "cpu_affinity.hpp"
#include "ddsperf.hpp"
#include "external_program.hpp"
#include "latency_loop.hpp"
#include "latency_stats.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/runtime/qos.hpp"
#include "plexus/runtime/transport.hpp"
#include "plexus/runtime/vendor.hpp"
#include "recording.hpp"
#include "topic_discovery.hpp"

namespace plexus::cli {
namespace fs = std::filesystem;
namespace {

using Json = nlohmann::ordered_json;

std::string temp_path(const std::string& stem) {
  return (fs::temp_directory_path() / ("plexus_" + stem + "_" + std::to_string(getpid()))).string();
}

std::vector<double> read_numbers(const std::string& path) {
  std::vector<double> v;
  std::ifstream f(path);
  for (double x; f >> x;) v.push_back(x);
  return v;
}

// ---------------------------------------------------------------------------------------
// pingpong

struct PingOpts {
  std::string dds = "fast", peer_dds, profile = "latency", qos_file, out, transport = "auto", pin = "auto";
  int size = 0, count = 2000, domain = 180;
  double rate = 1000;
  bool json = false, no_baseline = false;
};

Json parse_result(const std::string& out, int rc, const std::string& who) {
  std::istringstream in(out);
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line.front() == '{') return Json::parse(line);
  throw std::runtime_error(who + " produced no result (exit " + std::to_string(rc) + ")");
}

Percentiles pct_of_result(const Json& r) {
  Percentiles p;
  p.count = r.value("received", 0);
  p.mean = r.value("rtt_mean_us", 0.0);
  p.p50 = r.value("rtt_p50_us", 0.0);
  p.p90 = r.value("rtt_p90_us", 0.0);
  p.p99 = r.value("rtt_p99_us", 0.0);
  p.max = r.value("rtt_max_us", 0.0);
  return p;
}

/// Where the ping and the pong run (--pin), the same for plexus and the vendor's baseline.
/// On this 2-vCPU virtual machine the round trip is decided by where the kernel puts the two
/// processes' receiving threads: a wake-up across CPUs costs about 30 us more per hop than
/// one on the same CPU. Unpinned, plexus's processes (more threads) and ddsperf's were placed
/// differently, and the p50 ratio read 1.4-1.8 although the paths cost the same: pinned alike,
/// 0.69-0.72 on one CPU and 1.00-1.14 across two (docs/performance.md, "Ping-pong").
struct Placement {
  int ping = -1, pong = -1;  ///< CPU of each side; -1: not pinned
};

Placement placement(const std::string& pin) {
  const std::vector<int> cpus = allowed_cpus();
  if (pin == "none") return {};
  if (cpus.empty()) throw std::runtime_error("--pin: cannot read this process's CPUs");
  if (pin == "same") return {cpus[0], cpus[0]};
  if (pin == "split" && cpus.size() < 2) throw InputError("--pin split: needs 2 CPUs, this process may use 1");
  if (pin == "split" || pin == "auto")
    return cpus.size() < 2 ? Placement{cpus[0], cpus[0]} : Placement{cpus[0], cpus[1]};
  throw InputError("--pin: must be auto, split, same or none, got '" + pin + "'");
}

int run_pingpong(const PingOpts& o) {
  const rt::Vendor vendor = rt::parse_vendor(o.dds, "--dds");
  const std::string peer = o.peer_dds.empty() ? o.dds : o.peer_dds;
  const rt::Vendor peer_vendor = rt::parse_vendor(peer, "--peer-dds");
  const rt::Transport transport = rt::parse_transport(o.transport, "--transport");
  // What carries the samples: shared memory only between two Fast DDS participants of this
  // host (Cyclone DDS stays on UDP, docs/runtime.md, Transports); the baseline uses the same.
  const bool shm = rt::fast_shared_memory(transport) && vendor == rt::Vendor::fast && peer_vendor == rt::Vendor::fast;
  const std::string qos_file = o.qos_file.empty() ? rt::default_qos_file() : o.qos_file;
  const auto qos = rt::QosProfiles::load(qos_file).get(o.profile);
  if (o.size < 0 || o.size > (1 << 20))
    throw InputError("--size: must be in 0..1048576 bytes, got " + std::to_string(o.size));
  if (!(o.rate >= 0 && o.rate <= 100000)) throw InputError("--rate: must be in 0..100000 Hz (0: back to back)");
  if (o.count < 1 || o.count > 10'000'000) throw InputError("--count: must be in 1..10000000");
  if (o.domain < 0 || o.domain > 231) throw InputError("--domain: must be in 0..231 (the baseline uses domain + 1)");
  const Placement cpus = placement(o.pin);
  make_out_dir(o.out);
  const std::string d = std::to_string(o.domain), d2 = std::to_string(o.domain + 1);
  // Each side starts while this process runs on its CPU, and inherits it.
  auto spawn_on = [](int cpu, auto&& start) {
    PinnedTo pinned(cpu);
    return start();
  };
  const double expected_s = o.rate > 0 ? (o.count + 100) / o.rate : o.count * 0.002;
  const std::string pong_duration = std::to_string(static_cast<int>(expected_s + 40));
  std::vector<std::string> common = {"--size",  std::to_string(o.size), "--rate", std::to_string(o.rate),
                                     "--count", std::to_string(o.count)};

  // plexus: pingpong_node ping (--dds) against pingpong_node pong (--peer-dds).
  const std::string samples = temp_path("pingpong_samples");
  auto args = [&](const char* role, const std::string& vendor_name, const std::string& domain) {
    std::vector<std::string> a = {role,     "--dds",     vendor_name, "--domain",    domain,     "--qos-file",
                                  qos_file, "--profile", o.profile,   "--transport", o.transport};
    a.insert(a.end(), common.begin(), common.end());
    return a;
  };
  auto pong_args = args("pong", peer, d);
  pong_args.insert(pong_args.end(), {"--duration", pong_duration});
  const pid_t pong = spawn_on(cpus.pong, [&] { return spawn("pingpong_node", pong_args); });
  auto ping_args = args("ping", o.dds, d);
  ping_args.insert(ping_args.end(), {"--samples", samples});
  std::string out;
  const int rc = spawn_on(cpus.ping, [&] { return run_capture("pingpong_node", ping_args, out); });
  stop(pong);
  const Json plexus_r = parse_result(out, rc, "pingpong_node ping");
  std::vector<double> plexus_samples = read_numbers(samples);
  fs::remove(samples);

  // The vendor's own baseline, same machine, same run.
  Json vendor_r;
  std::vector<double> vendor_samples;
  std::string vendor_name;
  if (!o.no_baseline) {
    if (vendor == rt::Vendor::fast) {
      vendor_name = "raw Fast DDS";
      std::vector<std::string> base = {"--domain", d2, "--depth", std::to_string(qos.depth)};
      base.insert(base.end(), common.begin(), common.end());
      if (qos.reliability == rt::QosProfile::Reliability::best_effort) base.push_back("--best-effort");
      if (shm) base.push_back("--shm");
      std::vector<std::string> pa = {"pong", "--duration", pong_duration};
      pa.insert(pa.end(), base.begin(), base.end());
      const pid_t rpong = spawn_on(cpus.pong, [&] { return spawn("raw_fast_pingpong", pa); });
      std::vector<std::string> qa = {"ping", "--samples", samples};
      qa.insert(qa.end(), base.begin(), base.end());
      std::string rout;
      const int rrc = spawn_on(cpus.ping, [&] { return run_capture("raw_fast_pingpong", qa, rout); });
      stop(rpong);
      vendor_r = parse_result(rout, rrc, "raw_fast_pingpong ping");
      vendor_samples = read_numbers(samples);
      fs::remove(samples);
    } else {
      vendor_name = "ddsperf";
      const std::string ddsperf = find_program("ddsperf");
      if (ddsperf.empty()) throw std::runtime_error("ddsperf not found (install cyclonedds-tools)");
      const std::string uri = ddsperf_uri();
      std::vector<std::string> base = {"-i", d2};
      if (qos.reliability == rt::QosProfile::Reliability::best_effort) base.push_back("-u");
      const int dur = static_cast<int>(std::ceil(expected_s)) + 1;
      std::vector<std::string> pa = base;
      pa.insert(pa.end(), {"-D", std::to_string(dur + 12), "pong"});
      const std::string pong_log = temp_path("ddsperf_pong");
      const pid_t dpong =
          spawn_on(cpus.pong, [&] { return spawn_program(ddsperf, pa, {uri}, {.file = pong_log, .fd = -1}); });
      std::vector<std::string> qa = base;
      qa.insert(qa.end(), {"-Qminmatch:1", "-Qinitwait:10", "-D", std::to_string(dur), "ping"});
      if (o.rate > 0) qa.push_back(std::to_string(static_cast<long>(o.rate)) + "Hz");
      qa.insert(qa.end(), {"size", std::to_string(o.size == 0 ? 0 : std::max(o.size, 12))});
      std::string dout;
      spawn_on(cpus.ping, [&] { return run_program(ddsperf, qa, dout, {uri}, true); });
      kill(dpong, SIGTERM);
      wait_program(dpong);
      fs::remove(pong_log);
      vendor_r = parse_ddsperf_ping(dout);
    }
  }

  Percentiles a = pct_of_result(plexus_r), b = vendor_r.is_null() ? Percentiles{} : pct_of_result(vendor_r);
  Json result = {{"dds", o.dds},
                 {"peer_dds", peer},
                 {"profile", o.profile},
                 {"size", o.size},
                 {"rate_hz", o.rate},
                 {"count", o.count},
                 {"transport", o.transport},
                 {"carried_by", shm ? "shm" : "udp"},
                 {"cpus", {{"ping", cpus.ping}, {"pong", cpus.pong}}},
                 {"plexus", plexus_r}};
  if (!vendor_r.is_null()) {
    result["vendor"] = vendor_r;
    result["ratio"] = {{"mean", a.mean / b.mean},
                       {"p50", a.p50 / b.p50},
                       {"p90", a.p90 / b.p90},
                       {"p99", a.p99 / b.p99},
                       {"max", a.max / b.max}};
  }
  if (!o.out.empty()) {
    std::vector<Series> series = {{"plexus " + o.dds + "->" + peer, plexus_samples, false}};
    if (!vendor_samples.empty()) series.push_back({vendor_name, vendor_samples, false});
    const std::string stem = o.out + "/pingpong_" + o.dds + "_" + std::to_string(o.size) + (shm ? "_shm" : "");
    write_histogram_png(
        stem + ".png", "round trip, " + std::to_string(o.size) + " B payload, " + o.dds + (shm ? ", shm" : ""), series);
    result["png"] = stem + ".png";
    std::ofstream(stem + ".json") << result.dump(2) << '\n';
  }
  if (o.json) {
    std::printf("%s\n", result.dump().c_str());
  } else {
    std::printf("plexus latency pingpong: %s -> %s, profile '%s', payload %d B, %g Hz, %d round trips, %s\n",
                o.dds.c_str(), peer.c_str(), o.profile.c_str(), o.size, o.rate, o.count,
                shm ? "shared memory" : "UDP on loopback");
    if (cpus.ping >= 0)
      std::printf("ping on CPU %d, pong on CPU %d (--pin), for plexus and the baseline alike\n", cpus.ping, cpus.pong);
    std::printf("plexus: received %d/%d, %.0f round trips/s\n", plexus_r.value("received", 0), o.count,
                plexus_r.value("round_trips_per_s", 0.0));
    if (!vendor_r.is_null()) {
      print_compare("round trip", a, b, vendor_name, true);
      if (vendor_name == "ddsperf")
        std::printf("(ddsperf reports half round trips per 1 s interval: shown x2, count-weighted)\n");
    } else {
      print_compare("round trip", a, Percentiles{}, "-", false);
    }
    if (result.contains("png")) std::printf("histogram: %s\n", result["png"].get<std::string>().c_str());
  }
  return plexus_r.value("received", 0) == o.count ? 0 : 1;
}

// ---------------------------------------------------------------------------------------
// pipeline

struct PipeOpts {
  std::string run, topics, out, end_topic, join = "auto";
  bool live = false, json = false;
  DdsOptions dds;
  double duration = 5;
};

int run_pipeline(const PipeOpts& o) {
  std::string file = o.run;
  bool temp = false;
  if (o.live) {
    rt::parse_vendor(o.dds.dds);
    if (!(o.duration > 0)) throw InputError("--duration: must be > 0 seconds");
    file = temp_path("pipeline") + ".mcap";
    temp = true;
    std::vector<std::string> args = {"record",
                                     "-o",
                                     file,
                                     "--dds",
                                     o.dds.dds,
                                     "--domain",
                                     std::to_string(o.dds.domain),
                                     "--duration",
                                     std::to_string(o.duration)};
    if (!o.topics.empty()) args.insert(args.end(), {"--topics", o.topics});
    for (const auto& [flag, value] : {std::pair<const char*, std::string>{"--security", o.dds.security},
                                      {"--identity", o.dds.identity},
                                      {"--governance", o.dds.governance}})
      if (!value.empty()) args.insert(args.end(), {flag, value});
    std::string out;
    const int rc = run_capture("plexus", args, out);
    if (rc != 0) throw std::runtime_error("live recording failed (plexus record exit " + std::to_string(rc) + ")");
  } else if (o.run.empty()) {
    throw InputError("RUN: a recording file (plexus record) is required, or --live");
  }
  make_out_dir(o.out);
  const auto opened = open_recording(file);
  const RecordingReader& rec = *opened;
  if (!rec.cut_short().empty())
    std::fprintf(stderr, "plexus latency pipeline: warning: %s: %s; using the %lld samples before the cut\n",
                 file.c_str(), rec.cut_short().c_str(), static_cast<long long>(rec.message_count()));
  struct T {
    std::string name;
    std::vector<double> to_publish, transport, to_receive;
    std::map<int64_t, int64_t> publish_by_origin, publish_by_data, receive_by_data;
  };
  std::map<int64_t, T> topics;
  const auto wanted = split_comma_list(o.topics);
  for (const auto& t : rec.topics())
    if (o.live || wanted.empty() || std::find(wanted.begin(), wanted.end(), t.name) != wanted.end())
      topics[t.id].name = t.name;
  for (const auto& w : wanted)
    if (!o.live && std::none_of(topics.begin(), topics.end(), [&](const auto& kv) { return kv.second.name == w; }))
      throw InputError("--topics: topic '" + w + "' is not in " + file);
  rec.for_each([&](const RecordedMessage& m) {
    auto it = topics.find(m.topic_id);
    // Header times at or before 0 are unset (or from a broken clock): such a sample joins nothing,
    // and with every time positive no difference below can overflow.
    if (it == topics.end() || m.origin_time_ns <= 0 || m.publish_time_ns <= 0) return true;
    auto& t = it->second;
    t.to_publish.push_back(static_cast<double>(m.publish_time_ns - m.origin_time_ns) * 1e-3);
    t.transport.push_back(static_cast<double>(m.receive_time_ns - m.publish_time_ns) * 1e-3);
    t.to_receive.push_back(static_cast<double>(m.receive_time_ns - m.origin_time_ns) * 1e-3);
    t.publish_by_origin[m.origin_time_ns] = m.publish_time_ns;
    t.publish_by_data[m.data_time_ns] = m.publish_time_ns;
    t.receive_by_data[m.data_time_ns] = m.receive_time_ns;
    return true;
  });
  if (temp) fs::remove(file);
  // The chain: topics ordered by how long after the origin they are published.
  std::vector<T*> chain;
  for (auto& [id, t] : topics)
    if (!t.to_publish.empty()) chain.push_back(&t);
  if (chain.empty()) throw std::runtime_error(file + ": no samples with header times");
  // Join the samples of one chain by their shared origin time (services carry it through),
  // or by their header data time (lockstep: one step), whichever links more samples.
  auto links = [&](bool by_origin) {
    std::size_t n = 0;
    for (std::size_t i = 0; i + 1 < chain.size(); ++i)
      for (const auto& [key, pub] : (by_origin ? chain[i + 1]->publish_by_origin : chain[i + 1]->publish_by_data))
        n += (by_origin ? chain[i]->publish_by_origin : chain[i]->publish_by_data).count(key) && key != 0;
    return n;
  };
  const bool by_origin = o.join == "origin_time" || (o.join == "auto" && links(true) >= links(false));
  std::map<const T*, double> median;
  std::map<int64_t, int64_t> first_publish;  // data time -> earliest publish over the topics
  if (!by_origin)
    for (auto* t : chain)
      for (const auto& [key, pub] : t->publish_by_data) {
        auto [it, fresh] = first_publish.emplace(key, pub);
        if (!fresh) it->second = std::min(it->second, pub);
      }
  for (auto* t : chain) {
    std::vector<double> c;
    if (by_origin) {
      c = t->to_publish;
    } else {
      for (const auto& [key, pub] : t->publish_by_data) c.push_back(static_cast<double>(pub - first_publish[key]));
    }
    median[t] = percentiles(c).p50;
  }
  std::stable_sort(chain.begin(), chain.end(), [&](const T* a, const T* b) { return median[a] < median[b]; });
  if (!o.end_topic.empty()) {
    auto it = std::find_if(chain.begin(), chain.end(), [&](const T* t) { return t->name == o.end_topic; });
    if (it == chain.end()) throw InputError("--end: topic '" + o.end_topic + "' has no samples with header times");
    chain.erase(it + 1, chain.end());
  }
  Json result = {{"run", o.live ? "live" : o.run},
                 {"join", by_origin ? "origin_time" : "data_time"},
                 {"topics", Json::array()},
                 {"hops", Json::array()}};
  std::vector<Series> series;
  if (!o.json)
    std::printf("%-32s %8s | %-26s | %-26s | %-26s\n%-32s %8s | %8s %8s %8s | %8s %8s %8s | %8s %8s %8s\n",
                "topic (chain order)", "samples", "origin -> publish (us)", "publish -> receive (us)",
                "origin -> receive (us)", "", "", "p50", "p99", "max", "p50", "p99", "max", "p50", "p99", "max");
  for (auto* t : chain) {
    auto a = percentiles(t->to_publish), b = percentiles(t->transport), c = percentiles(t->to_receive);
    result["topics"].push_back({{"topic", t->name},
                                {"origin_to_publish", pct_json(a)},
                                {"publish_to_receive", pct_json(b)},
                                {"origin_to_receive", pct_json(c)}});
    if (!o.json)
      std::printf("%-32s %8zu | %8.1f %8.1f %8.1f | %8.1f %8.1f %8.1f | %8.1f %8.1f %8.1f\n", t->name.c_str(), a.count,
                  a.p50, a.p99, a.max, b.p50, b.p99, b.max, c.p50, c.p99, c.max);
  }
  // Hops: publish of topic k+1 minus publish of topic k, for samples of the same chain (same origin time).
  for (std::size_t k = 0; k + 1 < chain.size(); ++k) {
    std::vector<double> d;
    const auto& next = by_origin ? chain[k + 1]->publish_by_origin : chain[k + 1]->publish_by_data;
    const auto& prev = by_origin ? chain[k]->publish_by_origin : chain[k]->publish_by_data;
    for (const auto& [key, pub] : next) {
      auto it = prev.find(key);
      if (it != prev.end()) d.push_back(static_cast<double>(pub - it->second) * 1e-3);
    }
    if (d.empty()) continue;
    series.push_back({chain[k]->name + " -> " + chain[k + 1]->name, d, false});
    auto p = percentiles(d);
    result["hops"].push_back({{"from", chain[k]->name}, {"to", chain[k + 1]->name}, {"latency", pct_json(p)}});
    if (!o.json)
      std::printf("hop %s -> %s: p50 %.1f us  p90 %.1f us  p99 %.1f us  max %.1f us  (%zu chains)\n",
                  chain[k]->name.c_str(), chain[k + 1]->name.c_str(), p.p50, p.p90, p.p99, p.max, p.count);
  }
  // End to end: origin -> receipt of the last topic (origin join), or first publish of the
  // step -> receipt of the last topic (data-time join).
  std::vector<double> e2e_values;
  if (by_origin) {
    e2e_values = chain.back()->to_receive;
  } else {
    for (const auto& [key, recv] : chain.back()->receive_by_data)
      if (auto it = first_publish.find(key); it != first_publish.end())
        e2e_values.push_back(static_cast<double>(recv - it->second) * 1e-3);
  }
  const std::string e2e_name =
      std::string(by_origin ? "origin" : "first publish of the step") + " -> " + chain.back()->name + " received";
  series.push_back({"end to end (" + e2e_name + ")", e2e_values, false});
  auto e2e = percentiles(e2e_values);
  result["end_to_end"] = {{"topic", chain.back()->name}, {"latency", pct_json(e2e)}};
  if (!o.out.empty()) {
    const std::string png = o.out + "/pipeline.png";
    write_histogram_png(png, "pipeline latency", series);
    result["png"] = png;
  }
  if (o.json) {
    std::printf("%s\n", result.dump().c_str());
  } else {
    std::printf("end to end (%s): p50 %.1f us  p90 %.1f us  p99 %.1f us  max %.1f us  (chains joined by %s)\n",
                e2e_name.c_str(), e2e.p50, e2e.p90, e2e.p99, e2e.max, by_origin ? "origin time" : "data time");
    if (result.contains("png")) std::printf("histogram: %s\n", result["png"].get<std::string>().c_str());
  }
  return 0;
}

}  // namespace

Command add_latency_command(CLI::App& root) {
  Command c;
  c.app = root.add_subcommand("latency",
                              "Latency measurements: pingpong (vs the vendor's tool), loop (vs cyclictest), pipeline");
  c.app->require_subcommand(1);

  auto po = std::make_shared<PingOpts>();
  auto* ping =
      c.app->add_subcommand("pingpong", "Round-trip latency through plexus and through the vendor's own baseline");
  ping->add_option("--dds", po->dds, "vendor of the ping side (and of the baseline)")->capture_default_str();
  ping->add_option("--peer-dds", po->peer_dds, "vendor of the pong side (default: --dds)");
  ping->add_option("--profile", po->profile, "QoS profile")->capture_default_str();
  ping->add_option("--qos-file", po->qos_file, "QoS profiles file (default: deploy/qos.yaml)");
  ping->add_option("--size", po->size, "payload bytes (0..1048576)")->capture_default_str();
  ping->add_option("--rate", po->rate, "pings per second (0: back to back)")->capture_default_str();
  ping->add_option("--count", po->count, "measured round trips")->capture_default_str();
  ping->add_option("--domain", po->domain, "DDS domain (the baseline uses domain + 1)")->capture_default_str();
  ping->add_option("--transport", po->transport,
                   "auto, udp or shm: shm carries Fast DDS round trips over shared memory (docs/runtime.md)")
      ->capture_default_str();
  ping->add_option("-o,--out", po->out, "directory for the PNG histogram and JSON");
  ping->add_option("--pin", po->pin,
                   "where ping and pong run, alike for plexus and the baseline: split (ping on the first CPU, pong on "
                   "the second), same (both on the first), none, auto (split, or same with one CPU)")
      ->capture_default_str();
  ping->add_flag("--no-baseline", po->no_baseline, "skip the vendor baseline");
  ping->add_flag("--json", po->json, "one JSON object");

  auto lo = std::make_shared<LoopOpts>();
  auto* loop = c.app->add_subcommand(
      "loop", "Wake-up lateness of a plexus periodic loop, and of cyclictest at the same settings");
  loop->add_option("--rate", lo->rate, "loop rate, Hz")->capture_default_str();
  loop->add_option("--duration", lo->duration, "seconds")->capture_default_str();
  loop->add_option("--priority", lo->priority, "SCHED_FIFO priority (0: none)")->capture_default_str();
  loop->add_option("--cpu", lo->cpu, "pin both to this CPU (-1: the first allowed CPU, where cyclictest pins itself)")
      ->capture_default_str();
  loop->add_option("--rounds", lo->rounds, "alternate plexus and cyclictest in this many segments (ABBA order)")
      ->capture_default_str();
  loop->add_option(
          "--cpu-dma-latency", lo->cpu_dma_latency,
          "CPU wake-up latency request, us, held on /dev/cpu_dma_latency by both (-1: none; cyclictest --laptop)")
      ->capture_default_str();
  loop->add_option("--timer-slack", lo->timer_slack, "the plexus loop thread's timer slack, ns (0: keep Linux's 50 us)")
      ->capture_default_str();
  loop->add_flag("--no-mlock", lo->no_mlock, "neither locks its memory (mlockall)");
  loop->add_option("-o,--out", lo->out, "directory for the PNG histogram");
  loop->add_flag("--no-cyclictest", lo->no_cyclictest, "skip the cyclictest baseline");
  loop->add_flag("--json", lo->json, "one JSON object");

  auto pp = std::make_shared<PipeOpts>();
  auto* pipe =
      c.app->add_subcommand("pipeline", "Per-hop and end-to-end latency from header times (recording or live)");
  pipe->add_option("run", pp->run, "recording file (plexus record)");
  pipe->add_flag("--live", pp->live, "record the live system for --duration first");
  pipe->add_option("--topics", pp->topics, "comma-separated topics (default: all)");
  pipe->add_option("--end", pp->end_topic, "the chain's last topic (default: the latest-published one)");
  // One list for the help and the parser: the names are the header fields the chain is joined by.
  pipe->add_option("--join", pp->join, "link a chain's samples by origin_time, data_time, or auto")
      ->capture_default_str()
      ->check(CLI::IsMember({"auto", "origin_time", "data_time"}));
  pipe->add_option("--duration", pp->duration, "--live: seconds to record")->capture_default_str();
  add_dds_options(pipe, pp->dds);
  pipe->add_option("-o,--out", pp->out, "directory for the PNG histogram");
  pipe->add_flag("--json", pp->json, "one JSON object");

  c.run = [po, lo, pp, ping, loop, pipe] {
    if (ping->parsed()) return run_pingpong(*po);
    if (loop->parsed()) return run_loop(*lo);
    if (pipe->parsed()) return run_pipeline(*pp);
    return 2;
  };
  return c;
}

}  // namespace plexus::cli
