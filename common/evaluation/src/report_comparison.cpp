#include "plexus/evaluation/report_comparison.hpp"

#include <cmath>
#include <map>
#include <sstream>

#include "plexus/evaluation/evaluation.hpp"
#include "plexus/scenario/expectation.hpp"

namespace plexus::scenario {

Comparison compare(const ReportInputs& in) {
  std::map<std::string, std::vector<Expectation>> bounds;
  if (in.scenario["expectations"] && in.scenario["expectations"].IsMap())
    for (const auto& kv : in.scenario["expectations"]) {
      Expectation e;
      if (kv.second.IsScalar() && parse_expectation(kv.first.Scalar(), kv.second.Scalar(), e))
        bounds[e.metric].push_back(e);
    }
  std::map<std::string, std::string> papers;
  if (in.scenario["metrics"] && in.scenario["metrics"].IsSequence())
    for (const auto& m : in.scenario["metrics"]) {
      const std::string name = m["name"] ? m["name"].Scalar() : m["type"] ? m["type"].Scalar() : "";
      if (m["paper"] && m["paper"].IsScalar()) papers[name] = m["paper"].Scalar();
    }
  auto bound_text = [](const std::vector<Expectation>& es) {
    std::string out;
    for (const auto& e : es) out += (out.empty() ? "" : ", ") + std::string(e.op_text()) + " " + format_number(e.bound);
    return out.empty() ? std::string("-") : out;
  };

  Comparison c;
  for (const auto& [metric, value] : in.metrics.items()) {
    if (metric == "digest") continue;
    const double v = value.is_number() ? value.get<double>() : std::nan("");
    const auto& es = bounds[metric];
    std::string result = "-";
    for (const auto& e : es) result = (result == "-" || result == "pass") && e.holds(v) ? "pass" : "FAIL";
    c.rows.push_back({metric, papers[metric], format_number(v), bound_text(es), result});
    if (result == "FAIL") ++c.failed;
  }
  // An expectation whose metric metrics.json lacks is a row too: missing, and FAIL.
  for (const auto& [metric, es] : bounds) {
    if (in.metrics.contains(metric)) continue;
    c.rows.push_back({metric, papers[metric], "missing", bound_text(es), "FAIL"});
    ++c.failed;
  }
  return c;
}

std::string Comparison::markdown() const {
  std::ostringstream table;
  table << "| metric | value | expectation | result |\n|---|---|---|---|\n";
  for (const auto& r : rows)
    table << "| " << r.metric << " | " << r.value << " | " << r.bound << " | " << r.result << " |\n";
  return table.str();
}

}  // namespace plexus::scenario
