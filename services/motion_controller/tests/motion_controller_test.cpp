// motion_controller: trajectory_tracking (paper 000), path_following (paper 003),
// reference_feedforward and skid_steer_driver. PlanarReference / PathSample / Pose2D /
// PositionMeasurement / HeadingEstimate in -> edge check -> control law ->
// UnicycleCommand / TrackCommand out.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "plexus/algorithms/skid_steer/driving_pattern.hpp"
#include "plexus/algorithms/unicycle/path_following_controller.hpp"
#include "plexus/algorithms/unicycle/tracking_controller.hpp"
#include "service_harness.hpp"

namespace plexus::services_test {
namespace {

// The component types of services/motion_controller/ whose data path this file tests.
const Covers kCovers{"trajectory_tracking", "path_following", "reference_feedforward", "skid_steer_driver"};

namespace alg = plexus::algorithms;

msg::PlanarReference reference(const ServiceUnderTest& s, int64_t k, Eigen::Vector2d p, Eigen::Vector2d dp,
                               Eigen::Vector2d ddp) {
  auto m = s.stamped<msg::PlanarReference>(k);
  m.position()[0] = p.x(), m.position()[1] = p.y();
  m.velocity()[0] = dp.x(), m.velocity()[1] = dp.y();
  m.acceleration()[0] = ddp.x(), m.acceleration()[1] = ddp.y();
  return m;
}

msg::Pose2D pose(const ServiceUnderTest& s, int64_t k, double x, double y, double theta) {
  auto m = s.stamped<msg::Pose2D>(k);
  m.x(x), m.y(y), m.theta(theta);
  return m;
}

msg::PositionMeasurement position(const ServiceUnderTest& s, int64_t k, double x, double y) {
  auto m = s.stamped<msg::PositionMeasurement>(k);
  m.x(x), m.y(y);
  return m;
}

msg::HeadingEstimate heading(const ServiceUnderTest& s, int64_t k, double z_a, double z4) {
  auto m = s.stamped<msg::HeadingEstimate>(k);
  m.direction()[0] = z_a, m.direction()[1] = z4;
  return m;
}

// --- trajectory_tracking ----------------------------------------------------------------

const std::string kTrackingState = R"(name: ctl_part
step: 0.01
services:
  ctl: {type: trajectory_tracking, robot: r1, feedback: state, k1: 0.11, k2: 0.11, k3: 0.01, reference_min_speed: 1.0}
)";

const std::string kTrackingOutput = R"(name: ctl_part
step: 0.01
services:
  ctl: {type: trajectory_tracking, robot: r1, feedback: output, k1: 0.11, k2: 0.11, k3: 0.01, reference_min_speed: 1.0}
)";

alg::ReferenceSample ref_at(int64_t k) {
  const double t = 0.01 * static_cast<double>(k);
  alg::ReferenceSample r;
  r.p = {t, 0.2 * t * t};
  r.dp = {1.0, 0.4 * t};
  r.ddp = {0.0, 0.4};
  return r;
}

TEST(TrajectoryTracking, OnTheReferenceTheCommandIsTheFeedforward) {
  // On track (zeta = 0), heading along p_r': v = |p_r'| = 1 and
  // omega = theta*' = (x_r' y_r'' - y_r' x_r'') / v^2 = 0.5 (paper 000 eq. (14)).
  ServiceUnderTest s(kTrackingState);
  EXPECT_EQ(s.message_type("r1/truth/state"), "Pose2D");
  s.step(0);  // no inputs yet: zero command
  EXPECT_EQ(s.out("r1/cmd", "v"), 0.0);
  EXPECT_EQ(s.out("r1/cmd", "omega"), 0.0);
  ASSERT_EQ(s.deliver("r1/reference", reference(s, 1, {0, 0}, {1, 0}, {0, 0.5})), Rejection::none);
  ASSERT_EQ(s.deliver("r1/truth/state", pose(s, 1, 0, 0, 0)), Rejection::none);
  s.step(1);
  const auto m = s.published<msg::UnicycleCommand>("r1/cmd");
  EXPECT_NEAR(m.v(), 1.0, 1e-12);
  EXPECT_NEAR(m.omega(), 0.5, 1e-12);
  EXPECT_EQ(s.check_output("r1/cmd"), Rejection::none);
}

TEST(TrajectoryTracking, AnOffsetGivesTheSaturatedCorrection) {
  // 1 m right of the reference: zeta2 = -1, f2 = k2 atan(-1), S = (1, k2 pi / 4),
  // v = |S| (eq. (14)); omega from the algorithm itself.
  ServiceUnderTest s(kTrackingState);
  s.deliver("r1/reference", reference(s, 0, {0, 0}, {1, 0}, {0, 0}));
  s.deliver("r1/truth/state", pose(s, 0, 0, -1, 0));
  s.step(0);
  EXPECT_NEAR(s.out("r1/cmd", "v"), std::hypot(1.0, 0.11 * std::numbers::pi / 4), 1e-12);
  const alg::TrajectoryTrackingController ctl({0.11, 0.11, 0.01, 0.9, 1e-3});
  alg::ReferenceSample r;
  r.dp = {1, 0};
  const auto u = ctl.state_feedback(r, {0, -1, 0}).input;
  EXPECT_NEAR(s.out("r1/cmd", "omega"), u.omega, 1e-15);
  EXPECT_GT(s.out("r1/cmd", "omega"), 0.0);  // turns left, towards the reference
}

TEST(TrajectoryTracking, OutputFeedbackUsesPositionAndObserverHeading) {
  ServiceUnderTest s(kTrackingOutput);
  EXPECT_EQ(s.message_type("r1/position"), "PositionMeasurement");
  EXPECT_EQ(s.message_type("r1/heading"), "HeadingEstimate");
  s.deliver("r1/reference", reference(s, 0, {0, 0}, {1, 0}, {0, 0.5}));
  s.deliver("r1/position", position(s, 0, 0, 0));
  s.step(0);  // no heading estimate yet: zero
  EXPECT_EQ(s.out("r1/cmd", "v"), 0.0);
  s.deliver("r1/heading", heading(s, 0, 1.0, 0.0));  // z_hat = (cos 0, sin 0)
  s.step(1);
  EXPECT_NEAR(s.out("r1/cmd", "v"), 1.0, 1e-12);
  EXPECT_NEAR(s.out("r1/cmd", "omega"), 0.5, 1e-12);
  // Off track with an estimate off the true heading: the algorithm's output feedback.
  s.deliver("r1/position", position(s, 2, 0.3, -0.2));
  s.deliver("r1/heading", heading(s, 2, 0.8, 0.6));
  s.step(2);
  const alg::TrajectoryTrackingController ctl({0.11, 0.11, 0.01, 0.9, 1e-3});
  alg::ReferenceSample r;
  r.dp = {1, 0};
  r.ddp = {0, 0.5};
  const auto u = ctl.output_feedback(r, {0.3, -0.2}, {0.8, 0.6}).input;
  EXPECT_NEAR(s.out("r1/cmd", "v"), u.v, 1e-15);
  EXPECT_NEAR(s.out("r1/cmd", "omega"), u.omega, 1e-15);
}

// plexus param (docs/parameters.md): k1 changes between two steps; the command responds from
// that step on, as the algorithm with the new gain; a refused value leaves gain and command alone.
TEST(TrajectoryTracking, ItsGainsChangeWhileItRunsFromTheNextStep) {
  ServiceUnderTest s(kTrackingState);
  const auto& ctl = *s.scenario().components[0].component;
  ASSERT_EQ(ctl.tunables().size(), 3u);
  const scenario::TunableParameter* k1 = ctl.tunable("k1");
  ASSERT_NE(k1, nullptr);
  EXPECT_EQ(k1->get(), 0.11);
  alg::ReferenceSample r;
  r.dp = {1, 0};
  const auto command_at = [&](int64_t k) {  // 1 m behind and 0.5 m right of the reference
    s.deliver("r1/reference", reference(s, k, {0, 0}, {1, 0}, {0, 0}));
    s.deliver("r1/truth/state", pose(s, k, -1, -0.5, 0));
    s.step(k);
    return s.published<msg::UnicycleCommand>("r1/cmd");
  };
  const auto before = command_at(0);
  const auto u_before =
      alg::TrajectoryTrackingController({0.11, 0.11, 0.01, 0.9, 1e-3}).state_feedback(r, {-1, -0.5, 0});
  EXPECT_NEAR(before.v(), u_before.input.v, 1e-15);
  k1->set(0.3);
  const auto after = command_at(1);
  const auto u_after = alg::TrajectoryTrackingController({0.3, 0.11, 0.01, 0.9, 1e-3}).state_feedback(r, {-1, -0.5, 0});
  EXPECT_NEAR(after.v(), u_after.input.v, 1e-15);
  EXPECT_NEAR(after.omega(), u_after.input.omega, 1e-15);
  EXPECT_GT(after.v(), before.v() + 0.1);  // f1 = k1 atan(1): a larger k1 catches up faster
  EXPECT_THROW(k1->set(0.0), std::invalid_argument);
  EXPECT_EQ(k1->get(), 0.3);
  const auto refused = command_at(2);
  EXPECT_EQ(refused.v(), after.v());
  EXPECT_EQ(refused.omega(), after.omega());
}

void feed_tracking(ServiceUnderTest& s, int64_t k) {
  const auto r = ref_at(k);
  ASSERT_EQ(s.deliver("r1/reference", reference(s, k, r.p, r.dp, r.ddp)), Rejection::none);
  ASSERT_EQ(s.deliver("r1/truth/state", pose(s, k, r.p.x() + 0.1, r.p.y() - 0.2, 0.05 * static_cast<double>(k))),
            Rejection::none);
}

TEST(TrajectoryTracking, BadSamplesAreRefusedAndLeaveTheCommandAlone) {
  expect_refused_without_effect(
      kTrackingState, {}, {"r1/cmd"}, 8, 4, feed_tracking,
      {
          {"reference ddy NaN",
           [](ServiceUnderTest& s, int64_t k) {
             return s.deliver("r1/reference", reference(s, k, {0, 0}, {1, 0}, {0, kNaN}));
           },
           Rejection::non_finite},
          {"reference dx 1e5 m/s",
           [](ServiceUnderTest& s, int64_t k) {
             return s.deliver("r1/reference", reference(s, k, {0, 0}, {1e5, 0}, {0, 0}));
           },
           Rejection::out_of_range},
          {"state theta 2e6 rad",
           [](ServiceUnderTest& s, int64_t k) { return s.deliver("r1/truth/state", pose(s, k, 0, 0, 2e6)); },
           Rejection::out_of_range},
          {"state x -inf",
           [](ServiceUnderTest& s, int64_t k) { return s.deliver("r1/truth/state", pose(s, k, -kInf, 0, 0)); },
           Rejection::non_finite},
          {"state before the epoch",
           [](ServiceUnderTest& s, int64_t) { return s.deliver("r1/truth/state", pose(s, -1, 0, 0, 0)); },
           Rejection::negative_time},
      });
}

TEST(TrajectoryTracking, BadParametersAreConfigurationErrors) {
  expect_config_errors(kTrackingState, {
                                           {"services.ctl.feedback=velocity", {"services.ctl.feedback"}},
                                           {"services.ctl.k3=-1", {"services.ctl", "k3"}},
                                           {"services.ctl.gamma=1.5", {"services.ctl", "gamma"}},
                                           {"services.ctl.reference_min_speed=0", {"services.ctl.reference_min_speed"}},
                                           {"services.ctl.k1=[0.1]", {"services.ctl.k1"}},
                                       });
}

// --- path_following ---------------------------------------------------------------------

const std::string kPathState = R"(name: ctl_part
step: 0.01
services:
  ctl: {type: path_following, robot: r1, feedback: state, u1: 1.0, k1: 1.0, k2: 2.0}
)";

const std::string kPathObserver = R"(name: ctl_part
step: 0.01
services:
  ctl: {type: path_following, robot: r1, feedback: observer, u1: 1.0, k1: 1.0, k2: 2.0}
)";

msg::PathSample path(const ServiceUnderTest& s, int64_t k, double h, double hx, double hy, double hxx, double hxy,
                     double hyy) {
  auto m = s.stamped<msg::PathSample>(k);
  m.h(h);
  m.gradient()[0] = hx, m.gradient()[1] = hy;
  m.hessian()[0] = hxx, m.hessian()[1] = hxy, m.hessian()[2] = hyy;
  return m;
}

TEST(PathFollowing, TurnRateByHand) {
  // h = 0.5, grad h = (1, 0), Hess h = 2 I, heading pi/2, u1 = 1: w = (0, 1), h' = 0,
  // f = w^T H w = 2, g = -h_x w_y + h_y w_x = -1, u2 = (-f - k2 h' - k1 h) / g = 2.5 (eq. (5)).
  ServiceUnderTest s(kPathState);
  EXPECT_EQ(s.fields("r1/truth/state"), std::vector<std::string>{"theta"});
  s.step(0);  // no inputs yet: v = u1, omega = 0
  EXPECT_EQ(s.out("r1/cmd", "v"), 1.0);
  EXPECT_EQ(s.out("r1/cmd", "omega"), 0.0);
  s.deliver("r1/path", path(s, 1, 0.5, 1, 0, 2, 0, 2));
  s.deliver("r1/truth/state", pose(s, 1, 0, 0, std::numbers::pi / 2));
  s.step(1);
  const auto m = s.published<msg::UnicycleCommand>("r1/cmd");
  EXPECT_EQ(m.v(), 1.0);
  EXPECT_NEAR(m.omega(), 2.5, 1e-12);
}

TEST(PathFollowing, ObserverFeedbackUsesTheVelocityEstimate) {
  ServiceUnderTest s(kPathObserver);
  s.deliver("r1/path", path(s, 0, 0.5, 1, 0, 2, 0, 2));
  s.deliver("r1/heading", heading(s, 0, 0.0, 1.0));  // z_hat = (z2, z4) = (0, 1)
  s.step(0);
  EXPECT_DOUBLE_EQ(s.out("r1/cmd", "omega"), 2.5);
  // A general case against the algorithm (eqs. (15)-(16)).
  s.deliver("r1/path", path(s, 1, -0.3, 0.4, 1.2, 2, 0.5, 1));
  s.deliver("r1/heading", heading(s, 1, 0.6, -0.7));
  s.step(1);
  const alg::PathFollowingController ctl({1.0, 2.0, 1e-3, std::numeric_limits<double>::infinity()});
  alg::PathEvaluation e;
  e.h = -0.3;
  e.gradient = {0.4, 1.2};
  e.hessian << 2, 0.5, 0.5, 1;
  EXPECT_NEAR(s.out("r1/cmd", "omega"), ctl.compute(e, {0.6, -0.7}).u2, 1e-15);
}

void feed_path(ServiceUnderTest& s, int64_t k) {
  const double t = 0.01 * static_cast<double>(k);
  ASSERT_EQ(s.deliver("r1/path", path(s, k, 0.2 - t, 1, 0.3, 2, 0, 2)), Rejection::none);
  ASSERT_EQ(s.deliver("r1/truth/state", pose(s, k, 0, 0, 1.0 + t)), Rejection::none);
}

TEST(PathFollowing, BadSamplesAreRefusedAndLeaveTheCommandAlone) {
  expect_refused_without_effect(
      kPathState, {}, {"r1/cmd"}, 8, 4, feed_path,
      {
          {"path h 1e13",
           [](ServiceUnderTest& s, int64_t k) { return s.deliver("r1/path", path(s, k, 1e13, 1, 0, 2, 0, 2)); },
           Rejection::out_of_range},
          {"path hxy NaN",
           [](ServiceUnderTest& s, int64_t k) { return s.deliver("r1/path", path(s, k, 0, 1, 0, 2, kNaN, 2)); },
           Rejection::non_finite},
          {"heading inf",
           [](ServiceUnderTest& s, int64_t k) { return s.deliver("r1/truth/state", pose(s, k, 0, 0, kInf)); },
           Rejection::non_finite},
      });
}

TEST(PathFollowing, BadParametersAreConfigurationErrors) {
  expect_config_errors(kPathState, {
                                       {"services.ctl.u1=0", {"services.ctl.u1"}},
                                       {"services.ctl.k2=0", {"services.ctl", "k2"}},
                                       {"services.ctl.feedback=output", {"services.ctl.feedback"}},
                                       {"services.ctl.min_abs_g=-1", {"services.ctl", "min_abs_g"}},
                                   });
}

// --- reference_feedforward --------------------------------------------------------------

const std::string kFeedforward = R"(name: ff_part
step: 0.01
services:
  ff: {type: reference_feedforward, robot: r1}
)";

TEST(ReferenceFeedforward, SpeedAndTurnRateOfTheReference) {
  // p_r' = (3, 4), p_r'' = (0, 1): v = 5, omega = (3 * 1 - 4 * 0) / 25 = 0.12.
  ServiceUnderTest s(kFeedforward);
  s.deliver("r1/reference", reference(s, 0, {7, -2}, {3, 4}, {0, 1}));
  s.step(0);
  const auto m = s.published<msg::UnicycleCommand>("r1/cmd");
  EXPECT_DOUBLE_EQ(m.v(), 5.0);
  EXPECT_DOUBLE_EQ(m.omega(), 0.12);
}

TEST(ReferenceFeedforward, BadSamplesAreRefusedAndLeaveTheCommandAlone) {
  const Feed feed = [](ServiceUnderTest& s, int64_t k) {
    const auto r = ref_at(k);
    ASSERT_EQ(s.deliver("r1/reference", reference(s, k, r.p, r.dp, r.ddp)), Rejection::none);
  };
  expect_refused_without_effect(kFeedforward, {}, {"r1/cmd"}, 6, 3, feed,
                                {
                                    {"velocity NaN",
                                     [](ServiceUnderTest& s, int64_t k) {
                                       return s.deliver("r1/reference", reference(s, k, {0, 0}, {kNaN, 1}, {0, 0}));
                                     },
                                     Rejection::non_finite},
                                    {"acceleration 1e8",
                                     [](ServiceUnderTest& s, int64_t k) {
                                       return s.deliver("r1/reference", reference(s, k, {0, 0}, {1, 1}, {1e8, 0}));
                                     },
                                     Rejection::out_of_range},
                                });
}

TEST(ReferenceFeedforward, BadParametersAreConfigurationErrors) {
  expect_config_errors(kFeedforward, {
                                         {"services.ff.gain=1", {"services.ff.gain", "unknown key"}},
                                         {"services.ff.rate=7", {"services.ff.rate"}},
                                     });
}

// --- skid_steer_driver ------------------------------------------------------------------

const std::string kDriver = R"(name: driver_part
step: 0.01
services:
  driver: {type: skid_steer_driver, robot: r1, pattern: circle, speed: 0.5, turn_rate: 0.5}
)";

TEST(SkidSteerDriver, CircleTrackSpeedsByHand) {
  // v -/+ w B / 2 with B = 0.4: (0.4, 0.6), at every step.
  ServiceUnderTest s(kDriver);
  EXPECT_TRUE(s.remote_inputs().empty());
  for (int64_t k : {0, 1, 250}) {
    s.step(k);
    const auto m = s.published<msg::TrackCommand>("r1/cmd");
    EXPECT_DOUBLE_EQ(m.left(), 0.4) << k;
    EXPECT_DOUBLE_EQ(m.right(), 0.6) << k;
  }
  // It reads nothing: no edge check of its own; what it publishes passes the consumer's.
  EXPECT_EQ(s.check_output("r1/cmd"), Rejection::none);
}

TEST(SkidSteerDriver, PatternsFollowTheClock) {
  ServiceUnderTest seg(
      kDriver, {}, {"services.driver.pattern=segments", "services.driver.segments=[[1.0, 0.1, 0.2], [1.0, 0.3, 0.4]]"});
  seg.step(50);  // t = 0.5 s: first segment
  EXPECT_EQ(seg.out("r1/cmd", "v_l"), 0.1);
  seg.step(150);  // t = 1.5 s: second
  EXPECT_EQ(seg.out("r1/cmd", "v_r"), 0.4);
  seg.step(250);  // t = 2.5 s: repeated, first again
  EXPECT_EQ(seg.out("r1/cmd", "v_l"), 0.1);
  ServiceUnderTest eight(kDriver, {}, {"services.driver.pattern=figure_eight", "services.driver.period=10"});
  alg::DrivingPatternParams p;
  p.kind = alg::DrivingPatternKind::kFigureEight;
  p.speed = 0.5, p.turn_rate = 0.5, p.period = 10.0;
  const alg::DrivingPattern pattern(p);
  for (int64_t k : {0, 125, 333}) {
    eight.step(k);
    EXPECT_DOUBLE_EQ(eight.out("r1/cmd", "v_l"), pattern.at(0.01 * static_cast<double>(k)).v_l);
    EXPECT_DOUBLE_EQ(eight.out("r1/cmd", "v_r"), pattern.at(0.01 * static_cast<double>(k)).v_r);
  }
  EXPECT_NE(eight.out("r1/cmd", "v_l"), eight.out("r1/cmd", "v_r"));
}

TEST(SkidSteerDriver, BadParametersAreConfigurationErrors) {
  expect_config_errors(kDriver, {
                                    {"services.driver.pattern=zigzag", {"services.driver.pattern"}},
                                    {"services.driver.track_width=-0.4", {"services.driver", "track_width"}},
                                    {"services.driver.speed=.nan", {"services.driver", "speed"}},
                                });
  EXPECT_NE(config_error(kDriver, {"services.driver.pattern=segments", "services.driver.segments=[[1.0, 0.1]]"})
                .find("services.driver.segments"),
            std::string::npos);
}

}  // namespace
}  // namespace plexus::services_test
