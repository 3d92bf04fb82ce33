// Arm metrics (arm_metrics.cpp): tracking_rms and settling_time on synthetic runs whose
// answer is known in closed form.
//
// Sums used below: with N samples per period (N > 2) over whole periods,
//   sum sin(2 pi k / N) = sum cos(2 pi k / N) = 0 and sum sin^2 = sum cos^2 = (samples) / 2,
// so the RMS of A sin is A / sqrt(2) and of (A sin, B cos) is sqrt((A^2 + B^2) / 2).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "metric_on_log.hpp"
#include "plexus/scenario/metric.hpp"

namespace plexus::scenario {
namespace {

constexpr double kStep = 0.01;   // 100 samples per 1 s period
constexpr int64_t kSteps = 500;  // 5 s
constexpr double kDuration = kStep * kSteps;
constexpr double kPi = std::numbers::pi;
constexpr double kA = 3e-3, kB = 4e-3, kC = 2e-3;  // rad
constexpr double kTransient = 0.1;                 // rad, added to e1 for t < 1 s

/// Joint reference q_ref = (0.5 sin 0.3t, 0.2 cos 0.7t, 0.1), recorded every other step (held
/// at the odd steps) and stored as (q3, q1, q2); the joints follow it with errors
///   e1 = A sin(2 pi t) (+ kTransient for t < 1), e2 = B cos(2 pi t), e3 = C
/// against the reference as held at each step.
RunLog tracking_run() {
  RunLog log;
  log.base_step = kStep;
  log.steps = kSteps;
  SignalTrace q{{"arm/q", {"q1", "q2", "q3", "dq1"}, 1, "plant", true, ""}, {}, {}};
  SignalTrace ref{{"arm/q_ref", {"q3", "q1", "q2"}, 2, "ref", false, ""}, {}, {}};
  for (int64_t k = 0; k <= kSteps; ++k) {
    const double t = static_cast<double>(k) * kStep;
    const double th = static_cast<double>(k - k % 2) * kStep;  // time of the held reference sample
    const double r1 = 0.5 * std::sin(0.3 * th), r2 = 0.2 * std::cos(0.7 * th), r3 = 0.1;
    if (k % 2 == 0) {
      ref.steps.push_back(k);
      ref.values.insert(ref.values.end(), {r3, r1, r2});
    }
    const double e1 = kA * std::sin(2 * kPi * t) + (k < 100 ? kTransient : 0.0);
    q.steps.push_back(k);
    q.values.insert(q.values.end(), {r1 + e1, r2 + kB * std::cos(2 * kPi * t), r3 + kC, 7.0});
  }
  log.signals = {q, ref};
  return log;
}

/// One joint against a constant reference 0.3 recorded once, at step 0 (held for the whole
/// run), with error e(t) given per step.
template <class Error>
RunLog settling_run(Error error) {
  RunLog log;
  log.base_step = kStep;
  log.steps = kSteps;
  SignalTrace q{{"arm/q", {"q1", "dq1"}, 1, "plant", true, ""}, {}, {}};
  SignalTrace ref{{"arm/q_ref", {"q1"}, 1, "ref", false, ""}, {0}, {0.3}};
  for (int64_t k = 0; k <= kSteps; ++k) {
    q.steps.push_back(k);
    q.values.insert(q.values.end(), {0.3 + error(k, static_cast<double>(k) * kStep), 0.0});
  }
  log.signals = {q, ref};
  return log;
}

/// e = -0.1 exp(-2 t): |e| enters the band b at t* = ln(0.1 / b) / 2 and stays in.
RunLog decay_run() {
  return settling_run([](int64_t, double t) { return -0.1 * std::exp(-2.0 * t); });
}

/// The first sample at or after t*: the settling time the metric reports (counted from 0).
double first_sample_after(double t_star) { return std::ceil(t_star / kStep) * kStep; }

MetricResult compute(const RunLog& log, const std::string& yaml) {
  return testing::metric_on_log(log, yaml, kStep, kDuration);
}

const std::string kRms = "{type: tracking_rms, signal: arm/q, reference: arm/q_ref";
const std::string kWhole = ", from: 1, to: 3.99";  // 300 samples, 3 whole periods, no transient

TEST(ArmMetrics, TrackingRmsOfOneFieldOverWholePeriods) {
  const RunLog log = tracking_run();
  EXPECT_NEAR(compute(log, kRms + ", fields: [q1]" + kWhole + "}").value, kA / std::sqrt(2.0), 1e-12);  // A / sqrt 2
  EXPECT_NEAR(compute(log, kRms + ", fields: [q2]" + kWhole + "}").value, kB / std::sqrt(2.0), 1e-12);  // B / sqrt 2
  EXPECT_NEAR(compute(log, kRms + ", fields: [q3]" + kWhole + "}").value, kC, 1e-12);  // a constant offset is its RMS
  // scale 1000 reports mrad: 3 mrad / sqrt 2; the series is |e| * scale at each sample.
  const MetricResult r = compute(log, kRms + ", fields: [q1], scale: 1000" + kWhole + "}");
  EXPECT_NEAR(r.value, 3.0 / std::sqrt(2.0), 1e-9);
  ASSERT_EQ(r.series.size(), 300u);
  EXPECT_NEAR(r.series.front().first, 1.0, 1e-12);
  EXPECT_NEAR(r.series.back().first, 3.99, 1e-12);
  EXPECT_NEAR(r.series[25].first, 1.25, 1e-12);
  EXPECT_NEAR(r.series[25].second, 3.0, 1e-9);  // sin(2.5 pi) = 1
}

TEST(ArmMetrics, TrackingRmsOfSeveralFieldsIsTheRmsOfTheErrorNorm) {
  const RunLog log = tracking_run();
  // |e|^2 = A^2 sin^2 + B^2 cos^2, mean (A^2 + B^2) / 2: RMS 5e-3 / sqrt 2 (eq. (62)).
  EXPECT_NEAR(compute(log, kRms + ", fields: [q1, q2]" + kWhole + "}").value, 5e-3 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(compute(log, kRms + ", fields: [q2, q1], scale: 1000" + kWhole + "}").value, 5.0 / std::sqrt(2.0), 1e-9);
  // + C^2: sqrt(12.5e-6 + 4e-6).
  EXPECT_NEAR(compute(log, kRms + ", fields: [q1, q2, q3]" + kWhole + "}").value, std::sqrt(16.5e-6), 1e-12);
}

TEST(ArmMetrics, TrackingRmsWindowIncludesBothEnds) {
  const RunLog log = tracking_run();
  // Whole run, 501 samples: sum e1^2 = 100 T^2 (the transient; its cross term sums sin over
  // a whole period: 0) + 500 A^2 / 2 (5 periods) + 0 (t = 5: sin 10 pi = 0).
  EXPECT_NEAR(compute(log, kRms + ", fields: [q1]}").value,
              std::sqrt((100 * kTransient * kTransient + 250 * kA * kA) / 501.0), 1e-12);
  // [0, 0.99]: the first period only, 100 samples: (100 T^2 + 50 A^2) / 100.
  EXPECT_NEAR(compute(log, kRms + ", fields: [q1], to: 0.99}").value,
              std::sqrt(kTransient * kTransient + 0.5 * kA * kA), 1e-12);
  // [1.25, 1.25]: the one sample at t = 1.25, e1 = A.
  const MetricResult one = compute(log, kRms + ", fields: [q1], from: 1.25, to: 1.25}");
  EXPECT_NEAR(one.value, kA, 1e-15);
  EXPECT_EQ(one.series.size(), 1u);
  // The constant offset has RMS C over any window.
  EXPECT_NEAR(compute(log, kRms + ", fields: [q3]}").value, kC, 1e-12);
}

const std::string kSettle = "{type: settling_time, signal: arm/q, reference: arm/q_ref, field: q1";

TEST(ArmMetrics, SettlingTimeOfAnExponentialDecay) {
  const RunLog log = decay_run();
  // band 1e-3: t* = ln(0.1 / 1e-3) / 2 = ln(100) / 2 = 2.3026 s -> the sample at 2.31 s.
  const double t_star = std::log(100.0) / 2.0;
  const MetricResult r = compute(log, kSettle + ", band: 1e-3}");
  EXPECT_GE(r.value, t_star);
  EXPECT_LT(r.value, t_star + kStep);
  EXPECT_NEAR(r.value, first_sample_after(t_star), 1e-9);
  ASSERT_EQ(r.series.size(), static_cast<std::size_t>(kSteps + 1));
  EXPECT_NEAR(r.series.front().second, 0.1, 1e-15);  // |e(0)|
  // Counted from `from`: 2.31 - 1.
  EXPECT_NEAR(compute(log, kSettle + ", band: 1e-3, from: 1}").value, first_sample_after(t_star) - 1.0, 1e-9);
  // The default band is the paper's 1.15e-3: t* = ln(0.1 / 1.15e-3) / 2 = 2.2326 s -> 2.24 s.
  EXPECT_NEAR(compute(log, kSettle + "}").value, first_sample_after(std::log(0.1 / 1.15e-3) / 2.0), 1e-9);
  // band 1e-2: t* = ln(10) / 2 = 1.1513 s -> 1.16 s.
  EXPECT_NEAR(compute(log, kSettle + ", band: 0.01}").value, first_sample_after(std::log(10.0) / 2.0), 1e-9);
}

TEST(ArmMetrics, SettlingTimeIsTheEntryAfterTheLastExcursion) {
  // The decay enters the 1e-3 band at 2.31 s, then leaves it (e = 2e-3 on [3.0, 3.2]) and
  // comes back: it settles for good at the first sample after the excursion, 3.21 s.
  const RunLog log =
      settling_run([](int64_t k, double t) { return k >= 300 && k <= 320 ? 2e-3 : -0.1 * std::exp(-2.0 * t); });
  EXPECT_NEAR(compute(log, kSettle + ", band: 1e-3}").value, 3.21, 1e-9);
  // A window that ends before the excursion sees the first entry only.
  EXPECT_NEAR(compute(log, kSettle + ", band: 1e-3, to: 2.9}").value, first_sample_after(std::log(100.0) / 2.0), 1e-9);
  // A window that ends inside the excursion: the last sample is outside, never settled (null).
  EXPECT_TRUE(std::isnan(compute(log, kSettle + ", band: 1e-3, to: 3.1}").value));
}

TEST(ArmMetrics, ANonFiniteErrorIsOutsideTheBand) {
  // A run that diverged (NaN from 2 s on) never settled; nor does one that blew up for a while.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(std::isnan(
      compute(settling_run([&](int64_t k, double) { return k >= 200 ? nan : 0.0; }), kSettle + ", band: 1e-3}").value));
  EXPECT_NEAR(compute(settling_run([&](int64_t k, double) { return k >= 100 && k <= 150 ? nan : 0.0; }),
                      kSettle + ", band: 1e-3}")
                  .value,
              1.51, 1e-9);
}

TEST(ArmMetrics, SettlingTimeIsNullWhenTheLastSampleIsOutsideAndZeroWhenNeverOutside) {
  // Constant error 2e-3 > band: never settles -> null (NaN), with the series still recorded.
  const MetricResult never = compute(settling_run([](int64_t, double) { return 2e-3; }), kSettle + ", band: 1e-3}");
  EXPECT_TRUE(std::isnan(never.value));
  EXPECT_EQ(never.series.size(), static_cast<std::size_t>(kSteps + 1));
  // Inside until the last sample only: still null.
  EXPECT_TRUE(std::isnan(
      compute(settling_run([](int64_t k, double) { return k == kSteps ? -2e-3 : 0.0; }), kSettle + ", band: 1e-3}")
          .value));
  // Never outside: 0, from the start of the window too.
  const RunLog inside = settling_run([](int64_t, double) { return -5e-4; });
  EXPECT_EQ(compute(inside, kSettle + ", band: 1e-3}").value, 0.0);
  EXPECT_NEAR(compute(inside, kSettle + ", band: 1e-3, from: 1.5}").value, 0.0, 1e-12);
  // The default band 1.15e-3 lies between 1.1e-3 (inside: 0) and 1.2e-3 (outside: null).
  EXPECT_EQ(compute(settling_run([](int64_t, double) { return 1.1e-3; }), kSettle + "}").value, 0.0);
  EXPECT_TRUE(std::isnan(compute(settling_run([](int64_t, double) { return 1.2e-3; }), kSettle + "}").value));
}

TEST(ArmMetrics, ConfigurationErrorsNameTheKey) {
  const RunLog log = tracking_run();
  auto fails = [&](const std::string& yaml, const std::string& expected) {
    return testing::metric_fails(log, yaml, kStep, kDuration, expected);
  };
  EXPECT_TRUE(fails(kRms + "}", "fields: needs at least one field"));
  EXPECT_TRUE(fails(kRms + ", fields: []}", "fields: needs 1 to"));
  EXPECT_TRUE(fails(kRms + ", fields: [q9]}", "fields: signal 'arm/q' has no field 'q9'"));
  EXPECT_TRUE(fails(kRms + ", fields: [dq1]}", "fields: signal 'arm/q_ref' has no field 'dq1'"));
  EXPECT_TRUE(fails(kRms + ", fields: [q1], scale: 0}", "scale: must be > 0"));
  EXPECT_TRUE(fails(kRms + ", fields: [q1], scale: -1000}", "scale: must be > 0"));
  EXPECT_TRUE(fails(kRms + ", fields: [q1], from: -1}", "from: must be in [0, duration]"));
  EXPECT_TRUE(fails(kRms + ", fields: [q1], from: 6}", "from: must be in [0, duration]"));
  EXPECT_TRUE(fails(kRms + ", fields: [q1], to: 6}", "to: must be in [from, duration]"));
  EXPECT_TRUE(fails(kRms + ", fields: [q1], from: 3, to: 2}", "to: must be in [from, duration]"));
  EXPECT_TRUE(fails(kRms + ", fields: [q1], field: q1}", "field: unknown key"));
  EXPECT_TRUE(fails("{type: tracking_rms, signal: arm/zz, reference: arm/q_ref, fields: [q1]}",
                    "signal: no signal 'arm/zz' in this scenario (signals: arm/q, arm/q_ref)"));
  EXPECT_TRUE(fails("{type: tracking_rms, signal: arm/q, fields: [q1]}", "reference: required key is missing"));

  EXPECT_TRUE(fails("{type: settling_time, signal: arm/q, reference: arm/q_ref}", "field: required key is missing"));
  EXPECT_TRUE(fails(kSettle + ", band: 0}", "band: must be > 0"));
  EXPECT_TRUE(fails(kSettle + ", band: -1e-3}", "band: must be > 0"));
  EXPECT_TRUE(fails("{type: settling_time, signal: arm/q, reference: arm/q_ref, field: dq1}",
                    "field: signal 'arm/q_ref' has no field 'dq1'"));
  EXPECT_TRUE(fails(kSettle + ", to: 5.5}", "to: must be in [from, duration]"));
  EXPECT_TRUE(fails(kSettle + ", fields: [q1]}", "fields: unknown key"));
}

}  // namespace
}  // namespace plexus::scenario
