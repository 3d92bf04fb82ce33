#include "bench/bench_baseline.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>

#include "plexus/base/input_error.hpp"

namespace plexus::cli::bench {
namespace {

using Json = nlohmann::ordered_json;

double headline_rate(const Json& run) {
  for (const auto& r : run["matrix"]["rates_hz"])
    if (r.get<double>() > 0) return r.get<double>();
  return 0;
}

const Json* latency_at(const Json& cell, double rate) {
  if (!cell.contains("latency")) return nullptr;
  for (const auto& l : cell["latency"])
    if (l.value("rate_hz", -1.0) == rate) return &l;
  return nullptr;
}

double number_at(const Json& j, std::initializer_list<const char*> path, double fallback = -1) {
  const Json* p = &j;
  for (const char* k : path) {
    if (!p->is_object() || !p->contains(k)) return fallback;
    p = &(*p)[k];
  }
  return p->is_number() ? p->get<double>() : fallback;
}

}  // namespace

Json load_run(const std::string& path) {
  const std::string file = std::filesystem::is_directory(path) ? path + "/run.json" : path;
  std::ifstream f(file);
  if (!f) throw InputError("--baseline: cannot read " + file);
  try {
    Json j = Json::parse(f);
    if (!j.contains("plexus_bench") || !j.contains("cells"))
      throw InputError("--baseline: " + file + ": not a plexus bench run.json");
    return j;
  } catch (const Json::exception& e) {
    throw InputError("--baseline: " + file + ": " + e.what());
  }
}

Comparison compare_runs(const Json& now, const Json& old, const Thresholds& t) {
  Comparison out;
  std::map<std::string, const Json*> old_cells;
  for (const auto& c : old["cells"])
    if (c.value("status", "") == "ok") old_cells[c.value("id", "")] = &c;
  const double rate_now = headline_rate(now), rate_old = headline_rate(old);
  for (const auto& c : now["cells"]) {
    if (c.value("status", "") != "ok") continue;
    auto it = old_cells.find(c.value("id", ""));
    if (it == old_cells.end()) continue;
    const Json& o = *it->second;
    // Latencies: lower is better.
    const Json *ln = latency_at(c, rate_now), *lo = latency_at(o, rate_old);
    if (ln && lo)
      for (const auto& [measure, spread] :
           {std::pair{"one_way_us", "one_way_p50_us"}, std::pair{"round_trip_us", "round_trip_p50_us"}}) {
        const double a = number_at(*lo, {measure, "p50"}), b = number_at(*ln, {measure, "p50"});
        if (a < 0 || b < 0 || number_at(*ln, {measure, "count"}) <= 0 || number_at(*lo, {measure, "count"}) <= 0)
          continue;
        ++out.compared;
        const double noise = number_at(o, {"spread", spread}, 0);
        const double allowed = std::max({t.relative * a, t.absolute_us, t.noise_factor * noise});
        if (b - a > allowed) out.regressions.push_back({c["id"], std::string(measure) + " p50", a, b, allowed});
      }
    // Throughput: higher is better.
    const double a = number_at(o, {"throughput", "samples_per_s"}), b = number_at(c, {"throughput", "samples_per_s"});
    if (a > 0 && b >= 0) {
      ++out.compared;
      const double noise = number_at(o, {"spread", "throughput_samples_per_s"}, 0);
      const double allowed = std::max(t.relative * a, t.noise_factor * noise);
      if (a - b > allowed) out.regressions.push_back({c["id"], "throughput samples/s", a, b, allowed});
    }
  }
  return out;
}

}  // namespace plexus::cli::bench
