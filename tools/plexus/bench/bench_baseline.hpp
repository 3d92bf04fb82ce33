// `plexus bench --baseline OLD_RUN`: cell-by-cell comparison of two runs (docs/qos-bench.md).
// A measure regresses when it is worse than the old run's by more than the larger of a
// relative threshold, an absolute floor (latencies) and a multiple of the noise the old run
// measured of itself (each cell's spread: between chunks of a phase, and between repeats).
// The old run's noise only: a new run made noisy by the regression itself (a latency that
// grows through the phase) must not excuse it.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace plexus::cli::bench {

struct Thresholds {
  double relative = 0.25;   ///< fraction of the old value
  double absolute_us = 20;  ///< latencies: changes below this are noise
  double noise_factor = 3;  ///< x the old cell's spread
};

struct Regression {
  std::string cell, measure;
  double old_value = 0, new_value = 0, allowed = 0;
};

struct Comparison {
  int compared = 0;  ///< cell measures present in both runs
  std::vector<Regression> regressions;
};

/// Compares the cells with status ok in both runs (by id): one-way and round-trip p50 at the
/// headline rate (the first rate > 0 of each run), and throughput in samples/s.
Comparison compare_runs(const nlohmann::ordered_json& now, const nlohmann::ordered_json& old, const Thresholds& t);

/// The run.json of a run directory (or the file itself); InputError naming it if unreadable.
nlohmann::ordered_json load_run(const std::string& path);

}  // namespace plexus::cli::bench
