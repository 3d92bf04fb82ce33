// Skid-steer metrics (skid_steer_metrics.cpp) on synthetic runs whose answer is known in
// closed form: ICR estimates that approach each new true value exponentially.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "metric_on_log.hpp"
#include "plexus/scenario/metric.hpp"

namespace plexus::scenario {
namespace {

constexpr double kStep = 0.01;
constexpr int64_t kSteps = 3000;  // 30 s
constexpr double kSwitch1 = 5.0, kSwitch2 = 15.0;
constexpr double kTau1 = 0.5, kTau2 = 1.5;  // s, time constants of the estimate after each switch

/// Truth: ICRs (0.3, -0.5, -0.1) until kSwitch1, then (0.5, -0.7, -0.3), from kSwitch2
/// (0.5, -0.6, -0.3) (x_G and y_l unchanged at the second switch). The estimate starts on
/// the truth and approaches each new value as new + (old - new) exp(-(t - switch) / tau).
/// Two odometry signals with constant position errors 0.3 m and 0.6 m.
RunLog switching_run() {
  RunLog log;
  log.base_step = kStep;
  log.steps = kSteps;
  SignalTrace state{{"r/truth/state", {"x", "y", "y_l", "y_r", "x_G"}, 1, "plant", true, ""}, {}, {}};
  SignalTrace est{{"r/icr", {"y_l", "y_r", "x_G"}, 1, "ekf", false, ""}, {}, {}};
  SignalTrace odo_a{{"r/odo_a", {"x", "y"}, 1, "a", false, ""}, {}, {}};
  SignalTrace odo_b{{"r/odo_b", {"x", "y"}, 1, "b", false, ""}, {}, {}};
  const double a[3] = {0.3, -0.5, -0.1}, b[3] = {0.5, -0.7, -0.3}, c[3] = {0.5, -0.6, -0.3};
  for (int64_t k = 0; k <= kSteps; ++k) {
    const double t = static_cast<double>(k) * kStep;
    const double x = 0.4 * t, y = std::sin(t);
    const double* truth = t < kSwitch1 - 1e-9 ? a : (t < kSwitch2 - 1e-9 ? b : c);
    double e[3];
    for (int i = 0; i < 3; ++i) {
      if (truth == a)
        e[i] = a[i];
      else if (truth == b)
        e[i] = b[i] + (a[i] - b[i]) * std::exp(-(t - kSwitch1) / kTau1);
      else
        e[i] = c[i] + (b[i] - c[i]) * std::exp(-(t - kSwitch2) / kTau2);
    }
    for (auto* tr : {&state, &est, &odo_a, &odo_b}) tr->steps.push_back(k);
    state.values.insert(state.values.end(), {x, y, truth[0], truth[1], truth[2]});
    est.values.insert(est.values.end(), {e[0], e[1], e[2]});
    odo_a.values.insert(odo_a.values.end(), {x + 0.3, y});
    odo_b.values.insert(odo_b.values.end(), {x, y - 0.6});
  }
  log.signals = {state, est, odo_a, odo_b};
  return log;
}

MetricResult compute(const RunLog& log, const std::string& yaml) {
  return testing::metric_on_log(log, yaml, kStep, kStep * kSteps);
}

// The metrics count from the last sample on the old truth (one step before the switch) to
// the first sample past the threshold (up to one step after the crossing): within 2 steps.
constexpr double kTol = 2.5 * kStep;

TEST(SkidSteerMetrics, ReconvergenceTimeIsTheTimeToEnterTheBandForGood) {
  const RunLog log = switching_run();
  const std::string m = "{type: icr_reconvergence_time, estimate: r/icr, truth: r/truth/state, tolerance: 0.02";
  // Switch 1: steps of 0.2 m, tau 0.5 s -> 0.5 ln(10); switch 2: 0.1 m, tau 1.5 s -> 1.5 ln(5).
  const double t1 = kTau1 * std::log(0.2 / 0.02), t2 = kTau2 * std::log(0.1 / 0.02);
  EXPECT_NEAR(compute(log, m + ", switch: 1}").value, t1, kTol);
  EXPECT_NEAR(compute(log, m + ", switch: 2}").value, t2, kTol);
  EXPECT_NEAR(compute(log, m + "}").value, std::max(t1, t2), kTol);
  EXPECT_TRUE(std::isnan(compute(log, m + ", switch: 3}").value));
}

TEST(SkidSteerMetrics, ReconvergenceRiseTimeIsTheTimeToCoverNinetyPercentOfTheStep) {
  const RunLog log = switching_run();
  const std::string m = "{type: icr_reconvergence_rise_time, estimate: r/icr, truth: r/truth/state";
  // 90 % of an exponential step after tau ln(10), whatever the step's size; the fields that
  // do not change at the second switch (y_l, x_G) are skipped.
  EXPECT_NEAR(compute(log, m + ", switch: 1}").value, kTau1 * std::log(10.0), kTol);
  EXPECT_NEAR(compute(log, m + ", switch: 2}").value, kTau2 * std::log(10.0), kTol);
  EXPECT_NEAR(compute(log, m + ", fraction: 0.5}").value, kTau2 * std::log(2.0), kTol);
}

TEST(SkidSteerMetrics, ReconvergenceIsTheRunLengthWhenTheEstimateNeverGetsThere) {
  RunLog log = switching_run();
  // Freeze the estimate after the first switch: it never moves towards the new truth.
  SignalTrace& est = log.signals[1];
  for (std::size_t i = 0; i < est.steps.size(); ++i) {
    if (static_cast<double>(est.steps[i]) * kStep >= kSwitch1) {
      est.values[3 * i] = 0.3, est.values[3 * i + 1] = -0.5, est.values[3 * i + 2] = -0.1;
    }
  }
  const double run = kStep * kSteps;
  EXPECT_EQ(compute(log, "{type: icr_reconvergence_time, estimate: r/icr, truth: r/truth/state}").value, run);
  EXPECT_EQ(compute(log, "{type: icr_reconvergence_rise_time, estimate: r/icr, truth: r/truth/state}").value, run);
}

TEST(SkidSteerMetrics, ReconvergenceWindowAndFieldsChooseTheSwitches) {
  const RunLog log = switching_run();
  const std::string m = "{type: icr_reconvergence_time, estimate: r/icr, truth: r/truth/state";
  const double t1 = kTau1 * std::log(0.2 / 0.02), t2 = kTau2 * std::log(0.1 / 0.02);
  // `switch: 0` is the default: the largest over the switches.
  EXPECT_NEAR(compute(log, m + ", switch: 0}").value, std::max(t1, t2), kTol);
  // From 10 s the window holds the second switch only: it becomes switch 1.
  EXPECT_NEAR(compute(log, m + ", from: 10}").value, t2, kTol);
  EXPECT_NEAR(compute(log, m + ", from: 10, switch: 1}").value, t2, kTol);
  EXPECT_TRUE(std::isnan(compute(log, m + ", from: 10, switch: 2}").value));
  // From 20 s the truth never changes: NaN.
  EXPECT_TRUE(std::isnan(compute(log, m + ", from: 20}").value));
  // x_G changes at the first switch only (-0.1 -> -0.3, the same 0.2 step and tau 0.5 s).
  EXPECT_NEAR(compute(log, m + ", fields: [x_G]}").value, t1, kTol);
  EXPECT_TRUE(std::isnan(compute(log, m + ", fields: [x_G], switch: 2}").value));
  const std::string rise = "{type: icr_reconvergence_rise_time, estimate: r/icr, truth: r/truth/state";
  EXPECT_NEAR(compute(log, rise + ", fields: [x_G]}").value, kTau1 * std::log(10.0), kTol);
  EXPECT_TRUE(std::isnan(compute(log, rise + ", from: 20}").value));
}

/// One field (y_l) whose truth steps 0 -> 1 at step 10 (t = 2.5 s; base step 0.25 s, so
/// every value below is exact): the switch is counted from the last sample on the old
/// truth, t = 2.25. The estimate is 0 up to step 9, 0.5 at steps 10-11, 0.8 at step 12 (in
/// a 0.25 band, past 75 % and 80 % of the step), 0.5 again at steps 13-14, then exactly
/// 0.75 (error = 0.25, on the band's edge) to the end (step 40, 10 s).
RunLog excursion_run() {
  RunLog log;
  log.base_step = 0.25;
  log.steps = 40;
  SignalTrace truth{{"r/truth/state", {"x", "y", "y_l", "y_r", "x_G"}, 1, "plant", true, ""}, {}, {}};
  SignalTrace est{{"r/icr", {"y_l", "y_r", "x_G"}, 1, "ekf", false, ""}, {}, {}};
  for (int64_t k = 0; k <= 40; ++k) {
    const double e = k < 10 ? 0.0 : (k < 12 ? 0.5 : (k == 12 ? 0.8 : (k < 15 ? 0.5 : 0.75)));
    truth.steps.push_back(k);
    truth.values.insert(truth.values.end(), {0.0, 0.0, k < 10 ? 0.0 : 1.0, -0.5, 0.1});
    est.steps.push_back(k);
    est.values.insert(est.values.end(), {e, -0.5, 0.1});
  }
  log.signals = {truth, est};
  return log;
}

TEST(SkidSteerMetrics, ReconvergenceIsForGoodAndItsToleranceIncludesTheEdge) {
  const RunLog log = excursion_run();
  auto value = [&](const std::string& yaml) { return testing::metric_on_log(log, yaml, 0.25, 10.0).value; };
  const std::string m = "{type: icr_reconvergence_time, estimate: r/icr, truth: r/truth/state";
  // In the band at step 12 but out again at 13-14; in for good from step 15 (error exactly
  // 0.25 <= tolerance): 15 * 0.25 - 2.25 = 1.5 s.
  EXPECT_DOUBLE_EQ(value(m + ", tolerance: 0.25}"), 1.5);
  EXPECT_DOUBLE_EQ(value(m + ", tolerance: 0.25, switch: 1}"), 1.5);
  // Just inside the edge the estimate never re-converges: the run length.
  EXPECT_DOUBLE_EQ(value(m + ", tolerance: 0.2499}"), 10.0);
  // A wide band holds from step 10 on (error 0.5): one step after the switch.
  EXPECT_DOUBLE_EQ(value(m + ", tolerance: 0.5}"), 0.25);
  const std::string rise = "{type: icr_reconvergence_rise_time, estimate: r/icr, truth: r/truth/state";
  // The rise time is the first crossing: step 12 (0.8 >= 0.75 and >= 0.8, exactly), 0.75 s,
  // even though the estimate falls back afterwards.
  EXPECT_DOUBLE_EQ(value(rise + ", fraction: 0.75}"), 0.75);
  EXPECT_DOUBLE_EQ(value(rise + ", fraction: 0.8}"), 0.75);
  EXPECT_DOUBLE_EQ(value(rise + ", fraction: 0.5}"), 0.25);   // step 10: 0.5 >= 0.5
  EXPECT_DOUBLE_EQ(value(rise + ", fraction: 0.81}"), 10.0);  // never: the run length
  EXPECT_DOUBLE_EQ(value(rise + ", fraction: 1}"), 10.0);
}

TEST(SkidSteerMetrics, ReconvergenceConfigurationErrorsNameTheKey) {
  const RunLog log = switching_run();
  auto fails = [&](const std::string& yaml, const std::string& expected) {
    return testing::metric_fails(log, yaml, kStep, kStep * kSteps, expected);
  };
  const std::string m = "{type: icr_reconvergence_time, estimate: r/icr, truth: r/truth/state";
  const std::string rise = "{type: icr_reconvergence_rise_time, estimate: r/icr, truth: r/truth/state";
  EXPECT_TRUE(fails(m + ", switch: -1}", "switch: must be >= 1 (or 0: the largest over the switches)"));
  EXPECT_TRUE(fails(rise + ", switch: -2}", "switch: must be >= 1"));
  EXPECT_TRUE(fails(m + ", tolerance: 0}", "tolerance: must be > 0"));
  EXPECT_TRUE(fails(rise + ", fraction: 0}", "fraction: must be in (0, 1]"));
  EXPECT_TRUE(fails(rise + ", fraction: 1.5}", "fraction: must be in (0, 1]"));
  EXPECT_TRUE(fails(rise + ", tolerance: 0.02}", "tolerance: unknown key"));
  EXPECT_TRUE(fails(m + ", fields: [y_l, q]}", "fields: signal 'r/icr' has no field 'q'"));
  EXPECT_TRUE(fails("{type: icr_reconvergence_time, estimate: r/odo_a, truth: r/truth/state}",
                    "fields: signal 'r/odo_a' has no field 'y_l'"));
  EXPECT_TRUE(fails(m + ", to: 31}", "to: must be in [from, duration]"));
}

TEST(SkidSteerMetrics, OdometryErrorRatioDividesTheFinalPositionErrors) {
  const RunLog log = switching_run();
  EXPECT_NEAR(
      compute(log, "{type: odometry_error_ratio, signal: r/odo_a, other: r/odo_b, reference: r/truth/state}").value,
      0.5, 1e-12);
  EXPECT_NEAR(
      compute(log, "{type: odometry_error_ratio, signal: r/odo_b, other: r/odo_a, reference: r/truth/state}").value,
      2.0, 1e-12);
}

}  // namespace
}  // namespace plexus::scenario
