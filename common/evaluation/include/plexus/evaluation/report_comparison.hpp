// `plexus report`: the comparison table, one row per metric of metrics.json and one per
// expectation whose metric metrics.json lacks ("missing", FAIL). Its columns: the metric,
// the published figure it reproduces (the metric entry's `paper` key), our value, the
// scenario's bound and pass / FAIL ("-" for a metric without an expectation), or
// "inconsistent in the paper" with its evidence for an unmet expectation the scenario marks
// `paper_inconsistent` (expectation.hpp): not a failure.
#pragma once

#include <string>
#include <vector>

#include "plexus/evaluation/report_inputs.hpp"

namespace plexus::scenario {

struct ComparisonRow {
  std::string metric;
  std::string paper;     ///< "" when the metric names no published figure
  std::string value;     ///< our value, "missing" when metrics.json lacks it
  std::string bound;     ///< "<= 0.05" (several joined by ", "), "-" for none
  std::string result;    ///< "pass", "FAIL", kInconsistentResult or "-"
  std::string evidence;  ///< for kInconsistentResult: where the evidence is
};

struct Comparison {
  std::vector<ComparisonRow> rows;
  int failed = 0;        ///< FAIL rows
  int inconsistent = 0;  ///< rows inconsistent in the paper (not failures)

  /// The markdown table `plexus report` prints and report.md holds:
  /// | metric | value | expectation | result |
  std::string markdown() const;
};

Comparison compare(const ReportInputs& in);

}  // namespace plexus::scenario
