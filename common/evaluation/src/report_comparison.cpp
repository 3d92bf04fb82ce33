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
  if (in.scenario["paper_inconsistent"] && in.scenario["paper_inconsistent"].IsMap())
    for (const auto& kv : in.scenario["paper_inconsistent"])
      if (kv.second.IsScalar())
        for (Expectation& e : bounds[kv.first.Scalar()]) e.inconsistent = kv.second.Scalar();
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
    std::string result = "-", evidence;
    for (const auto& e : es) {
      result = worse_result(result, expectation_result(e, v));
      if (!e.inconsistent.empty()) evidence = e.inconsistent;
    }
    c.rows.push_back({metric, papers[metric], format_number(v), bound_text(es), result,
                      result == kInconsistentResult ? evidence : ""});
    if (result == "FAIL") ++c.failed;
    if (result == kInconsistentResult) ++c.inconsistent;
  }
  // An expectation whose metric metrics.json lacks is a row too: missing, and FAIL.
  for (const auto& [metric, es] : bounds) {
    if (in.metrics.contains(metric)) continue;
    c.rows.push_back({metric, papers[metric], "missing", bound_text(es), "FAIL", ""});
    ++c.failed;
  }
  return c;
}

std::string Comparison::markdown() const {
  std::ostringstream table;
  table << "| metric | value | expectation | result |\n|---|---|---|---|\n";
  for (const auto& r : rows)
    table << "| " << r.metric << " | " << r.value << " | " << r.bound << " | " << r.result
          << (r.evidence.empty() ? "" : " (" + r.evidence + ")") << " |\n";
  return table.str();
}

}  // namespace plexus::scenario
