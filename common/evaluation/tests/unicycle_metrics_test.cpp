// Unicycle metrics (unicycle_metrics.cpp) on synthetic runs whose answer is known in closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "plexus/base/yaml_reader.hpp"
#include "plexus/scenario/metric.hpp"

namespace plexus::scenario {
namespace {

constexpr double kStep = 0.1;
constexpr int64_t kSteps = 200;  // 20 s

/// A heading-observer run: theta = 0.3 t, commanded speed v(t), gain L, and an estimate
/// whose error is e(t) = R(theta) e0 exp(-L int_0^t v) (paper 000 eq. (8) integrated), so
/// V_o = |e0|^2 / 2 exp(-2 L int v). Also a path signal with h = -e^{-t}, hx = 3.
RunLog observer_run(double L, double v0, double v1) {
  RunLog log;
  log.base_step = kStep;
  log.steps = kSteps;
  SignalTrace state{{"r/truth/state", {"x", "y", "theta"}, 1, "plant", true, ""}, {}, {}};
  SignalTrace cmd{{"r/cmd", {"v", "omega"}, 1, "ctl", false, ""}, {}, {}};
  SignalTrace est{{"r/heading", {"theta", "z3", "z4", "L"}, 1, "obs", false, ""}, {}, {}};
  SignalTrace path{{"r/path", {"h", "hx"}, 1, "path", false, ""}, {}, {}};
  double integral = 0.0;  // int_0^t v
  for (int64_t k = 0; k <= kSteps; ++k) {
    const double t = static_cast<double>(k) * kStep;
    const double v = v0 + v1 * std::sin(t);
    if (k > 0) integral += kStep * (v0 + v1 * std::sin(t - 0.5 * kStep));  // midpoint
    const double th = 0.3 * t, decay = std::exp(-L * integral);
    const double e3 = decay * (0.6 * std::cos(th) - 0.2 * std::sin(th));
    const double e4 = decay * (0.6 * std::sin(th) + 0.2 * std::cos(th));
    for (auto* tr : {&state, &cmd, &est, &path}) tr->steps.push_back(k);
    state.values.insert(state.values.end(), {0.0, 0.0, th});
    cmd.values.insert(cmd.values.end(), {v, 0.3});
    est.values.insert(est.values.end(), {th, std::cos(th) - e3, std::sin(th) - e4, L});
    path.values.insert(path.values.end(), {-std::exp(-t), 3.0});
  }
  log.signals = {state, cmd, est, path};
  return log;
}

MetricResult compute(const RunLog& log, const std::string& yaml) {
  std::vector<SignalSpec> specs;
  for (const auto& s : log.signals) specs.push_back(s.spec);
  const YamlMap entry(load_yaml_string(yaml, "m.yaml"), "m.yaml");
  const MetricType* t = find_metric_type(entry.required<std::string>("type"));
  EXPECT_NE(t, nullptr);
  const MetricFunction f = t->factory(MetricSetup(entry, specs, kStep, kStep * kSteps));
  entry.reject_unknown();
  return f(log);
}

const char* kDecay = "{type: observer_decay_rate, state: r/truth/state, estimate: r/heading}";
const char* kBound = "{type: observer_rate_bound, estimate: r/heading, cmd: r/cmd}";
const char* kRatio = "{type: observer_decay_ratio, state: r/truth/state, estimate: r/heading, cmd: r/cmd}";

TEST(UnicycleMetrics, DecayRateOfAnExactExponentialIsItsRate) {
  const RunLog log = observer_run(1.5, 0.2, 0.0);  // V_o ~ exp(-2 * 1.5 * 0.2 t)
  const MetricResult r = compute(log, kDecay);
  EXPECT_NEAR(r.value, 0.6, 1e-9);
  ASSERT_EQ(r.series.size(), static_cast<std::size_t>(kSteps + 1));
  EXPECT_NEAR(r.series.front().second, 0.5 * (0.36 + 0.04), 1e-12);  // V_o(0) = |e0|^2 / 2
  EXPECT_NEAR(compute(log, kBound).value, 0.6, 1e-12);               // 2 L v_min
  EXPECT_NEAR(compute(log, kRatio).value, 1.0, 1e-9);
}

// Theorem 1's claim as the metrics state it: with a varying speed the fitted rate lies
// between 2 L v_min and 2 L v_max (a weighted mean of 2 L v(t)), so the ratio is >= 1.
TEST(UnicycleMetrics, RatioIsAtLeastOneForAVaryingSpeed) {
  const RunLog log = observer_run(0.8, 0.15, 0.1);  // v in [0.05, 0.25]
  const double bound = compute(log, kBound).value;
  EXPECT_NEAR(bound, 2 * 0.8 * 0.05, 1e-4);
  const double ratio = compute(log, kRatio).value;
  EXPECT_GT(ratio, 1.0);
  EXPECT_LE(ratio * bound, 2 * 0.8 * 0.25);
}

TEST(UnicycleMetrics, WindowRestrictsTheFit) {
  const RunLog log = observer_run(1.0, 0.3, 0.0);
  const MetricResult r =
      compute(log, "{type: observer_decay_rate, state: r/truth/state, estimate: r/heading, from: 10, to: 15}");
  EXPECT_NEAR(r.value, 0.6, 1e-9);
  EXPECT_EQ(r.series.size(), 51u);
}

TEST(UnicycleMetrics, VelocityObserverErrorAndNormFinal) {
  // theta = 0.3 t, v = 2, estimate (z2, z4) = v (cos, sin) theta - (0.1, -0.2) e^{-t}.
  RunLog log;
  log.base_step = kStep;
  log.steps = kSteps;
  SignalTrace state{{"r/truth/state", {"theta"}, 1, "plant", true, ""}, {}, {}};
  SignalTrace cmd{{"r/cmd", {"v"}, 2, "ctl", false, ""}, {}, {}};  // every other step: held
  SignalTrace est{{"r/heading", {"z2", "z4"}, 1, "obs", false, ""}, {}, {}};
  for (int64_t k = 0; k <= kSteps; ++k) {
    const double t = static_cast<double>(k) * kStep, th = 0.3 * t;
    state.steps.push_back(k);
    state.values.push_back(th);
    if (k % 2 == 0) {
      cmd.steps.push_back(k);
      cmd.values.push_back(2.0);
    }
    est.steps.push_back(k);
    est.values.insert(est.values.end(), {2 * std::cos(th) - 0.1 * std::exp(-t), 2 * std::sin(th) + 0.2 * std::exp(-t)});
  }
  log.signals = {state, cmd, est};
  const MetricResult r =
      compute(log, "{type: velocity_observer_error_final, state: r/truth/state, cmd: r/cmd, estimate: r/heading}");
  EXPECT_NEAR(r.value, std::sqrt(0.05) * std::exp(-20.0), 1e-15);
  ASSERT_EQ(r.series.size(), static_cast<std::size_t>(kSteps + 1));
  EXPECT_NEAR(r.series.front().second, std::sqrt(0.05), 1e-12);
}

TEST(UnicycleMetrics, NormFinal) {
  const RunLog log = observer_run(1.0, 0.3, 0.0);
  EXPECT_NEAR(compute(log, "{type: value_norm_final, signal: r/path, fields: [h]}").value, std::exp(-20.0), 1e-15);
  EXPECT_NEAR(compute(log, "{type: value_norm_final, signal: r/path, fields: [h, hx]}").value,
              std::hypot(std::exp(-20.0), 3.0), 1e-12);
}

TEST(UnicycleMetrics, MissingFieldsAreConfigurationErrors) {
  const RunLog log = observer_run(1.0, 0.3, 0.0);
  EXPECT_THROW(compute(log, "{type: observer_decay_rate, state: r/cmd, estimate: r/heading}"), InputError);
  EXPECT_THROW(compute(log, "{type: observer_rate_bound, estimate: r/truth/state, cmd: r/cmd}"), InputError);
  EXPECT_THROW(compute(log, "{type: value_norm_final, signal: r/path, fields: [z]}"), InputError);
}

}  // namespace
}  // namespace plexus::scenario
