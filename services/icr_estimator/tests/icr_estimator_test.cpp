// icr_estimator: icr_ekf (paper 001 section 3.1) and icr_odometry. TrackSpeeds + Pose2D
// (+ TerrainClass) in -> edge check -> EKF predict / update / adaptive reset -> IcrEstimate
// out; TrackSpeeds + SkidSteerTruth (+ IcrEstimate) in -> dead reckoning -> Pose2D out.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>

#include "plexus/algorithms/skid_steer/icr_ekf.hpp"
#include "plexus/algorithms/skid_steer/icr_odometry.hpp"
#include "plexus/algorithms/skid_steer/terrain_icr_library.hpp"
#include "service_harness.hpp"

namespace plexus::services_test {
namespace {

// The component types of services/icr_estimator/ whose data path this file tests.
const Covers kCovers{"icr_ekf", "icr_odometry", "icr_library_recorder"};

namespace alg = plexus::algorithms;

msg::TrackSpeeds wheels(const ServiceUnderTest& s, int64_t k, double v_l, double v_r) {
  auto m = s.stamped<msg::TrackSpeeds>(k);
  m.left(v_l), m.right(v_r);
  return m;
}

msg::Pose2D gps(const ServiceUnderTest& s, int64_t k, double x, double y, double theta) {
  auto m = s.stamped<msg::Pose2D>(k);
  m.x(x), m.y(y), m.theta(theta);
  return m;
}

msg::TerrainClass terrain(const ServiceUnderTest& s, int64_t k, int id, uint32_t windows) {
  auto m = s.stamped<msg::TerrainClass>(k);
  m.terrain_id(id), m.windows(windows), m.confidence(0.8), m.votes(4);
  return m;
}

// --- icr_ekf ----------------------------------------------------------------------------

const std::string kEkf = R"(name: icr_part
step: 0.01
services:
  ekf: {type: icr_ekf, robot: r2}
)";

TEST(IcrEkf, StartsAtTheFirstGpsSampleThenPredictsByHand) {
  ServiceUnderTest s(kEkf);
  EXPECT_EQ(s.message_type("r2/wheels"), "TrackSpeeds");
  EXPECT_EQ(s.message_type("r2/gps"), "Pose2D");
  EXPECT_EQ(s.message_type("r2/icr"), "IcrEstimate");
  s.deliver("r2/wheels", wheels(s, 0, 0.4, 0.6));
  s.step(0);  // no GPS yet: initial ICRs (1, -1, 1), sd = sqrt(P_B) = 0.5 m
  auto m = s.published<msg::IcrEstimate>("r2/icr");
  EXPECT_EQ(m.y_l(), 1.0);
  EXPECT_EQ(m.y_r(), -1.0);
  EXPECT_EQ(m.x_g(), 1.0);
  EXPECT_DOUBLE_EQ(m.stddev()[3], 0.5);
  EXPECT_EQ(m.x(), 0.0);
  ASSERT_EQ(s.deliver("r2/gps", gps(s, 1, 2.0, -1.0, 0.0)), Rejection::none);
  s.step(1);  // starts at the GPS pose
  m = s.published<msg::IcrEstimate>("r2/icr");
  EXPECT_EQ(m.x(), 2.0);
  EXPECT_EQ(m.y(), -1.0);
  s.step(2);  // predicts with (0.4, 0.6): v_x = 0.5, v_y = 0.1, omega = 0.1 (eqs. (3)-(5), (7))
  m = s.published<msg::IcrEstimate>("r2/icr");
  EXPECT_DOUBLE_EQ(m.x(), 2.005);
  EXPECT_DOUBLE_EQ(m.y(), -0.999);
  EXPECT_DOUBLE_EQ(m.theta(), 0.001);
  EXPECT_EQ(m.resets(), 0u);
  EXPECT_EQ(s.check_output("r2/icr"), Rejection::none);
}

void feed_ekf(ServiceUnderTest& s, int64_t k) {
  const double t = 0.01 * static_cast<double>(k);
  ASSERT_EQ(s.deliver("r2/wheels", wheels(s, k, 0.3, 0.5 + 0.2 * std::sin(t))), Rejection::none);
  if (k % 5 == 0) {
    ASSERT_EQ(s.deliver("r2/gps", gps(s, k, 0.4 * t, 0.1 * t * t, 0.2 * t)), Rejection::none);  // 20 Hz
  }
}

TEST(IcrEkf, PredictsAndUpdatesLikeTheAlgorithm) {
  ServiceUnderTest s(kEkf);
  alg::IcrEkf ref{alg::IcrEkfParams{}};
  for (int64_t k = 0; k < 16; ++k) {
    feed_ekf(s, k);
    s.step(k);
    const double t = 0.01 * static_cast<double>(k);
    if (k > 0) ref.predict({0.3, 0.5 + 0.2 * std::sin(t)}, 0.01);
    if (k == 0)
      ref.reset({0, 0, 0});
    else if (k % 5 == 0)
      ref.update({0.4 * t, 0.1 * t * t, 0.2 * t});
    for (int i = 0; i < 6; ++i)
      ASSERT_NEAR(s.sample("r2/icr").values[static_cast<std::size_t>(i)], ref.state()(i), 1e-12) << k;
    ASSERT_NEAR(s.out("r2/icr", "sd_x_G"), std::sqrt(ref.covariance()(5, 5)), 1e-12) << k;
  }
  EXPECT_LT(s.out("r2/icr", "sd_y_l"), 0.5);  // the GPS updates tightened the ICRs
}

TEST(IcrEkf, AGpsSampleReadAfterItsStepIsDropped) {
  // Realtime: the GPS sample of step 10 arrives after step 10 ran (step 10 read the one of
  // step 5). Read at step 11, it would update the pose of step 11 with the position of
  // step 10: dropped and counted. Everything else as the algorithm does it.
  ServiceUnderTest s(kEkf);
  alg::IcrEkf ref{alg::IcrEkfParams{}};
  for (int64_t k = 0; k < 16; ++k) {
    const double t = 0.01 * static_cast<double>(k);
    if (k == 10) {
      ASSERT_EQ(s.deliver("r2/wheels", wheels(s, k, 0.3, 0.5 + 0.2 * std::sin(t))), Rejection::none);
      s.step(k);
      ASSERT_EQ(s.deliver("r2/gps", gps(s, k, 0.4 * t, 0.1 * t * t, 0.2 * t)), Rejection::none);  // too late
    } else {
      feed_ekf(s, k);
      s.step(k);
    }
    if (k > 0) ref.predict({0.3, 0.5 + 0.2 * std::sin(t)}, 0.01);
    if (k == 0)
      ref.reset({0, 0, 0});
    else if (k % 5 == 0 && k != 10)
      ref.update({0.4 * t, 0.1 * t * t, 0.2 * t});
    for (int i = 0; i < 6; ++i)
      ASSERT_NEAR(s.sample("r2/icr").values[static_cast<std::size_t>(i)], ref.state()(i), 1e-12) << k;
  }
  EXPECT_EQ(s.scenario().components[0].component->dropped_late_samples(), 1u);
}

TEST(IcrEkf, AdaptiveResetOnAConfirmedTerrainChange) {
  // Paper 001 eq. (22): two consecutive windows on a new class reset P to P_B (sd 0.5 m).
  ServiceUnderTest s(kEkf, {}, {"services.ekf.adaptive_reset=true"});
  EXPECT_EQ(s.message_type("r2/terrain"), "TerrainClass");
  int64_t k = 0;
  auto run = [&](int steps) {
    for (int i = 0; i < steps; ++i, ++k) {
      feed_ekf(s, k);
      s.step(k);
    }
  };
  s.deliver("r2/terrain", terrain(s, 0, 0, 1));
  run(10);
  EXPECT_LT(s.out("r2/icr", "sd_y_l"), 0.5);
  s.deliver("r2/terrain", terrain(s, k, 1, 2));  // a candidate
  run(3);
  EXPECT_EQ(s.out("r2/icr", "resets"), 0.0);
  s.deliver("r2/terrain", terrain(s, k, 1, 2));  // the same window again: no new decision
  run(1);
  EXPECT_EQ(s.out("r2/icr", "resets"), 0.0);
  s.deliver("r2/terrain", terrain(s, k, 1, 3));  // confirmed
  feed_ekf(s, k);
  s.step(k);
  const auto m = s.published<msg::IcrEstimate>("r2/icr");
  EXPECT_EQ(m.resets(), 1u);
  EXPECT_DOUBLE_EQ(m.stddev()[3], 0.5);
  EXPECT_DOUBLE_EQ(m.stddev()[5], 0.5);
}

TEST(IcrEkf, BadSamplesAreRefusedAndLeaveTheEstimateAlone) {
  const std::string doc = R"(name: icr_part
step: 0.01
services:
  ekf: {type: icr_ekf, robot: r2, adaptive_reset: true, consecutive_windows: 1}
)";
  const Feed feed = [](ServiceUnderTest& s, int64_t k) {
    feed_ekf(s, k);
    ASSERT_EQ(s.deliver("r2/terrain", terrain(s, k, k < 6 ? 0 : 2, static_cast<uint32_t>(k / 3 + 1))), Rejection::none);
  };
  expect_refused_without_effect(
      doc, {}, {"r2/icr"}, 12, 5, feed,
      {
          {"gps theta NaN", [](ServiceUnderTest& s, int64_t k) { return s.deliver("r2/gps", gps(s, k, 0, 0, kNaN)); },
           Rejection::non_finite},
          {"gps x 3e6 m", [](ServiceUnderTest& s, int64_t k) { return s.deliver("r2/gps", gps(s, k, 3e6, 0, 0)); },
           Rejection::out_of_range},
          {"gps before the epoch",
           [](ServiceUnderTest& s, int64_t) { return s.deliver("r2/gps", gps(s, -1, 1, 1, 1)); },
           Rejection::negative_time},
          {"wheels inf", [](ServiceUnderTest& s, int64_t k) { return s.deliver("r2/wheels", wheels(s, k, kInf, 0)); },
           Rejection::non_finite},
          {"terrain class -2",
           [](ServiceUnderTest& s, int64_t k) { return s.deliver("r2/terrain", terrain(s, k, -2, 99)); },
           Rejection::out_of_range},
      });
}

TEST(IcrEkf, BadParametersAreConfigurationErrors) {
  expect_config_errors(kEkf, {
                                 {"services.ekf.q_diag=[1, 2]", {"services.ekf.q_diag"}},
                                 {"services.ekf.r_diag=[0, 1, 1]", {"services.ekf", "r_diag"}},
                                 {"services.ekf.process_noise=wild", {"services.ekf.process_noise"}},
                                 {"services.ekf.consecutive_windows=0", {"services.ekf", "consecutive"}},
                                 {"services.ekf.adaptive_reset=maybe", {"services.ekf.adaptive_reset"}},
                             });
}

TEST(IcrEkf, PriorResetStartsFromTheLearnedIcrsOfTheConfirmedTerrain) {
  // reset_mode prior: on the confirmed change to class 1 (tile), the ICRs are the library's
  // tile values and their sd the library's (deploy/training/icr_terrain_library.txt).
  const std::string library = std::string(PLEXUS_SOURCE_DIR) + "/deploy/training/icr_terrain_library.txt";
  const alg::TerrainIcrPrior tile = *alg::load_terrain_icr_library(library).find(1);
  ServiceUnderTest s(
      kEkf, {},
      {"services.ekf.adaptive_reset=true", "services.ekf.reset_mode=prior", "services.ekf.icr_library=" + library,
       "services.ekf.rewind_s=0"});  // at the confirmation: the library's values exactly
  int64_t k = 0;
  auto run = [&](int steps) {
    for (int i = 0; i < steps; ++i, ++k) {
      feed_ekf(s, k);
      s.step(k);
    }
  };
  s.deliver("r2/terrain", terrain(s, 0, 0, 1));
  run(10);
  s.deliver("r2/terrain", terrain(s, k, 1, 2));
  run(1);
  s.deliver("r2/terrain", terrain(s, k, 1, 3));  // confirmed: tile
  feed_ekf(s, k);
  s.step(k);
  const auto m = s.published<msg::IcrEstimate>("r2/icr");
  EXPECT_EQ(m.resets(), 1u);
  EXPECT_DOUBLE_EQ(m.y_l(), tile.mean.y_l);
  EXPECT_DOUBLE_EQ(m.y_r(), tile.mean.y_r);
  EXPECT_DOUBLE_EQ(m.x_g(), tile.mean.x_G);
  EXPECT_DOUBLE_EQ(m.stddev()[3], tile.sd(0));
  EXPECT_DOUBLE_EQ(m.stddev()[5], tile.sd(2));
}

TEST(IcrEkf, PriorResetParametersAreConfigurationErrors) {
  EXPECT_NE(config_error(kEkf, {"services.ekf.adaptive_reset=true", "services.ekf.reset_mode=prior"})
                .find("icr_library: required with reset_mode: prior"),
            std::string::npos);
  EXPECT_NE(config_error(kEkf, {"services.ekf.adaptive_reset=true", "services.ekf.reset_mode=learned"})
                .find("reset_mode: expected one of covariance, prior, got 'learned'"),
            std::string::npos);
  EXPECT_NE(config_error(kEkf, {"services.ekf.adaptive_reset=true", "services.ekf.reset_mode=prior",
                                "services.ekf.icr_library=/nonexistent/lib.txt"})
                .find("icr_library: /nonexistent/lib.txt: cannot open"),
            std::string::npos);
  EXPECT_NE(config_error(kEkf, {"services.ekf.adaptive_reset=true", "services.ekf.rewind_s=-1"})
                .find("rewind_s: must be in [0, 30] s"),
            std::string::npos);
  EXPECT_NE(config_error(kEkf, {"services.ekf.rewind_s=1"}).find("rewind_s: only used with adaptive_reset: true"),
            std::string::npos);
  EXPECT_NE(config_error(kEkf, {"services.ekf.adaptive_reset=true", "services.ekf.rewind_candidates=0"})
                .find("rewind_candidates: must be >= 1"),
            std::string::npos);
}

// --- icr_library_recorder ----------------------------------------------------------------

TEST(IcrLibraryRecorder, LearnsTheMeanOfTheSettledEstimatePerTerrain) {
  const std::string path =
      std::filesystem::temp_directory_path() / ("plexus_icr_library_" + std::to_string(::getpid()) + ".txt");
  const std::string part =
      "name: lib_part\nstep: 0.01\nservices:\n  rec: {type: icr_library_recorder, robot: r2, "
      "settle_s: 0.5, class_names: [a, b], output: " +
      path + "}\n";
  ServiceUnderTest s(part);
  EXPECT_EQ(s.message_type("r2/icr"), "IcrEstimate");
  EXPECT_EQ(s.message_type("r2/truth/state"), "SkidSteerTruth");
  // Terrain 1 for 2.5 s: from 0.5 s on (settled) the estimate alternates 0.45 / 0.55 around
  // 0.5 (y_l), with the filter's sd 0.03: the library holds mean 0.5 and
  // sd = sqrt(sample variance + 0.03^2); the unsettled first 0.5 s (y_l = 9) is left out.
  for (int64_t k = 0; k < 250; ++k) {
    auto t = s.stamped<msg::SkidSteerTruth>(k);
    t.terrain_id(1);
    s.deliver("r2/truth/state", t);
    const bool settled = k >= 50;
    auto m = s.stamped<msg::IcrEstimate>(k);
    m.y_l(settled ? (k % 2 ? 0.55 : 0.45) : 9.0), m.y_r(-0.6), m.x_g(-0.2);
    m.stddev({0, 0, 0, 0.03, 0.03, 0.03});
    s.deliver("r2/icr", m);
    s.step(k);
  }
  EXPECT_EQ(s.out("r2/recorder", "samples"), 200.0);  // steps 50..249
  const auto lib = alg::load_terrain_icr_library(path);
  std::filesystem::remove(path);
  ASSERT_NE(lib.find(1), nullptr);
  EXPECT_EQ(lib.find(0), nullptr);
  EXPECT_EQ(lib.names.at(1), "b");
  EXPECT_NEAR(lib.find(1)->mean.y_l, 0.5, 1e-6);
  EXPECT_NEAR(lib.find(1)->mean.y_r, -0.6, 1e-6);
  // 100 of each of +-0.05 about 0.5: sample variance 0.0025 * 200 / 199.
  EXPECT_NEAR(lib.find(1)->sd(0), std::sqrt(0.0025 * 200.0 / 199.0 + 0.0009), 1e-4);
  EXPECT_NEAR(lib.find(1)->sd(1), 0.03, 1e-4);
  EXPECT_EQ(lib.find(1)->samples, 200);
}

// --- icr_odometry -----------------------------------------------------------------------

const std::string kOdometry = R"(name: odo_part
step: 0.01
services:
  odo: {type: icr_odometry, robot: r2, model: fixed, y_l: 0.25, y_r: -0.25, x_G: 0.0}
)";

msg::SkidSteerTruth truth(const ServiceUnderTest& s, int64_t k, double x, double y, double theta) {
  auto m = s.stamped<msg::SkidSteerTruth>(k);
  m.x(x), m.y(y), m.theta(theta);
  return m;
}

msg::IcrEstimate icr_estimate(const ServiceUnderTest& s, int64_t k, double y_l, double y_r, double x_G) {
  auto m = s.stamped<msg::IcrEstimate>(k);
  m.y_l(y_l), m.y_r(y_r), m.x_g(x_G);
  return m;
}

TEST(IcrOdometry, DeadReckoningByHand) {
  ServiceUnderTest s(kOdometry);
  EXPECT_EQ(s.message_type("r2/truth/state"), "SkidSteerTruth");
  EXPECT_EQ(s.message_type("r2/odo"), "Pose2D");
  s.deliver("r2/truth/state", truth(s, 0, 1.0, 2.0, 0.0));
  s.deliver("r2/wheels", wheels(s, 0, 1.0, 1.0));
  s.step(0);  // starts at the truth
  EXPECT_EQ(s.published<msg::Pose2D>("r2/odo").x(), 1.0);
  s.deliver("r2/truth/state", truth(s, 1, 50.0, 50.0, 1.0));  // read once, at the start only
  s.step(1);                                                  // straight at 1 m/s
  auto m = s.published<msg::Pose2D>("r2/odo");
  EXPECT_DOUBLE_EQ(m.x(), 1.01);
  EXPECT_DOUBLE_EQ(m.y(), 2.0);
  s.deliver("r2/wheels", wheels(s, 2, 0.5, 1.0));
  s.step(2);  // v_x = (1 0.25 + 0.5 0.25) / 0.5 = 0.75, omega = 0.5 / 0.5 = 1
  const alg::Pose2 p = alg::icr_pose_step({1.01, 2.0, 0.0}, {0.75, 0.0, 1.0}, 0.01);
  m = s.published<msg::Pose2D>("r2/odo");
  EXPECT_DOUBLE_EQ(m.x(), p.x);
  EXPECT_DOUBLE_EQ(m.y(), p.y);
  EXPECT_DOUBLE_EQ(m.theta(), 0.01);
}

TEST(IcrOdometry, EstimatedModelUsesTheFiltersIcrs) {
  ServiceUnderTest s(R"(name: odo_part
step: 0.01
services:
  odo: {type: icr_odometry, robot: r2, model: estimated, start: 0.02}
)");
  EXPECT_EQ(s.message_type("r2/icr"), "IcrEstimate");
  alg::IcrOdometry ref;
  for (int64_t k = 0; k < 6; ++k) {
    s.deliver("r2/truth/state", truth(s, k, 3.0, -1.0, 0.5 + static_cast<double>(k)));
    s.deliver("r2/wheels", wheels(s, k, 0.2, 0.7));
    s.deliver("r2/icr", icr_estimate(s, k, 0.3 + 0.01 * static_cast<double>(k), -0.28, 0.04));
    s.step(k);
    if (k == 2) ref.reset({3.0, -1.0, 2.5});  // start = 0.02 s: the truth of step 2
    if (k > 2) ref.step({0.2, 0.7}, {0.3 + 0.01 * static_cast<double>(k), -0.28, 0.04}, 0.01);
    if (k < 2) {
      EXPECT_EQ(s.out("r2/odo", "x"), 0.0) << k;  // not started
    } else {
      EXPECT_DOUBLE_EQ(s.out("r2/odo", "x"), ref.pose().x) << k;
      EXPECT_DOUBLE_EQ(s.out("r2/odo", "y"), ref.pose().y) << k;
      EXPECT_DOUBLE_EQ(s.out("r2/odo", "theta"), ref.pose().theta) << k;
    }
  }
  EXPECT_NE(s.out("r2/odo", "y"), -1.0);
}

TEST(IcrOdometry, ARewoundModelIsIntegratedAgainFromItsSwitch) {
  // The estimate says (model_age) since when its ICRs apply. Until step 9 model A applies
  // since 0; at step 10 model B arrives, applying since 0.05 s (a rewound reset): steps 5-9
  // are integrated again with B, as if B had been known from 0.05 s on.
  ServiceUnderTest s(R"(name: odo_part
step: 0.01
services:
  odo: {type: icr_odometry, robot: r2, model: estimated}
)");
  const alg::IcrParams a{0.3, -0.3, 0.0}, b{0.5, -0.45, 0.1};
  alg::IcrOdometry ref;
  ref.reset({1.0, 2.0, 0.3});
  for (int64_t k = 0; k <= 12; ++k) {
    const double t = 0.01 * static_cast<double>(k);
    const alg::TrackSpeeds u{0.2, 0.3 + 0.05 * t};
    s.deliver("r2/truth/state", truth(s, k, 1.0, 2.0, 0.3));
    s.deliver("r2/wheels", wheels(s, k, u.v_l, u.v_r));
    const alg::IcrParams m = k < 10 ? a : b;
    auto e = icr_estimate(s, k, m.y_l, m.y_r, m.x_G);
    e.model_age(k < 10 ? t : t - 0.05);
    s.deliver("r2/icr", e);
    s.step(k);
    if (k > 0) ref.step(u, k < 5 ? a : b, 0.01);
  }
  EXPECT_NEAR(s.out("r2/odo", "x"), ref.pose().x, 1e-12);
  EXPECT_NEAR(s.out("r2/odo", "y"), ref.pose().y, 1e-12);
  EXPECT_NEAR(s.out("r2/odo", "theta"), ref.pose().theta, 1e-12);
  // Without revision (revise_s 0) the steps before the model's arrival keep model A.
  ServiceUnderTest plain(R"(name: odo_part
step: 0.01
services:
  odo: {type: icr_odometry, robot: r2, model: estimated, revise_s: 0}
)");
  for (int64_t k = 0; k <= 12; ++k) {
    const double t = 0.01 * static_cast<double>(k);
    plain.deliver("r2/truth/state", truth(plain, k, 1.0, 2.0, 0.3));
    plain.deliver("r2/wheels", wheels(plain, k, 0.2, 0.3 + 0.05 * t));
    const alg::IcrParams m = k < 10 ? a : b;
    auto e = icr_estimate(plain, k, m.y_l, m.y_r, m.x_G);
    e.model_age(k < 10 ? t : t - 0.05);
    plain.deliver("r2/icr", e);
    plain.step(k);
  }
  EXPECT_GT(std::abs(plain.out("r2/odo", "theta") - ref.pose().theta), 1e-6);
}

TEST(IcrOdometry, BadSamplesAreRefusedAndLeaveThePoseAlone) {
  const std::string doc = R"(name: odo_part
step: 0.01
services:
  odo: {type: icr_odometry, robot: r2, model: estimated}
)";
  const Feed feed = [](ServiceUnderTest& s, int64_t k) {
    ASSERT_EQ(s.deliver("r2/truth/state", truth(s, k, 1, 1, 0.3)), Rejection::none);
    ASSERT_EQ(s.deliver("r2/wheels", wheels(s, k, 0.4, 0.5 + 0.1 * static_cast<double>(k))), Rejection::none);
    ASSERT_EQ(s.deliver("r2/icr", icr_estimate(s, k, 0.3, -0.3, 0.01 * static_cast<double>(k))), Rejection::none);
  };
  expect_refused_without_effect(
      doc, {}, {"r2/odo"}, 8, 4, feed,
      {
          {"wheels NaN", [](ServiceUnderTest& s, int64_t k) { return s.deliver("r2/wheels", wheels(s, k, 0, kNaN)); },
           Rejection::non_finite},
          {"icr y_l 2e6 m",
           [](ServiceUnderTest& s, int64_t k) { return s.deliver("r2/icr", icr_estimate(s, k, 2e6, -0.3, 0)); },
           Rejection::out_of_range},
          {"icr x_G NaN",
           [](ServiceUnderTest& s, int64_t k) { return s.deliver("r2/icr", icr_estimate(s, k, 0.3, -0.3, kNaN)); },
           Rejection::non_finite},
      });
}

TEST(IcrOdometry, BadParametersAreConfigurationErrors) {
  expect_config_errors(kOdometry, {
                                      {"services.odo.model=guess", {"services.odo.model"}},
                                      {"services.odo.start=-1", {"services.odo.start"}},
                                      {"services.odo.y_l=-0.5", {"services.odo", "y_l"}},
                                      {"services.odo.x_G=[0]", {"services.odo.x_G"}},
                                      {"services.odo.revise_s=1", {"services.odo.revise_s", "model: estimated"}},
                                  });
  EXPECT_NE(config_error(R"(name: p
step: 0.01
services:
  odo: {type: icr_odometry, robot: r2, model: no_slip, track_width: 0}
)",
                         {})
                .find("track_width"),
            std::string::npos);
}

}  // namespace
}  // namespace plexus::services_test
