// Test helper: evaluate one metric (given as a YAML entry) on a synthetic RunLog.
// The skid-steer metric tests use it; unicycle_metrics_test.cpp and metrics_test.cpp still
// carry their own copy of the same few lines and can switch to it.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

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

}  // namespace plexus::scenario::testing
