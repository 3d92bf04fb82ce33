#include "plexus/algorithms/skid_steer/skid_steer_plant.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "../support/validation_message.hpp"
#include "plexus/algorithms/skid_steer/driving_pattern.hpp"
#include "plexus/algorithms/skid_steer/icr_odometry.hpp"
#include "plexus/algorithms/skid_steer/terrain_change_detector.hpp"
#include "plexus/algorithms/skid_steer/terrain_features.hpp"

namespace plexus::algorithms {
namespace {

using testing::invalid_argument_message;

TEST(IcrKinematics, NoSlipModelIsTheDifferentialDrive) {
  const IcrParams ns = no_slip_icr(0.4);
  const BodyVelocity b = icr_body_velocity(ns, {0.3, 0.5});
  EXPECT_DOUBLE_EQ(b.v_x, 0.4);
  EXPECT_DOUBLE_EQ(b.v_y, 0.0);
  EXPECT_DOUBLE_EQ(b.omega, 0.2 / 0.4);
}

TEST(IcrKinematics, BodyVelocityMatchesTheTrackIcrDefinition) {
  // A track at lateral y_l moves at v_l in the body frame: v_x - omega y_l = v_l.
  const IcrParams icr{0.3, -0.5, -0.1};
  const TrackSpeeds u{0.2, 0.7};
  const BodyVelocity b = icr_body_velocity(icr, u);
  EXPECT_NEAR(b.v_x - b.omega * icr.y_l, u.v_l, 1e-15);
  EXPECT_NEAR(b.v_x - b.omega * icr.y_r, u.v_r, 1e-15);
  EXPECT_NEAR(b.v_y + b.omega * icr.x_G, 0.0 + 2 * b.omega * icr.x_G, 1e-15);  // v_y = omega x_G
}

TEST(IcrKinematics, ExactStepMatchesFineEulerIntegration) {
  const BodyVelocity b{0.5, -0.1, 0.8};
  const Pose2 p0{1.0, -2.0, 0.4};
  const Pose2 exact = icr_pose_step(p0, b, 0.5);
  Pose2 e = p0;
  for (int i = 0; i < 100000; ++i) e = icr_euler_step(e, b, 0.5 / 100000);
  EXPECT_NEAR(exact.x, e.x, 1e-5);
  EXPECT_NEAR(exact.y, e.y, 1e-5);
  EXPECT_NEAR(exact.theta, e.theta, 1e-12);
}

TEST(SkidSteerPlant, CircleRadiusFollowsTheTerrainIcrs) {
  SkidSteerPlantParams p;
  SkidSteerPlant plant(p);
  Rng rng(1);
  const TrackSpeeds u{0.3, 0.5};
  const BodyVelocity b = icr_body_velocity(p.terrains[0].icr, u);
  double t = 0;
  double max_dev = 0;
  // Centre of the circle: the instantaneous centre of rotation of the body.
  const double vnorm = std::hypot(b.v_x, b.v_y);
  const double radius = vnorm / b.omega;
  const double cx = -b.v_y / b.omega, cy = b.v_x / b.omega;  // from the start pose (0, 0, 0)
  for (int i = 0; i < 3000; ++i, t += p.step) {
    const SkidSteerState& s = plant.step(t, u, rng);
    max_dev = std::max(max_dev, std::abs(std::hypot(s.pose.x - cx, s.pose.y - cy) - radius));
  }
  EXPECT_LT(max_dev, 1e-9);
  EXPECT_NEAR(plant.state().pose.theta, b.omega * 30.0, 1e-9);
}

TEST(SkidSteerPlant, ScheduleSwitchesIcrsAndTerrain) {
  SkidSteerPlantParams p;
  p.schedule = {{0.0, 0}, {1.0, 1}, {2.0, 2}};
  SkidSteerPlant plant(p);
  Rng rng(1);
  std::vector<int> seen;
  for (int i = 0; i < 300; ++i) {
    const SkidSteerState& s = plant.step(i * p.step, {0.5, 0.5}, rng);
    if (seen.empty() || seen.back() != s.terrain) seen.push_back(s.terrain);
    EXPECT_EQ(s.icr.y_l, p.terrains[static_cast<std::size_t>(s.terrain)].icr.y_l);
  }
  EXPECT_EQ(seen, (std::vector<int>{0, 1, 2}));
}

TEST(SkidSteerPlant, SeedFixesTheVibration) {
  SkidSteerPlant a({}), b({});
  Rng ra(5), rb(5);
  for (int i = 0; i < 200; ++i) EXPECT_EQ(a.step(i * 0.01, {0.5, 0.5}, ra).a_z, b.step(i * 0.01, {0.5, 0.5}, rb).a_z);
}

TEST(SkidSteerPlant, RejectsBadParameters) {
  SkidSteerPlantParams p;
  p.terrains[1].icr = {0.1, 0.2, 0.0};
  EXPECT_EQ(invalid_argument_message<SkidSteerPlant>(p),
            "skid_steer_plant: terrains[1] (tile): y_l - y_r must be > 0 (y_l left of y_r) (got -0.1)");
  p = {};
  p.terrains.clear();
  EXPECT_EQ(invalid_argument_message<SkidSteerPlant>(p), "skid_steer_plant: terrains must not be empty");
  p = {};
  p.schedule = {{0.0, 0}, {5.0, 3}};
  EXPECT_EQ(invalid_argument_message<SkidSteerPlant>(p),
            "terrain_schedule: segments[1].terrain must be a terrain id in [0, 3) (got 3)");
  p.schedule = {{1.0, 0}};
  EXPECT_EQ(invalid_argument_message<SkidSteerPlant>(p),
            "terrain_schedule: segments[0].start_s must be 0 (the schedule starts at 0 s) (got 1)");
  p.schedule = {{0.0, 0}, {5.0, 1}, {5.0, 2}};
  EXPECT_EQ(invalid_argument_message<SkidSteerPlant>(p),
            "terrain_schedule: segments[2].start_s must be > the previous segment's start (got 5)");
  p = {};
  p.schedule.clear();
  EXPECT_EQ(invalid_argument_message<SkidSteerPlant>(p), "terrain_schedule: must have at least one segment");
  p = {};
  p.step = 0;
  EXPECT_EQ(invalid_argument_message<SkidSteerPlant>(p), "skid_steer_plant: step must be finite and > 0 (got 0)");
}

// ---------------------------------------------------------------------------- vibration

double rms_around_mean(const std::vector<double>& x) {
  double m = 0, v = 0;
  for (double a : x) m += a / static_cast<double>(x.size());
  for (double a : x) v += (a - m) * (a - m) / static_cast<double>(x.size());
  return std::sqrt(v);
}

TEST(TerrainVibration, StationaryRmsMatchesTheSpectrum) {
  TerrainVibrationParams p;
  p.spectra = {{{{12.0, 0.1, 0.7}}, 0.0}, {{{30.0, 0.3, 0.2}, {5.0, 0.2, 0.2}}, 0.1}};
  TerrainVibration v(p);
  Rng rng(9);
  for (int terrain : {0, 1}) {
    std::vector<double> x;
    for (int i = 0; i < 200000; ++i) x.push_back(v.sample(terrain, 0.5, rng));
    const double expected = terrain == 0 ? 0.7 : std::sqrt(0.2 * 0.2 + 0.2 * 0.2 + 0.1 * 0.1);
    EXPECT_NEAR(rms_around_mean(x), expected, 0.03 * expected) << terrain;
  }
}

TEST(TerrainVibration, GainScalesWithSpeedAndIsZeroAtRest) {
  TerrainVibrationParams p;
  p.spectra = {{{{12.0, 0.1, 0.7}}, 0.1}};
  p.speed_exponent = 1.5;
  TerrainVibration v(p);
  EXPECT_DOUBLE_EQ(v.gain(0.5), 1.0);
  EXPECT_NEAR(v.gain(1.0), std::pow(2.0, 1.5), 1e-12);
  EXPECT_EQ(v.gain(0.0), 0.0);
  Rng rng(1);
  EXPECT_EQ(v.sample(0, 0.0, rng), p.gravity);
}

TEST(TerrainVibration, PsdPeaksAtTheResonance) {
  TerrainVibrationParams p;
  p.spectra = {{{{17.0, 0.03, 1.0}}, 0.01}};
  TerrainVibration v(p);
  PsdFeatureExtractor e({});
  std::vector<double> f(e.size()), mean(e.size(), 0.0), w(100);
  Rng rng(4);
  for (int win = 0; win < 200; ++win) {
    for (double& s : w) s = v.sample(0, 0.5, rng);
    e.compute(w, f);
    for (std::size_t i = 0; i < f.size(); ++i) mean[i] += f[i];
  }
  EXPECT_EQ(e.frequency(static_cast<std::size_t>(std::max_element(mean.begin(), mean.end()) - mean.begin())), 17.0);
}

TEST(TerrainVibration, RejectsBadParameters) {
  TerrainVibrationParams p;
  EXPECT_EQ(invalid_argument_message<TerrainVibration>(p), "terrain_vibration: spectra must not be empty");
  p.spectra = {{{{60.0, 0.1, 1.0}}, 0.1}};
  EXPECT_EQ(invalid_argument_message<TerrainVibration>(p),
            "terrain_vibration: spectra[0].resonances[0].frequency_hz must be in (0, 50) (got 60)");
  p.spectra = {{{{10.0, 1.0, 1.0}}, 0.1}};
  EXPECT_EQ(invalid_argument_message<TerrainVibration>(p),
            "terrain_vibration: spectra[0].resonances[0].damping_ratio must be in (0, 1) (got 1)");
  p.spectra = {{{{10.0, 0.5, -1.0}}, 0.1}};
  EXPECT_EQ(invalid_argument_message<TerrainVibration>(p),
            "terrain_vibration: spectra[0].resonances[0].rms must be finite and >= 0 (got -1)");
  p.spectra = {{{}, -0.1}};
  EXPECT_EQ(invalid_argument_message<TerrainVibration>(p),
            "terrain_vibration: spectra[0].floor_rms must be finite and >= 0 (got -0.1)");
  p.spectra = {{{}, 0.1}};
  p.speed_exponent = -1;
  EXPECT_EQ(invalid_argument_message<TerrainVibration>(p),
            "terrain_vibration: speed_exponent must be finite and >= 0 (got -1)");
}

// ---------------------------------------------------------------------------- patterns

TEST(DrivingPattern, PatternsGiveTheirNominalMotion) {
  DrivingPatternParams p;
  p.kind = DrivingPatternKind::kCircle;
  p.speed = 0.5;
  p.turn_rate = 0.4;
  TrackSpeeds u = DrivingPattern(p).at(3.0);
  EXPECT_DOUBLE_EQ(0.5 * (u.v_l + u.v_r), 0.5);
  EXPECT_DOUBLE_EQ((u.v_r - u.v_l) / p.track_width, 0.4);
  p.kind = DrivingPatternKind::kStraight;
  u = DrivingPattern(p).at(3.0);
  EXPECT_EQ(u.v_l, u.v_r);
  p.kind = DrivingPatternKind::kFigureEight;
  p.period = 20;
  const DrivingPattern eight(p);
  EXPECT_GT(eight.at(5.0).v_r, eight.at(5.0).v_l);    // left turn in the first half
  EXPECT_LT(eight.at(15.0).v_r, eight.at(15.0).v_l);  // right turn in the second
  // A figure-eight closes: the no-slip heading returns to 0 after one period.
  double heading = 0;
  for (int i = 0; i < 2000; ++i) {
    const TrackSpeeds s = eight.at(i * 0.01 + 0.005);
    heading += (s.v_r - s.v_l) / p.track_width * 0.01;
  }
  EXPECT_NEAR(heading, 0.0, 1e-9);
}

TEST(DrivingPattern, SegmentsRepeatOrHold) {
  DrivingPatternParams p;
  p.kind = DrivingPatternKind::kSegments;
  p.segments = {{1.0, 0.1, 0.2}, {2.0, 0.3, -0.3}};
  EXPECT_EQ(DrivingPattern(p).at(0.5).v_r, 0.2);
  EXPECT_EQ(DrivingPattern(p).at(2.5).v_l, 0.3);
  EXPECT_EQ(DrivingPattern(p).at(3.5).v_l, 0.1);  // repeated
  p.repeat = false;
  EXPECT_EQ(DrivingPattern(p).at(10.0).v_l, 0.3);  // last held
}

TEST(DrivingPattern, RejectsBadParameters) {
  DrivingPatternParams p;
  p.kind = DrivingPatternKind::kSegments;
  EXPECT_EQ(invalid_argument_message<DrivingPattern>(p), "driving_pattern: segments must not be empty");
  p.segments = {{0.0, 0.1, 0.1}};
  EXPECT_EQ(invalid_argument_message<DrivingPattern>(p),
            "driving_pattern: segments[0].duration_s must be finite and > 0 (got 0)");
  p = {};
  p.period = -1;
  EXPECT_EQ(invalid_argument_message<DrivingPattern>(p), "driving_pattern: period must be finite and > 0 (got -1)");
  p = {};
  p.track_width = 0;
  EXPECT_EQ(invalid_argument_message<DrivingPattern>(p), "driving_pattern: track_width must be finite and > 0 (got 0)");
  EXPECT_THROW(driving_pattern_kind_from_string("spiral"), std::invalid_argument);
}

// ---------------------------------------------------------------------------- odometry, detector

TEST(IcrOdometry, WithTheTrueIcrsItReproducesThePlant) {
  SkidSteerPlantParams p;
  p.schedule = {{0.0, 0}, {10.0, 1}};
  SkidSteerPlant plant(p);
  const DrivingPattern drive({});
  IcrOdometry odo, ns;
  odo.reset(plant.state().pose);
  ns.reset(plant.state().pose);
  Rng rng(1);
  for (int i = 0; i < 2000; ++i) {
    const double t = i * p.step;
    const TrackSpeeds u = drive.at(t);
    plant.step(t, u, rng);
    odo.step(u, plant.state().icr, p.step);
    ns.step(u, no_slip_icr(0.4), p.step);
  }
  EXPECT_NEAR(odo.pose().x, plant.state().pose.x, 1e-9);
  EXPECT_NEAR(odo.pose().y, plant.state().pose.y, 1e-9);
  EXPECT_GT(std::hypot(ns.pose().x - plant.state().pose.x, ns.pose().y - plant.state().pose.y), 0.5);
  EXPECT_FALSE(odo.step({0.1, 0.1}, {0.0, 0.0, 0.0}, 0.01));
}

TEST(TerrainChangeDetector, NeedsConsecutiveWindowsOfTheNewClass) {
  TerrainChangeDetector d(2);
  EXPECT_FALSE(d.observe(0));  // first decision: no change
  EXPECT_EQ(d.current(), 0);
  EXPECT_FALSE(d.observe(1));
  EXPECT_FALSE(d.observe(0));  // interrupted
  EXPECT_FALSE(d.observe(1));
  EXPECT_FALSE(d.observe(2));  // another class restarts the count
  EXPECT_TRUE(d.observe(2));
  EXPECT_EQ(d.current(), 2);
  EXPECT_FALSE(d.observe(2));
  EXPECT_EQ(d.changes(), 1);
  TerrainChangeDetector one(1);
  one.observe(0);
  EXPECT_TRUE(one.observe(1));
  EXPECT_EQ(invalid_argument_message<TerrainChangeDetector>(0),
            "terrain_change_detector: consecutive must be >= 1 (got 0)");
}

}  // namespace
}  // namespace plexus::algorithms
