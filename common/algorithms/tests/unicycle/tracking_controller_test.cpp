#include "plexus/algorithms/unicycle/tracking_controller.hpp"

#include <gtest/gtest.h>

#include "../support/validation_message.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "plexus/algorithms/unicycle/figure_eight_reference.hpp"
#include "plexus/algorithms/unicycle/heading_observer.hpp"
#include "plexus/algorithms/unicycle/position_sensor.hpp"
#include "plexus/algorithms/unicycle/unicycle_plant.hpp"

namespace plexus::algorithms {
namespace {

// ---------------------------------------------------------------- g1, g2 (eq. (14))

TEST(TrackingG, SincFormsMatchDifferenceQuotientsAwayFromTheDiagonal) {
  for (double a : {-3.0, -0.7, 0.0, 1.2, 2.9, 5.0}) {
    for (double b : {-2.5, 0.4, 1.0, 3.1}) {
      if (std::abs(a - b) < 1e-3) continue;
      EXPECT_NEAR(tracking_g1(a, b), (std::cos(a) - std::cos(b)) / (a - b), 1e-12) << a << " " << b;
      EXPECT_NEAR(tracking_g2(a, b), (std::sin(a) - std::sin(b)) / (a - b), 1e-12) << a << " " << b;
    }
  }
}

TEST(TrackingG, SmoothAtTheDiagonal) {
  for (double b : {-2.0, 0.0, 0.5, 3.0}) {
    // Value at a = b is the paper's limit (eq. (14)): -sin b and cos b.
    EXPECT_DOUBLE_EQ(tracking_g1(b, b), -std::sin(b));
    EXPECT_DOUBLE_EQ(tracking_g2(b, b), std::cos(b));
    // Continuous and differentiable through a = b: the one-sided slopes agree with
    // d/da g1 = -cos(b) / 2 and d/da g2 = -sin(b) / 2 at a = b.
    for (double d : {1e-9, 1e-6, 1e-4}) {
      EXPECT_NEAR(tracking_g1(b + d, b), -std::sin(b), 1.0 * d);
      EXPECT_NEAR(tracking_g2(b - d, b), std::cos(b), 1.0 * d);
    }
    const double d = 1e-5;
    EXPECT_NEAR((tracking_g1(b + d, b) - tracking_g1(b - d, b)) / (2 * d), -0.5 * std::cos(b), 1e-6);
    EXPECT_NEAR((tracking_g2(b + d, b) - tracking_g2(b - d, b)) / (2 * d), -0.5 * std::sin(b), 1e-6);
  }
}

// ---------------------------------------------------------------- closed-loop simulations

enum class Feedback { kState, kOutput };

struct RunResult {
  double final_error = 0.0;
  double max_error_after_100 = 0.0;
  double mean_error_after_100 = 0.0;
  double min_speed = 1e9;
  int floored = 0;
};

// Paper 000, section 6: exact plant, 100 Hz, robot at (0, -6) heading theta0, reference from
// (0, -5) (t0 = 3 pi / (2 h2)), z_hat(0) = 0. The controller sees the sensor's measurement.
RunResult run(Feedback fb, TrackingControllerParams params, double L, PositionSensorKind sensor_kind, double T,
              double theta0 = 0.0) {
  const double h = 0.01;
  FigureEightReference ref({});
  TrajectoryTrackingController ctl(params);
  HeadingObserver obs({L});
  PositionSensorParams sp;
  sp.kind = sensor_kind;
  sp.grid_spacing = 0.1;
  PositionSensor sensor(sp);
  Rng rng = sensor.make_rng();
  UnicycleState s{0.0, -6.0, theta0};
  Eigen::Vector2d measured = sensor.measure({s.x, s.y}, rng);
  obs.reset({0.0, 0.0}, measured);
  RunResult res;
  double sum = 0;
  long n = 0;
  const long steps = std::lround(T / h);
  for (long k = 0; k <= steps; ++k) {
    const double t = k * h;
    const ReferenceSample r = ref.sample(t);
    const double Vt = std::hypot(s.x - r.p.x(), s.y - r.p.y());  // eq. (53)
    if (t > 100.0) {
      res.max_error_after_100 = std::max(res.max_error_after_100, Vt);
      sum += Vt;
      ++n;
    }
    res.final_error = Vt;
    if (k == steps) break;
    const TrackingOutput out =
        fb == Feedback::kState ? ctl.state_feedback(r, s) : ctl.output_feedback(r, measured, obs.state().z_hat);
    EXPECT_TRUE(std::isfinite(out.input.v) && std::isfinite(out.input.omega));
    res.min_speed = std::min(res.min_speed, out.input.v);
    res.floored += out.speed_floored;
    s = unicycle_step(s, out.input, h);
    measured = sensor.measure({s.x, s.y}, rng);
    obs.update(h, measured, out.input);
  }
  res.mean_error_after_100 = n ? sum / n : 0.0;
  return res;
}

// Section 6.2: k = [0.11, 0.11, 1], 80 s.
TEST(TrajectoryTracking, StateFeedbackConvergesOnThePaperFigureEight) {
  for (double theta0 : {0.0, std::numbers::pi, -2.0}) {
    const RunResult r = run(Feedback::kState, {0.11, 0.11, 1.0}, 1.0, PositionSensorKind::kExact, 80.0, theta0);
    EXPECT_LT(r.final_error, 1e-3) << "theta0 = " << theta0;  // from V_t(0) = 1 m
    EXPECT_GT(r.min_speed, 0.0);
  }
}

// Section 6.3.1: output feedback with exact positions, k = [0.11, 0.11, 0.01], L = 4, 480 s.
TEST(TrajectoryTracking, OutputFeedbackWithExactPositionsConverges) {
  const RunResult r = run(Feedback::kOutput, {0.11, 0.11, 0.01}, 4.0, PositionSensorKind::kExact, 480.0);
  EXPECT_LT(r.final_error, 1e-3);
  EXPECT_LT(r.max_error_after_100, 0.01);
}

// Section 6.3.2, the headline: RFID tags on a 10 cm grid, k = [0.11, 0.11, 0.1],
// L = 0.6, 480 s. Published: after 100 s max V_t = 0.05 m, mean V_t = 0.01 m.
TEST(TrajectoryTracking, OutputFeedbackWithRfidMeetsThePublishedErrors) {
  const RunResult r = run(Feedback::kOutput, {0.11, 0.11, 0.1}, 0.6, PositionSensorKind::kRfidGrid, 480.0);
  RecordProperty("max_Vt_after_100s", std::to_string(r.max_error_after_100));
  RecordProperty("mean_Vt_after_100s", std::to_string(r.mean_error_after_100));
  EXPECT_LE(r.max_error_after_100, 0.05);
  EXPECT_LE(r.mean_error_after_100, 0.01);
  EXPECT_GT(r.mean_error_after_100, 0.0);  // quantisation keeps it from converging exactly
}

// When condition (15) holds, eq. (21) guarantees v >= (1 - gamma) v_rm along any run.
TEST(TrajectoryTracking, SpeedLowerBoundHoldsWhenGainConditionHolds) {
  FigureEightReference ref({});
  TrackingControllerParams p{0.025, 0.025, 1.0, 0.9, 1e-3};
  ASSERT_FALSE(check_gain_condition(p, ref.min_speed()).has_value());
  for (double theta0 : {0.0, 2.0}) {
    const RunResult r = run(Feedback::kState, p, 1.0, PositionSensorKind::kExact, 60.0, theta0);
    EXPECT_GE(r.min_speed, (1.0 - p.gamma) * ref.min_speed());
  }
}

// ---------------------------------------------------------------- degenerate cases

TEST(TrajectoryTracking, FiniteAndContinuousWhenSpeedVanishes) {
  const TrackingControllerParams p{};
  TrajectoryTrackingController ctl(p);
  ReferenceSample ref;
  ref.dp = {0.05, 0.0};
  ref.ddp = {0.01, -0.02};
  // f1 = k1 atan(zeta1) = x_r' makes S = 0, v = 0: zeta1 = tan(0.05 / k1), zeta2 = 0.
  const double z1 = std::tan(0.05 / p.k1);
  for (double d : {1e-2, 1e-4, 1e-7, 1e-10, 0.0}) {
    ref.p = {-(z1 + d), 0.0};  // robot at the origin
    for (const TrackingOutput& out :
         {ctl.state_feedback(ref, {0.0, 0.0, 0.3}), ctl.output_feedback(ref, {0.0, 0.0}, {0.2, -0.1})}) {
      EXPECT_TRUE(std::isfinite(out.input.v));
      EXPECT_TRUE(std::isfinite(out.input.omega));
      EXPECT_TRUE(std::isfinite(out.theta_star_dot));
      EXPECT_GE(out.input.v, 0.0);
      // Documented bound: |theta*'| <= v (|x_r''| + |f'|) / max(v, v_eps)^2 with
      // |f_i'| <= k_i (v + |x_r'|): the feedforward vanishes with v instead of diverging.
      const double v = out.input.v;
      const double bound =
          v * (ref.ddp.norm() + (p.k1 + p.k2) * (v + ref.dp.norm())) / std::pow(std::max(v, p.min_speed_for_turn), 2);
      EXPECT_LE(std::abs(out.theta_star_dot), bound * (1 + 1e-12) + 1e-300);
      EXPECT_EQ(out.speed_floored, v < p.min_speed_for_turn);
    }
  }
  // Exactly v = 0: theta* = atan2(0, 0) = 0 and omega is the pure heading feedback -k3 zeta3
  // (zeta1, zeta2 terms carry the factor v).
  ReferenceSample exact;
  exact.dp = {p.k1 * std::atan(1.0), 0.0};
  exact.p = {-1.0, 0.0};
  const TrackingOutput out = ctl.state_feedback(exact, {0.0, 0.0, 0.3});
  ASSERT_EQ(out.input.v, 0.0);
  EXPECT_TRUE(out.speed_floored);
  EXPECT_EQ(out.theta_star, 0.0);
  EXPECT_NEAR(out.input.omega, -p.k3 * 0.3, 1e-15);
}

TEST(TrajectoryTracking, FiniteWhenObserverEstimateIsZero) {
  TrajectoryTrackingController ctl({});
  FigureEightReference ref({});
  const TrackingOutput out = ctl.output_feedback(ref.sample(3.0), {0.5, -6.0}, {0.0, 0.0});
  EXPECT_TRUE(std::isfinite(out.input.v) && std::isfinite(out.input.omega));
}

// ---------------------------------------------------------------- parameters

TEST(TrajectoryTracking, ValidationNamesTheParameterAndValue) {
  auto message = [](const TrackingControllerParams& p) {
    return testing::invalid_argument_message<TrajectoryTrackingController>(p);
  };
  TrackingControllerParams p;
  p.k1 = 0.0;
  EXPECT_NE(message(p).find("k1 must be finite and > 0 (got 0)"), std::string::npos) << message(p);
  p = {};
  p.k2 = -0.5;
  EXPECT_NE(message(p).find("k2"), std::string::npos);
  EXPECT_NE(message(p).find("-0.5"), std::string::npos);
  p = {};
  p.k3 = std::nan("");
  EXPECT_NE(message(p).find("k3"), std::string::npos);
  for (double gamma : {0.0, 1.0, 1.5, -0.2}) {
    p = {};
    p.gamma = gamma;
    EXPECT_NE(message(p).find("gamma must be in (0, 1)"), std::string::npos) << gamma;
  }
  p = {};
  p.min_speed_for_turn = 0.0;
  EXPECT_NE(message(p).find("min_speed_for_turn"), std::string::npos);
  EXPECT_EQ(message({}), "");
}

TEST(TrajectoryTracking, GainConditionWarnsForThePaperGains) {
  FigureEightReference ref({});
  TrackingControllerParams p{0.11, 0.11, 1.0, 0.999, 1e-3};
  const auto warning = check_gain_condition(p, ref.min_speed());
  ASSERT_TRUE(warning.has_value());
  EXPECT_NE(warning->find("(15)"), std::string::npos);
  EXPECT_NE(warning->find("k1 = 0.11"), std::string::npos);
  EXPECT_NE(warning->find("v_rm = 0.06959"), std::string::npos);
  // The ratio is about 12 (paper 000, docs/papers.md): lhs 0.0242 vs (4 / pi^2) v_rm^2 = 0.00196.
  const double ratio =
      0.0242 / (p.gamma * p.gamma * 4 / (std::numbers::pi * std::numbers::pi) * std::pow(ref.min_speed(), 2));
  EXPECT_NEAR(ratio, 12.3, 0.1);
  EXPECT_NE(warning->find("12.3"), std::string::npos) << *warning;
  // Gains that satisfy (15) give no warning; invalid inputs throw.
  EXPECT_FALSE(check_gain_condition({0.025, 0.025, 1.0, 0.9, 1e-3}, ref.min_speed()).has_value());
  EXPECT_THROW(check_gain_condition(p, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace plexus::algorithms
