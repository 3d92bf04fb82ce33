// Expectations: `metric: "<= 0.05"` bounds that make a run fail when not met.
#pragma once

#include <string>

namespace plexus::scenario {

struct Expectation {
  enum class Op { le, ge, lt, gt, eq };
  std::string metric;
  Op op = Op::le;
  double bound = 0.0;

  /// True if `value` satisfies the bound (NaN never does). `eq` is exact equality.
  bool holds(double value) const;
  /// "<=", ">=", "<", ">", "==".
  const char* op_text() const;
  /// "<= 0.05"
  std::string text() const;
};

/// Parses "<op> <number>" (op one of <=, >=, <, >, ==); returns false if malformed.
bool parse_expectation(const std::string& metric, const std::string& text, Expectation& out);

}  // namespace plexus::scenario
