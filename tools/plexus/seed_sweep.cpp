#include "seed_sweep.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>

#include "plexus/base/clock.hpp"
#include "plexus/evaluation/evaluation.hpp"
#include "plexus/evaluation/run_folder.hpp"
#include "plexus/scenario/executor.hpp"
#include "plexus/scenario/scenario.hpp"

namespace plexus::cli {
namespace {

nlohmann::ordered_json number(double v) { return std::isfinite(v) ? nlohmann::ordered_json(v) : nullptr; }

}  // namespace

SeedStatistics summarise(const std::vector<double>& values) {
  SeedStatistics s;
  s.values = values;
  const double n = static_cast<double>(values.size());
  bool finite = !values.empty();
  for (double v : values) finite = finite && std::isfinite(v);
  if (!finite) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    s.mean = s.std = s.sem = s.t = s.min = s.max = nan;
    return s;
  }
  s.min = s.max = values.front();
  double sum = 0.0;
  for (double v : values) {
    sum += v;
    s.min = std::min(s.min, v);
    s.max = std::max(s.max, v);
  }
  s.mean = sum / n;
  double sq = 0.0;
  for (double v : values) sq += (v - s.mean) * (v - s.mean);
  s.std = values.size() > 1 ? std::sqrt(sq / (n - 1.0)) : 0.0;
  s.sem = s.std / std::sqrt(n);
  s.t = s.sem > 0.0 ? s.mean / s.sem : std::numeric_limits<double>::quiet_NaN();
  return s;
}

nlohmann::ordered_json SeedStatistics::to_json() const {
  nlohmann::ordered_json j;
  j["mean"] = number(mean);
  j["std"] = number(std);
  j["sem"] = number(sem);
  j["t"] = number(t);
  j["min"] = number(min);
  j["max"] = number(max);
  auto& v = j["values"] = nlohmann::ordered_json::array();
  for (double x : values) v.push_back(number(x));
  return j;
}

int run_seed_sweep(const SeedSweepOptions& o) {
  const scenario::Scenario first = scenario::load_scenario(o.scenario, o.overrides);
  const auto dir = scenario::prepare_run_folder(o.out, first.name + "-seeds");
  scenario::log_warnings(first,
                         " (details: " + (dir / ("seed-" + std::to_string(first.seed)) / "summary.md").string() + ")");
  std::vector<uint64_t> seeds;
  std::vector<std::string> names;
  std::map<std::string, std::vector<double>> values;
  const int64_t start = monotonic_ns();
  for (int i = 0; i < o.seeds; ++i) {
    const uint64_t seed = first.seed + static_cast<uint64_t>(i);
    auto overrides = o.overrides;
    overrides.push_back({"seed", std::to_string(seed)});
    scenario::Scenario sc = scenario::load_scenario(o.scenario, overrides);
    const int64_t t0 = monotonic_ns();
    const scenario::RunLog log = scenario::run_scenario(sc);
    const double wall = static_cast<double>(monotonic_ns() - t0) * 1e-9;
    const scenario::Evaluation ev = scenario::evaluate(sc, log);
    scenario::write_run_folder(dir / ("seed-" + std::to_string(seed)), sc, log, ev, wall, o.units);
    seeds.push_back(seed);
    for (const auto& [name, r] : ev.metrics) {
      if (i == 0) names.push_back(name);
      values[name].push_back(r.value);
    }
    if (!o.quiet) std::fprintf(stderr, "\rseed %llu (%d/%d)", static_cast<unsigned long long>(seed), i + 1, o.seeds);
  }
  if (!o.quiet) std::fprintf(stderr, "\n");

  nlohmann::ordered_json j;
  j["seeds"] = seeds;
  std::map<std::string, SeedStatistics> stats;
  for (const auto& name : names) {
    stats[name] = summarise(values[name]);
    j[name] = stats[name].to_json();
  }
  std::ofstream(dir / "seeds.json") << j.dump(2) << "\n";
  scenario::mark_run_folder(dir, "complete");

  if (o.json) {
    std::cout << j.dump() << std::endl;
  } else {
    std::printf("scenario %s: %d seeds (%llu..%llu) in %.3g s\n", first.name.c_str(), o.seeds,
                static_cast<unsigned long long>(seeds.front()), static_cast<unsigned long long>(seeds.back()),
                static_cast<double>(monotonic_ns() - start) * 1e-9);
    std::printf("  %-32s %12s %12s %12s %12s %12s\n", "metric", "mean", "std", "t", "min", "max");
    for (const auto& name : names) {
      const auto& s = stats[name];
      std::printf("  %-32s %12.6g %12.6g %12.6g %12.6g %12.6g\n", name.c_str(), s.mean, s.std, s.t, s.min, s.max);
    }
  }
  if (!o.quiet) std::fprintf(stderr, "sweep folder: %s\n", dir.string().c_str());
  int failed = 0;
  for (const auto& e : first.expectations) {
    const auto& s = stats[e.metric];
    if (e.holds(s.mean)) continue;
    ++failed;
    std::fprintf(stderr, "expectation failed: %s mean = %s over %d seeds, bound %s %s\n", e.metric.c_str(),
                 scenario::format_number(s.mean).c_str(), o.seeds, e.op_text(),
                 scenario::format_number(e.bound).c_str());
  }
  return failed == 0 ? 0 : 1;
}

}  // namespace plexus::cli
