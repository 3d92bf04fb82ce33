// `plexus sim --seeds N`: one scenario run with N seeds, each metric summarised over the
// runs. A claim that depends on the noise (one filter beats another by a hair, a mean
// error against a paper's figure) is a statistic: it is checked on the mean over the
// seeds, with the spread beside it, not on whichever seed the scenario names.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "plexus/evaluation/run_folder.hpp"
#include "plexus/scenario/overrides.hpp"

namespace plexus::cli {

/// One metric over the seeds. NaN statistics when any run gave NaN (never silently dropped).
struct SeedStatistics {
  std::vector<double> values;  ///< per seed, in seed order
  double mean = 0.0;
  double std = 0.0;  ///< sample standard deviation (n - 1); 0 for one seed
  double sem = 0.0;  ///< standard error of the mean, std / sqrt(n)
  double t = 0.0;    ///< mean / sem: Student's t against 0 (n - 1 degrees of freedom)
  double min = 0.0;
  double max = 0.0;

  nlohmann::ordered_json to_json() const;
};

SeedStatistics summarise(const std::vector<double>& values);

struct SeedSweepOptions {
  std::string scenario;
  std::vector<scenario::Override> overrides;
  int seeds = 0;    ///< number of runs, seeds first .. first + seeds - 1
  std::string out;  ///< folder of the sweep: seeds.json and seed-<s>/ per run
  bool json = false;
  bool quiet = false;
  scenario::FieldUnits units;  ///< field units for each run folder's signals.json (wire_field_units())
};

/// Runs the sweep, prints the statistics (a table, or one JSON object with `json`:
/// {"seeds": [...], "<metric>": {"mean", "std", "sem", "t", "min", "max", "values"}}),
/// checks every expectation of the scenario on the metric's mean and prints each failure
/// as "expectation failed: <metric> mean = <v> over N seeds, bound <op> <b>". Returns 0 or 1.
int run_seed_sweep(const SeedSweepOptions& o);

}  // namespace plexus::cli
