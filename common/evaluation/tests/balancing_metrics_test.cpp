// Balancing metrics (balancing_metrics.cpp): angle_error_deg, angle_error_std_difference_deg
// and angle_deg on synthetic runs whose statistics are known in closed form.
//
// Angles are recorded in rad and reported in degrees. The metrics do not wrap angles
// across +-pi (a pitch stays near 0), so no case here crosses it.
//
// Sums used below: over whole periods with N > 2 samples per period, sum sin = sum cos = 0
// and sum sin^2 = sum cos^2 = (samples) / 2. For e = c + A sin over whole periods:
//   mean c, population std A / sqrt 2, rms sqrt(c^2 + A^2 / 2), max c + A, min c - A.
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
constexpr double kRad = kPi / 180.0;

/// Error of r/attitude's theta, deg: -0.5 + 2 sin(2 pi t), plus 10 for t < 1 (start-up).
double ukf_error_deg(int64_t k) {
  const double t = static_cast<double>(k) * kStep;
  return -0.5 + 2.0 * std::sin(2 * kPi * t) + (k < 100 ? 10.0 : 0.0);
}
/// Error of r/ekf's theta, deg: 0.25 + 3 sin(4 pi t) (period 0.5 s).
double ekf_error_deg(int64_t k) {
  const double t = static_cast<double>(k) * kStep;
  return 0.25 + 3.0 * std::sin(4 * kPi * t);
}

/// Truth (x, theta, theta_dot), recorded every other step (held at the odd steps), with
/// theta = -1 + 3 cos(2 pi t) deg; two estimates recorded every step: r/attitude (theta,
/// bias) = (held truth theta + ukf error, held truth theta_dot + 0.25 deg), r/ekf (theta) =
/// held truth theta + ekf error. All stored in rad.
RunLog balancing_run() {
  RunLog log;
  log.base_step = kStep;
  log.steps = kSteps;
  SignalTrace truth{{"r/truth/state", {"x", "theta", "theta_dot"}, 2, "plant", true, ""}, {}, {}};
  SignalTrace ukf{{"r/attitude", {"theta", "bias"}, 1, "ukf", false, ""}, {}, {}};
  SignalTrace ekf{{"r/ekf", {"theta"}, 1, "ekf", false, ""}, {}, {}};
  for (int64_t k = 0; k <= kSteps; ++k) {
    const double th = static_cast<double>(k - k % 2) * kStep;  // time of the held truth sample
    const double theta = kRad * (-1.0 + 3.0 * std::cos(2 * kPi * th));
    const double theta_dot = kRad * (-6.0 * kPi * std::sin(2 * kPi * th));
    if (k % 2 == 0) {
      truth.steps.push_back(k);
      truth.values.insert(truth.values.end(), {0.2 * th, theta, theta_dot});
    }
    ukf.steps.push_back(k);
    ukf.values.insert(ukf.values.end(), {theta + kRad * ukf_error_deg(k), theta_dot + kRad * 0.25});
    ekf.steps.push_back(k);
    ekf.values.push_back(theta + kRad * ekf_error_deg(k));
  }
  log.signals = {truth, ukf, ekf};
  return log;
}

MetricResult compute(const RunLog& log, const std::string& yaml) {
  return testing::metric_on_log(log, yaml, kStep, kDuration);
}

const std::string kErr = "{type: angle_error_deg, signal: r/attitude, reference: r/truth/state";
const std::string kWhole = ", from: 1, to: 3.99";  // 300 samples: 3 whole periods, no start-up

double stat(const RunLog& log, const std::string& s, const std::string& window = kWhole) {
  return compute(log, kErr + ", stat: " + s + window + "}").value;
}

TEST(BalancingMetrics, AngleErrorStatisticsOfAnOffsetSineInDegrees) {
  const RunLog log = balancing_run();
  // e = -0.5 + 2 sin(2 pi t) deg over 3 whole periods.
  EXPECT_NEAR(stat(log, "mean"), -0.5, 1e-9);                 // signed: c
  EXPECT_NEAR(stat(log, "abs_mean"), 0.5, 1e-9);              // |c|
  EXPECT_NEAR(stat(log, "std"), std::sqrt(2.0), 1e-9);        // A / sqrt 2, population
  EXPECT_NEAR(stat(log, "rms"), 1.5, 1e-9);                   // sqrt(0.25 + 4 / 2)
  EXPECT_NEAR(stat(log, "max"), 1.5, 1e-9);                   // c + A at t = 1.25
  EXPECT_NEAR(stat(log, "min"), -2.5, 1e-9);                  // c - A at t = 1.75
  EXPECT_NEAR(stat(log, "max_abs"), 2.5, 1e-9);               // |c - A|, not c + A
  EXPECT_NEAR(stat(log, "final", ", to: 3.75"), -2.5, 1e-9);  // the sample at the window's end
  EXPECT_NEAR(stat(log, "final"), -0.5 + 2.0 * std::sin(2 * kPi * 3.99), 1e-9);
  const MetricResult r = compute(log, kErr + ", stat: mean" + kWhole + "}");
  ASSERT_EQ(r.series.size(), 300u);
  EXPECT_NEAR(r.series[25].first, 1.25, 1e-12);
  EXPECT_NEAR(r.series[25].second, 1.5, 1e-9);  // the series is the signed error, deg
}

TEST(BalancingMetrics, AngleErrorWindowIncludesBothEnds) {
  const RunLog log = balancing_run();
  // Whole run, 401 samples: sum e = 100 * 10 (start-up) + 401 * (-0.5) + 2 * 0 (4 periods
  // plus sin 8 pi = 0).
  EXPECT_NEAR(stat(log, "mean", ""), (1000.0 - 200.5) / 401.0, 1e-9);
  EXPECT_NEAR(stat(log, "max", ""), 11.5, 1e-9);  // 10 - 0.5 + 2 at t = 0.25
  // [0, 0.99]: the start-up period alone: mean 9.5, std still A / sqrt 2.
  EXPECT_NEAR(stat(log, "mean", ", to: 0.99"), 9.5, 1e-9);
  EXPECT_NEAR(stat(log, "std", ", to: 0.99"), std::sqrt(2.0), 1e-9);
  // [1.25, 1.25]: one sample, e = 1.5; its std is 0.
  EXPECT_NEAR(stat(log, "mean", ", from: 1.25, to: 1.25"), 1.5, 1e-9);
  EXPECT_NEAR(stat(log, "std", ", from: 1.25, to: 1.25"), 0.0, 1e-9);
}

TEST(BalancingMetrics, AngleErrorFieldAndReferenceFieldAreMatchedByName) {
  const RunLog log = balancing_run();
  // bias - theta_dot = 0.25 deg at every sample (theta_dot held like theta).
  const std::string m = kErr + ", field: bias, reference_field: theta_dot";
  EXPECT_NEAR(compute(log, m + ", stat: mean}").value, 0.25, 1e-9);
  EXPECT_NEAR(compute(log, m + ", stat: std}").value, 0.0, 1e-9);
  // field / reference_field default to theta.
  EXPECT_NEAR(compute(log, kErr + ", field: theta, reference_field: theta, stat: rms" + kWhole + "}").value, 1.5, 1e-9);
}

TEST(BalancingMetrics, StdDifferenceIsTheDifferenceOfTheTwoErrorStds) {
  const RunLog log = balancing_run();
  // std(ukf error) - std(ekf error) = 2 / sqrt 2 - 3 / sqrt 2 = -1 / sqrt 2 deg (both over
  // whole periods: 3 of 1 s and 6 of 0.5 s); the offsets -0.5 and 0.25 drop out.
  const std::string m = "{type: angle_error_std_difference_deg, reference: r/truth/state";
  EXPECT_NEAR(compute(log, m + ", signal: r/attitude, other: r/ekf" + kWhole + "}").value, -1.0 / std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(compute(log, m + ", signal: r/ekf, other: r/attitude" + kWhole + "}").value, 1.0 / std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(compute(log, m + ", signal: r/ekf, other: r/ekf}").value, 0.0, 1e-12);
}

TEST(BalancingMetrics, AngleDegStatisticsOfOneField) {
  const RunLog log = balancing_run();
  // Truth theta = -1 + 3 cos(2 pi t) deg at the even steps of [1, 3.99]: 150 samples, 3
  // whole periods of 50: mean -1, std 3 / sqrt 2, rms sqrt(1 + 9 / 2), max 2 (t = 1),
  // min -4 (t = 1.5), max_abs 4.
  const std::string m = "{type: angle_deg, signal: r/truth/state, field: theta" + kWhole + ", stat: ";
  EXPECT_NEAR(compute(log, m + "mean}").value, -1.0, 1e-9);
  EXPECT_NEAR(compute(log, m + "abs_mean}").value, 1.0, 1e-9);
  EXPECT_NEAR(compute(log, m + "std}").value, 3.0 / std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(compute(log, m + "rms}").value, std::sqrt(5.5), 1e-9);
  EXPECT_NEAR(compute(log, m + "max}").value, 2.0, 1e-9);
  EXPECT_NEAR(compute(log, m + "min}").value, -4.0, 1e-9);
  EXPECT_NEAR(compute(log, m + "max_abs}").value, 4.0, 1e-9);
  EXPECT_EQ(compute(log, m + "mean}").series.size(), 150u);
  EXPECT_NEAR(compute(log, "{type: angle_deg, signal: r/truth/state, field: theta, stat: final, to: 1.5}").value, -4.0,
              1e-9);
}

TEST(BalancingMetrics, ConfigurationErrorsNameTheKey) {
  const RunLog log = balancing_run();
  auto fails = [&](const std::string& yaml, const std::string& expected) {
    return testing::metric_fails(log, yaml, kStep, kDuration, expected);
  };
  EXPECT_TRUE(fails(kErr + "}", "stat: required key is missing"));
  EXPECT_TRUE(fails(kErr + ", stat: median}",
                    "stat: expected mean, abs_mean, std, max, min, max_abs, rms or final, got 'median'"));
  EXPECT_TRUE(fails(kErr + ", stat: mean, field: phi}", "field: r/attitude has no field 'phi'"));
  EXPECT_TRUE(
      fails(kErr + ", stat: mean, reference_field: bias}", "reference_field: r/truth/state has no field 'bias'"));
  EXPECT_TRUE(fails(kErr + ", stat: mean, to: 5}", "to: must be in [from, duration]"));
  EXPECT_TRUE(fails(kErr + ", stat: mean, from: -0.5}", "from: must be in [0, duration]"));
  EXPECT_TRUE(fails(kErr + ", stat: mean, band: 1}", "band: unknown key"));
  const std::string diff =
      "{type: angle_error_std_difference_deg, signal: r/attitude, other: r/ekf, reference: r/truth/state";
  EXPECT_TRUE(fails(diff + ", field: bias}", "field: r/ekf has no field 'bias'"));
  EXPECT_TRUE(fails(diff + ", stat: std}", "stat: unknown key"));
  EXPECT_TRUE(fails("{type: angle_error_std_difference_deg, signal: r/attitude, reference: r/truth/state}",
                    "other: required key is missing"));
  EXPECT_TRUE(fails("{type: angle_deg, signal: r/truth/state, stat: mean}", "field: required key is missing"));
  EXPECT_TRUE(fails("{type: angle_deg, signal: r/truth/state, field: q, stat: mean}",
                    "field: signal 'r/truth/state' has no field 'q'"));
  EXPECT_TRUE(fails("{type: angle_deg, signal: r/truth/state, field: theta, stat: avg}", "stat: expected mean"));
}

}  // namespace
}  // namespace plexus::scenario
