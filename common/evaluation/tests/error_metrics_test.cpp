// Built-in error and value metrics (error_metrics.cpp) on synthetic runs whose answer is
// known in closed form (metrics_test.cpp checks them on a four-sample log).
//
// Sums used below, with 100 samples per period over whole periods:
//   sum sin = 0, sum sin^2 = (samples) / 2, and over one period
//   sum_{k=0}^{99} |sin(2 pi k / 100)| = 2 sum_{k=0}^{49} sin(pi k / 50) = 2 cot(pi / 100)
//   (sum_{k=0}^{n-1} sin(pi k / n) = cot(pi / (2 n))): the discrete mean of |sin|,
//   cot(pi / 100) / 50 = 0.63641..., close to the continuous 2 / pi = 0.63662.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "metric_on_log.hpp"
#include "plexus/scenario/metric.hpp"

namespace plexus::scenario {
namespace {

constexpr double kStep = 0.01;   // 100 samples per 1 s period
constexpr int64_t kSteps = 400;  // 4 s
constexpr double kDuration = kStep * kSteps;
constexpr double kPi = std::numbers::pi;

/// Reference r/ref stored as (y, x, z) = (0.1 t^2, 0.3 t, 1), recorded every other step from
/// step `ref_start` (held at the odd steps); the estimate r/est (x, y, z, v) is the held
/// reference plus (3 sin(2 pi t), 4 sin(2 pi t), 12), so its distance over [x, y] is
/// 5 |sin(2 pi t)|; v = -2 + 3 sin(2 pi t). r/aux (v) has no position.
RunLog error_run(int64_t ref_start = 0) {
  RunLog log;
  log.base_step = kStep;
  log.steps = kSteps;
  SignalTrace ref{{"r/ref", {"y", "x", "z"}, 2, "ref", false, ""}, {}, {}};
  SignalTrace est{{"r/est", {"x", "y", "z", "v"}, 1, "est", false, ""}, {}, {}};
  SignalTrace aux{{"r/aux", {"v"}, 1, "aux", false, ""}, {}, {}};
  for (int64_t k = 0; k <= kSteps; ++k) {
    const double t = static_cast<double>(k) * kStep;
    const double th = static_cast<double>(k - k % 2) * kStep;  // time of the held reference sample
    const double rx = 0.3 * th, ry = 0.1 * th * th, rz = 1.0;
    if (k % 2 == 0 && k >= ref_start) {
      ref.steps.push_back(k);
      ref.values.insert(ref.values.end(), {ry, rx, rz});
    }
    const double s = std::sin(2 * kPi * t);
    est.steps.push_back(k);
    est.values.insert(est.values.end(), {rx + 3 * s, ry + 4 * s, rz + 12, -2 + 3 * s});
    aux.steps.push_back(k);
    aux.values.push_back(s);
  }
  log.signals = {ref, est, aux};
  return log;
}

MetricResult compute(const RunLog& log, const std::string& yaml) {
  return testing::metric_on_log(log, yaml, kStep, kDuration);
}

const std::string kWhole = ", to: 3.99";  // 400 samples: 4 whole periods

double error(const RunLog& log, const std::string& type, const std::string& rest = kWhole) {
  return compute(log, "{type: " + type + ", signal: r/est, reference: r/ref" + rest + "}").value;
}

TEST(ErrorMetrics, DistanceOfARectifiedSine) {
  const RunLog log = error_run();
  // Default fields [x, y]: |(3, 4) sin| = 5 |sin(2 pi t)|.
  EXPECT_NEAR(error(log, "error_max"), 5.0, 1e-9);                   // t = 0.25
  EXPECT_NEAR(error(log, "error_rms"), 5.0 / std::sqrt(2.0), 1e-9);  // 5 / sqrt 2
  EXPECT_NEAR(error(log, "error_mean"), 5.0 * std::cos(kPi / 100) / std::sin(kPi / 100) / 50.0,
              1e-9);                                                             // 5 cot(pi/100) / 50
  EXPECT_NEAR(error(log, "error_final", ", to: 3.75"), 5.0, 1e-9);               // |sin 7.5 pi|
  EXPECT_NEAR(error(log, "error_final", ""), 0.0, 1e-9);                         // t = 4: sin 8 pi
  EXPECT_NEAR(error(log, "error_final"), 5.0 * std::sin(2 * kPi * 0.01), 1e-9);  // t = 3.99
  const MetricResult r = compute(log, "{type: error_rms, signal: r/est, reference: r/ref}");
  ASSERT_EQ(r.series.size(), static_cast<std::size_t>(kSteps + 1));
  EXPECT_NEAR(r.series[75].first, 0.75, 1e-12);
  EXPECT_NEAR(r.series[75].second, 5.0, 1e-9);  // the series is the distance, >= 0
}

TEST(ErrorMetrics, FieldsAreMatchedByNameAndNormed) {
  const RunLog log = error_run();
  EXPECT_NEAR(error(log, "error_rms", ", fields: [x]" + kWhole), 3.0 / std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(error(log, "error_max", ", fields: [y]" + kWhole), 4.0, 1e-9);
  // + a constant 12 in z: sqrt(25 / 2 + 144).
  EXPECT_NEAR(error(log, "error_rms", ", fields: [x, y, z]" + kWhole), std::sqrt(156.5), 1e-9);
  EXPECT_NEAR(error(log, "error_mean", ", fields: [z]" + kWhole), 12.0, 1e-9);
  EXPECT_NEAR(error(log, "error_final", ", fields: [z]"), 12.0, 1e-9);
}

TEST(ErrorMetrics, WindowIncludesBothEnds) {
  const RunLog log = error_run();
  // [1.75, 1.75]: one sample, distance 5.
  EXPECT_NEAR(error(log, "error_mean", ", from: 1.75, to: 1.75"), 5.0, 1e-9);
  // [1, 1.99]: one whole period, the same RMS and mean as the whole run's.
  EXPECT_NEAR(error(log, "error_rms", ", from: 1, to: 1.99"), 5.0 / std::sqrt(2.0), 1e-9);
  EXPECT_EQ(compute(log, "{type: error_max, signal: r/est, reference: r/ref, from: 1, to: 1.99}").series.size(), 100u);
}

TEST(ErrorMetrics, SamplesBeforeTheFirstReferenceAreSkipped) {
  // Reference from t = 0.5 on: the series starts there (351 samples); over [0.5, 3.99]
  // (3.5 periods) the max is still 5 (t = 0.75).
  const RunLog log = error_run(50);
  const MetricResult r = compute(log, "{type: error_max, signal: r/est, reference: r/ref}");
  ASSERT_EQ(r.series.size(), 351u);
  EXPECT_NEAR(r.series.front().first, 0.5, 1e-12);
  EXPECT_NEAR(r.value, 5.0, 1e-9);
  // A window wholly before the reference has no samples: NaN.
  EXPECT_TRUE(std::isnan(error(log, "error_max", ", to: 0.4")));
}

TEST(ErrorMetrics, ValueStatisticsOfAnOffsetSine) {
  const RunLog log = error_run();
  // v = -2 + 3 sin(2 pi t) over 4 whole periods.
  const std::string m = "{signal: r/est, field: v" + kWhole + ", type: ";
  EXPECT_NEAR(compute(log, m + "value_mean}").value, -2.0, 1e-9);
  EXPECT_NEAR(compute(log, m + "value_max}").value, 1.0, 1e-9);      // t = 0.25
  EXPECT_NEAR(compute(log, m + "value_min}").value, -5.0, 1e-9);     // t = 0.75
  EXPECT_NEAR(compute(log, m + "value_max_abs}").value, 5.0, 1e-9);  // |min|, not max
  EXPECT_NEAR(compute(log, m + "value_final}").value, -2.0 + 3.0 * std::sin(2 * kPi * 3.99), 1e-9);
  EXPECT_NEAR(compute(log, "{type: value_final, signal: r/est, field: v, to: 0.75}").value, -5.0, 1e-9);
  EXPECT_NEAR(compute(log, "{type: value_final, signal: r/est, field: v}").value, -2.0, 1e-9);  // t = 4
  // max_abs over [0, 0.5] (the positive half-period, v = -2 + 3 sin in [-2, 1]): 2.
  EXPECT_NEAR(compute(log, "{type: value_max_abs, signal: r/est, field: v, to: 0.5}").value, 2.0, 1e-9);
}

TEST(ErrorMetrics, ConfigurationErrorsNameTheKey) {
  const RunLog log = error_run();
  auto fails = [&](const std::string& yaml, const std::string& expected) {
    return testing::metric_fails(log, yaml, kStep, kDuration, expected);
  };
  const std::string e = "{type: error_rms, signal: r/est, reference: r/ref";
  EXPECT_TRUE(fails(e + ", fields: [v]}", "fields: signal 'r/ref' has no field 'v'"));
  EXPECT_TRUE(fails(e + ", fields: [x, w]}", "fields: signal 'r/est' has no field 'w'"));
  // The default fields [x, y] are checked too, under the key's name.
  EXPECT_TRUE(fails("{type: error_max, signal: r/aux, reference: r/ref}", "fields: signal 'r/aux' has no field 'x'"));
  EXPECT_TRUE(fails("{type: error_final, signal: r/est}", "reference: required key is missing"));
  EXPECT_TRUE(fails("{type: error_mean, signal: r/est, reference: r/none}", "reference: no signal 'r/none'"));
  EXPECT_TRUE(fails(e + ", from: 2, to: 1}", "to: must be in [from, duration]"));
  EXPECT_TRUE(fails(e + ", from: 4.5}", "from: must be in [0, duration]"));
  EXPECT_TRUE(fails(e + ", field: x}", "field: unknown key"));
  EXPECT_TRUE(fails("{type: value_final, signal: r/est}", "field: required key is missing"));
  EXPECT_TRUE(fails("{type: value_max_abs, signal: r/est, field: w}", "field: signal 'r/est' has no field 'w'"));
  EXPECT_TRUE(fails("{type: value_max, signal: r/est, field: v, fields: [v]}", "fields: unknown key"));
  EXPECT_TRUE(fails("{type: value_min, signal: r/est, field: v, to: -1}", "to: must be in [from, duration]"));
}

// ratio (ratio_metric.cpp): one metric of the run over another. error_max = 5 (above) over
// value_max_abs of v on [0, 0.5] = 2 gives 2.5; a zero denominator gives NaN, not inf.
TEST(RatioMetric, DividesTwoMetricsOfTheSameRun) {
  const RunLog log = error_run();
  auto compute = [&](const std::string& yaml) { return testing::metric_on_log(log, yaml, kStep, kDuration); };
  const std::string num = "numerator: {type: error_max, signal: r/est, reference: r/ref}";
  EXPECT_NEAR(
      compute("{type: ratio, " + num + ", denominator: {type: value_max_abs, signal: r/est, field: v, to: 0.5}}").value,
      2.5, 1e-9);
  EXPECT_NEAR(compute("{type: ratio, numerator: {type: value_max_abs, signal: r/est, field: v, to: 0.5}, "
                      "denominator: {type: error_max, signal: r/est, reference: r/ref}}")
                  .value,
              0.4, 1e-9);
  // r/aux's v = sin(2 pi t) is exactly 0 at t = 0: the ratio is NaN (null), not inf.
  EXPECT_TRUE(std::isnan(
      compute("{type: ratio, " + num + ", denominator: {type: value_final, signal: r/aux, field: v, to: 0}}").value));
}

TEST(RatioMetric, PartsAreValidatedAsMetricsNamingTheirKey) {
  const RunLog log = error_run();
  auto fails = [&](const std::string& yaml, const std::string& expected) {
    return testing::metric_fails(log, yaml, kStep, kDuration, expected);
  };
  const std::string num = "numerator: {type: error_max, signal: r/est, reference: r/ref}";
  EXPECT_TRUE(fails("{type: ratio, " + num + "}", "denominator: required"));
  EXPECT_TRUE(
      fails("{type: ratio, " + num + ", denominator: {type: nope}}", "denominator.type: unknown metric type 'nope'"));
  EXPECT_TRUE(fails("{type: ratio, " + num + ", denominator: {type: error_max, signal: r/est}}",
                    "denominator.reference: required key is missing"));
  EXPECT_TRUE(fails("{type: ratio, " + num + ", denominator: {type: value_max, signal: r/est, field: v, band: 1}}",
                    "denominator.band: unknown key"));
  EXPECT_TRUE(fails("{type: ratio, " + num + ", denominator: {type: ratio}}",
                    "denominator.type: a ratio's parts cannot be ratios"));
}

}  // namespace
}  // namespace plexus::scenario
