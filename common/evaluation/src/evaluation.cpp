#include "plexus/evaluation/evaluation.hpp"

#include <charconv>
#include <cmath>

#include "plexus/scenario/digest.hpp"

namespace plexus::scenario {

nlohmann::ordered_json Evaluation::to_json() const {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  j["digest"] = digest;
  for (const auto& [name, result] : metrics)
    j[name] = std::isfinite(result.value) ? nlohmann::ordered_json(result.value) : nullptr;
  return j;
}

Evaluation evaluate(const Scenario& scenario, const RunLog& log) {
  Evaluation ev;
  ev.digest = hex16(run_digest(log));
  for (const auto& m : scenario.metrics) ev.metrics.emplace_back(m.name, m.compute(log));
  for (const auto& e : scenario.expectations) {
    for (const auto& [name, result] : ev.metrics) {
      if (name != e.metric || e.holds(result.value)) continue;
      const std::string what =
          name + " = " + format_number(result.value) + ", bound " + e.op_text() + " " + format_number(e.bound);
      if (e.inconsistent.empty())
        ev.failures.push_back("expectation failed: " + what);
      else
        ev.inconsistent.push_back("inconsistent in the paper: " + what + " (evidence: " + e.inconsistent + ")");
    }
  }
  return ev;
}

}  // namespace plexus::scenario
