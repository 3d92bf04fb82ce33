// Test helper: evaluate one metric (given as a YAML entry) on a synthetic RunLog.
// The skid-steer metric tests use it; unicycle_metrics_test.cpp and metrics_test.cpp still
// carry their own copy of the same few lines and can switch to it.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "plexus/base/input_error.hpp"
#include "plexus/base/yaml_reader.hpp"
#include "plexus/scenario/metric.hpp"

namespace plexus::scenario::testing {

/// The metric's result on `log` (base step `step`, run length `duration`); unknown keys in
/// `yaml` are a test failure (they throw).
inline MetricResult metric_on_log(const RunLog& log, const std::string& yaml, double step, double duration) {
  std::vector<SignalSpec> specs;
  for (const auto& s : log.signals) specs.push_back(s.spec);
  const YamlMap entry(load_yaml_string(yaml, "m.yaml"), "m.yaml");
  const MetricType* t = find_metric_type(entry.required<std::string>("type"));
  EXPECT_NE(t, nullptr);
  const MetricFunction f = t->factory(MetricSetup(entry, specs, step, duration));
  entry.reject_unknown();
  return f(log);
}

/// Success when loading the metric (its factory, then the unknown-key check, as the scenario
/// loader does) throws an InputError whose message is "m.yaml:<line>: <expected>...", i.e.
/// `expected` starts with the offending key: "stat: required key is missing".
inline ::testing::AssertionResult metric_fails(const RunLog& log, const std::string& yaml, double step, double duration,
                                               const std::string& expected) {
  std::vector<SignalSpec> specs;
  for (const auto& s : log.signals) specs.push_back(s.spec);
  try {
    const YamlMap entry(load_yaml_string(yaml, "m.yaml"), "m.yaml");
    const MetricType* t = find_metric_type(entry.required<std::string>("type"));
    if (t == nullptr) return ::testing::AssertionFailure() << "no metric type in " << yaml;
    t->factory(MetricSetup(entry, specs, step, duration));
    entry.reject_unknown();
  } catch (const InputError& e) {
    const std::string msg = e.what();
    if (msg.rfind("m.yaml:", 0) == 0 && msg.find(": " + expected) != std::string::npos)
      return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << yaml << "\n  message: " << msg << "\n  expected: ...: " << expected;
  }
  return ::testing::AssertionFailure() << yaml << " loads without an error (expected: " << expected << ")";
}

}  // namespace plexus::scenario::testing
