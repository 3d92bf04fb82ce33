#include "bench/bench_runner.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <map>
#include <memory>

#include "bench/bench_cells.hpp"
#include "bench/bench_group.hpp"
#include "bench/bench_machine.hpp"
#include "bench/bench_netns.hpp"
#include "bench/bench_vendor_tools.hpp"

namespace plexus::cli::bench {
namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

std::string cell_id(const std::string& pair, const std::string& transport, const std::string& profile, int size,
                    const std::string& topology) {
  return pair + "/" + transport + "/" + profile + "/" + std::to_string(size) + "/" + topology;
}

namespace {

double now_s() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

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
                vendor_cache[key] = g.pair.writer == rt::Vendor::fast ? raw_fast_baseline(g, size, rate, m, scratch)
                                                                      : ddsperf_baseline(g, size, rate, m);
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
