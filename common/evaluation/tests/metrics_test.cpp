// Metric values against numbers computed by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "plexus/base/yaml_reader.hpp"
#include "plexus/evaluation/evaluation.hpp"
#include "plexus/scenario/metric.hpp"
#include "plexus/scenario/scenario.hpp"

namespace plexus::scenario {
namespace {

/// Two signals at 1 s steps: a = (x,y) = (0,0) (3,4) (6,8) (0,1) produced every step;
/// b, stored as (y,x), = (0,0) at step 0 and (x,y) = (1,2) at step 2, held at steps 1 and 3.
RunLog two_signals() {
  RunLog log;
  log.base_step = 1.0;
  log.steps = 3;
  log.signals.push_back({{"r/a", {"x", "y"}, 1, "pa", true, ""}, {0, 1, 2, 3}, {0, 0, 3, 4, 6, 8, 0, 1}});
  log.signals.push_back({{"r/b", {"y", "x"}, 2, "pb", false, ""}, {0, 2}, {0, 0, 2, 1}});
  return log;
}

MetricResult compute(const std::string& yaml) {
  const RunLog log = two_signals();
  std::vector<SignalSpec> specs;
  for (const auto& s : log.signals) specs.push_back(s.spec);
  const YamlMap entry(load_yaml_string(yaml, "m.yaml"), "m.yaml");
  const std::string type = entry.required<std::string>("type");
  const MetricType* t = find_metric_type(type);
  EXPECT_NE(t, nullptr) << type;
  const MetricFunction f = t->factory(MetricSetup(entry, specs, 1.0, 3.0));
  entry.reject_unknown();
  return f(log);
}

// Distances a - held b: step0 |(0,0)-(0,0)| = 0; step1 |(3,4)-(0,0)| = 5;
// step2 |(6,8)-(1,2)| = sqrt(25+36) = sqrt(61); step3 |(0,1)-(1,2)| = sqrt(2).
TEST(Metrics, ErrorMetricsHoldTheReferenceAndMatchFieldsByName) {
  const char* base = "{signal: r/a, reference: r/b, type: ";
  EXPECT_DOUBLE_EQ(compute(std::string(base) + "error_final}").value, std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(compute(std::string(base) + "error_max}").value, std::sqrt(61.0));
  EXPECT_DOUBLE_EQ(compute(std::string(base) + "error_mean}").value, (0 + 5 + std::sqrt(61.0) + std::sqrt(2.0)) / 4);
  EXPECT_DOUBLE_EQ(compute(std::string(base) + "error_rms}").value, std::sqrt((0 + 25 + 61 + 2) / 4.0));
  const MetricResult r = compute(std::string(base) + "error_max, fields: [x]}");
  EXPECT_DOUBLE_EQ(r.value, 5.0);  // |x| differences 0, 3, 5, 1
  ASSERT_EQ(r.series.size(), 4u);
  EXPECT_DOUBLE_EQ(r.series[2].first, 2.0);
  EXPECT_DOUBLE_EQ(r.series[2].second, 5.0);
}

TEST(Metrics, WindowsIncludeTheirEnds) {
  const char* base = "{signal: r/a, reference: r/b, type: error_max";
  EXPECT_DOUBLE_EQ(compute(std::string(base) + ", to: 1}").value, 5.0);
  EXPECT_DOUBLE_EQ(compute(std::string(base) + ", from: 3}").value, std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(compute(std::string(base) + ", from: 1, to: 1}").value, 5.0);
}

TEST(Metrics, ValueMetrics) {
  const char* base = "{signal: r/a, field: y, type: ";
  EXPECT_DOUBLE_EQ(compute(std::string(base) + "value_final}").value, 1.0);
  EXPECT_DOUBLE_EQ(compute(std::string(base) + "value_max}").value, 8.0);
  EXPECT_DOUBLE_EQ(compute(std::string(base) + "value_min}").value, 0.0);
  EXPECT_DOUBLE_EQ(compute(std::string(base) + "value_mean}").value, 13.0 / 4);
  EXPECT_DOUBLE_EQ(compute(std::string(base) + "value_max_abs, to: 1}").value, 4.0);
}

TEST(Metrics, EvaluateReportsFailedExpectationsWithValueAndBound) {
  Scenario sc;
  sc.metrics.push_back({"m", "value_max", [](const RunLog&) { return MetricResult{0.25, {}}; }});
  sc.metrics.push_back({"n", "value_max", [](const RunLog&) { return MetricResult{}; }});  // NaN
  Expectation e;
  ASSERT_TRUE(parse_expectation("m", "<= 0.2", e));
  sc.expectations.push_back(e);
  ASSERT_TRUE(parse_expectation("n", ">= 0", e));
  sc.expectations.push_back(e);
  const Evaluation ev = evaluate(sc, two_signals());
  ASSERT_EQ(ev.failures.size(), 2u);
  EXPECT_EQ(ev.failures[0], "expectation failed: m = 0.25, bound <= 0.2");
  EXPECT_EQ(ev.failures[1], "expectation failed: n = nan, bound >= 0");
  EXPECT_EQ(ev.to_json().dump(), R"({"digest":")" + ev.digest + R"(","m":0.25,"n":null})");
}

// An expectation marked paper_inconsistent that is not met is reported with its evidence and
// does not fail the run; one that is met passes as usual.
TEST(Metrics, InconsistentInThePaperIsNotAFailure) {
  Scenario sc;
  sc.metrics.push_back({"m", "value_max", [](const RunLog&) { return MetricResult{0.25, {}}; }});
  sc.metrics.push_back({"k", "value_max", [](const RunLog&) { return MetricResult{0.1, {}}; }});
  Expectation e;
  ASSERT_TRUE(parse_expectation("m", "<= 0.2", e));
  e.inconsistent = "docs/a.md, \"B\"";
  sc.expectations.push_back(e);
  ASSERT_TRUE(parse_expectation("k", "<= 0.2", e));
  sc.expectations.push_back(e);
  const Evaluation ev = evaluate(sc, two_signals());
  EXPECT_TRUE(ev.failures.empty());
  ASSERT_EQ(ev.inconsistent.size(), 1u);
  EXPECT_EQ(ev.inconsistent[0], "inconsistent in the paper: m = 0.25, bound <= 0.2 (evidence: docs/a.md, \"B\")");
  EXPECT_EQ(expectation_result(sc.expectations[0], 0.25), kInconsistentResult);
  EXPECT_EQ(expectation_result(sc.expectations[0], 0.15), "pass");
  EXPECT_EQ(expectation_result(sc.expectations[1], 0.25), "FAIL");
  EXPECT_EQ(worse_result("pass", kInconsistentResult), kInconsistentResult);
  EXPECT_EQ(worse_result(kInconsistentResult, "FAIL"), "FAIL");
  EXPECT_EQ(worse_result("-", "pass"), "pass");
}

TEST(Expectations, ParseEveryOperatorAndRejectGarbage) {
  Expectation e;
  ASSERT_TRUE(parse_expectation("m", "<= 0.05", e));
  EXPECT_TRUE(e.holds(0.05));
  EXPECT_FALSE(e.holds(0.051));
  ASSERT_TRUE(parse_expectation("m", ">=1e-3", e));
  EXPECT_TRUE(e.holds(1e-3));
  ASSERT_TRUE(parse_expectation("m", "< 1", e));
  EXPECT_FALSE(e.holds(1));
  ASSERT_TRUE(parse_expectation("m", "> 1", e));
  EXPECT_FALSE(e.holds(1));
  ASSERT_TRUE(parse_expectation("m", "== 2", e));
  EXPECT_TRUE(e.holds(2));
  EXPECT_FALSE(e.holds(std::nan("")));
  EXPECT_EQ(e.text(), "== 2");
  for (const char* bad : {"", "0.05", "<= ", "<= x", "=< 1", "<= 1 m", "<= nan", "!= 1"})
    EXPECT_FALSE(parse_expectation("m", bad, e)) << bad;
}

}  // namespace
}  // namespace plexus::scenario
