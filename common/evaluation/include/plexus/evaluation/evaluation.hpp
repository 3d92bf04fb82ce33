// After a run: the metrics, the digest and the expectations that failed.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "plexus/scenario/format.hpp"
#include "plexus/scenario/metric.hpp"
#include "plexus/scenario/scenario.hpp"

namespace plexus::scenario {

struct Evaluation {
  std::string digest;                                         ///< 16 hex digits, see digest.hpp
  std::vector<std::pair<std::string, MetricResult>> metrics;  ///< in scenario order
  /// One line per failed expectation: "expectation failed: <metric> = <value>, bound <op> <bound>".
  std::vector<std::string> failures;
  /// One line per unmet expectation marked `paper_inconsistent` (not a failure):
  /// "inconsistent in the paper: <metric> = <value>, bound <op> <bound> (evidence: ...)".
  std::vector<std::string> inconsistent;

  /// {"digest": "...", "<metric>": value, ...} in scenario order; a NaN value is null.
  nlohmann::ordered_json to_json() const;
};

/// Computes every metric of the scenario and checks its expectations.
Evaluation evaluate(const Scenario& scenario, const RunLog& log);

}  // namespace plexus::scenario
