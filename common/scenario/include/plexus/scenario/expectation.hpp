// Expectations: `metric: "<= 0.05"` bounds that make a run fail when not met. An expectation
// listed under `paper_inconsistent:` (metric: evidence) reproduces a published figure that
// the paper's own text cannot produce (docs/reports.md "Inconsistent in the paper"): when
// not met it is reported as such, with its evidence, and does not fail the run.
#pragma once

#include <string>

namespace plexus::scenario {

struct Expectation {
  enum class Op { le, ge, lt, gt, eq };
  std::string metric;
  Op op = Op::le;
  double bound = 0.0;
  /// Where the evidence is that the paper cannot produce this figure (a docs page and
  /// section); empty for an ordinary expectation.
  std::string inconsistent;

  /// True if `value` satisfies the bound (NaN never does). `eq` is exact equality.
  bool holds(double value) const;
  /// "<=", ">=", "<", ">", "==".
  const char* op_text() const;
  /// "<= 0.05"
  std::string text() const;
};

/// The result of `e` for `value`: "pass", kInconsistentResult (not met, marked
/// paper_inconsistent) or "FAIL".
inline constexpr const char* kInconsistentResult = "inconsistent in the paper";
std::string expectation_result(const Expectation& e, double value);
/// The worse of two results, FAIL before inconsistent before pass ("-": none yet).
std::string worse_result(const std::string& a, const std::string& b);

/// Parses "<op> <number>" (op one of <=, >=, <, >, ==); returns false if malformed.
bool parse_expectation(const std::string& metric, const std::string& text, Expectation& out);

}  // namespace plexus::scenario
