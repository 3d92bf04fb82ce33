// attitude_filter: attitude_filter (UKF / EKF, paper 002), balancing_controller and
// motion_profile. Imu + WheelTorqueCommand in -> edge check -> filter cycle ->
// AttitudeEstimate out; TravelState + AttitudeEstimate in -> state feedback ->
// WheelTorqueCommand out; the clock -> TravelState reference out.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "plexus/algorithms/balancing/attitude_filter.hpp"
#include "plexus/algorithms/balancing/balancing_controller.hpp"
#include "plexus/algorithms/balancing/imu_sensor.hpp"
#include "plexus/algorithms/balancing/wheeled_inverted_pendulum.hpp"
#include "service_harness.hpp"

namespace plexus::services_test {
namespace {

// The component types of services/attitude_filter/ whose data path this file tests.
const Covers kCovers{"attitude_filter", "balancing_controller", "motion_profile"};

namespace alg = plexus::algorithms;
constexpr double kDeg = std::numbers::pi / 180.0;

// --- attitude_filter --------------------------------------------------------------------

const std::string kFilter = R"(name: att_part
step: 0.01
services:
  att: {type: attitude_filter, robot: r3}
)";

msg::Imu imu(const ServiceUnderTest& s, int64_t k, double acc_x, double acc_z, double gyro) {
  auto m = s.stamped<msg::Imu>(k);
  m.linear_acceleration()[0] = acc_x;
  m.linear_acceleration()[2] = acc_z;
  m.angular_velocity()[1] = gyro;
  return m;
}

msg::WheelTorqueCommand torque(const ServiceUnderTest& s, int64_t k, double t) {
  auto m = s.stamped<msg::WheelTorqueCommand>(k);
  m.torque(t);
  return m;
}

// The accelerometer reading of a tilt (a still body): specific force g along the body axis.
msg::Imu tilted(const ServiceUnderTest& s, int64_t k, double tilt, double gyro) {
  return imu(s, k, -9.81 * std::sin(tilt), 9.81 * std::cos(tilt), gyro);
}

TEST(AttitudeFilter, FirstCycleIsOneKalmanUpdateByHand) {
  // EKF, paper measurement z = theta: the first cycle only updates. From x = 0 with
  // sigma_theta = 0.5 deg and r = 0.2 deg: theta+ = 0.25 / (0.25 + 0.04) z and
  // sigma+ = sqrt(0.25 * 0.04 / 0.29) deg; rate and drift are not measured: they stay 0.
  ServiceUnderTest s(kFilter, {}, {"services.att.filter=ekf", "services.att.measurement=paper"});
  EXPECT_EQ(s.message_type("r3/imu"), "Imu");
  EXPECT_EQ(s.message_type("r3/cmd"), "WheelTorqueCommand");
  s.step(0);  // no IMU sample yet: the initial estimate
  auto m = s.published<msg::AttitudeEstimate>("r3/attitude");
  EXPECT_EQ(m.tilt(), 0.0);
  EXPECT_NEAR(m.stddev()[0], 0.5 * kDeg, 1e-15);
  ASSERT_EQ(s.deliver("r3/imu", tilted(s, 1, 0.05, 0.0)), Rejection::none);
  s.step(1);
  m = s.published<msg::AttitudeEstimate>("r3/attitude");
  EXPECT_NEAR(m.tilt(), 0.25 / 0.29 * 0.05, 1e-12);
  EXPECT_NEAR(m.stddev()[0], std::sqrt(0.25 * 0.04 / 0.29) * kDeg, 1e-12);
  EXPECT_EQ(m.tilt_rate(), 0.0);
  EXPECT_EQ(m.gyro_drift(), 0.0);
  s.step(2);  // no new IMU sample: no cycle, the estimate is held
  EXPECT_NEAR(s.out("r3/attitude", "theta"), 0.25 / 0.29 * 0.05, 1e-12);
}

alg::AttitudeFilterParams service_defaults() {
  // The component's defaults: its model from the plant's and the IMU's default keys.
  alg::AttitudeFilterParams f;
  const alg::WheeledPendulumParams plant;
  f.model.coefficients = alg::WheeledInvertedPendulum(plant).coefficients();
  f.model.gravity = plant.gravity;
  f.model.gamma1 = alg::GyroParams{}.gamma1;
  f.model.gamma2 = alg::GyroParams{}.gamma2;
  f.model.gyro_range = alg::GyroParams{}.range;
  f.model.accelerometer_height = alg::AccelerometerParams{}.height;
  f.model.dt = 0.01;
  return f;
}

double tilt_at(int64_t k) { return 0.03 * std::sin(0.2 * static_cast<double>(k)); }
double gyro_at(int64_t k) { return 0.006 * std::cos(0.2 * static_cast<double>(k)) + 0.01; }
double torque_at(int64_t k) { return 0.1 * static_cast<double>(k % 3) - 0.1; }

void feed_filter(ServiceUnderTest& s, int64_t k) {
  ASSERT_EQ(s.deliver("r3/imu", tilted(s, k, tilt_at(k), gyro_at(k))), Rejection::none);
  ASSERT_EQ(s.deliver("r3/cmd", torque(s, k, torque_at(k))), Rejection::none);
}

TEST(AttitudeFilter, UkfCyclesMatchTheAlgorithm) {
  ServiceUnderTest s(kFilter);
  alg::AttitudeFilter ref(service_defaults());
  for (int64_t k = 0; k < 10; ++k) {
    feed_filter(s, k);
    s.step(k);
    ref.step(torque_at(k), std::atan2(9.81 * std::sin(tilt_at(k)), 9.81 * std::cos(tilt_at(k))), gyro_at(k));
    const auto m = s.published<msg::AttitudeEstimate>("r3/attitude");
    ASSERT_NEAR(m.tilt(), ref.state()(0), 1e-13) << k;
    ASSERT_NEAR(m.tilt_rate(), ref.state()(1), 1e-13) << k;
    ASSERT_NEAR(m.gyro_drift(), ref.state()(2), 1e-13) << k;
    ASSERT_NEAR(m.stddev()[0], std::sqrt(ref.covariance()(0, 0)), 1e-15) << k;
  }
  EXPECT_NE(s.out("r3/attitude", "drift"), 0.0);  // the gyro's offset is being learnt
  EXPECT_EQ(s.check_output("r3/attitude"), Rejection::none);
}

TEST(AttitudeFilter, AMissingSampleIsPredictedOver) {
  // Realtime: the IMU sample of step 5 never came (step 5 reads the old one, step 6 the
  // new). The filter predicts over step 5's period with the held torque, then runs step 6's
  // cycle: its time stays the samples'. Counted as one bridged sample.
  ServiceUnderTest s(kFilter);
  alg::AttitudeFilter ref(service_defaults());
  for (int64_t k = 0; k < 10; ++k) {
    if (k == 5) {
      ASSERT_EQ(s.deliver("r3/cmd", torque(s, k, torque_at(k))), Rejection::none);
    } else {
      feed_filter(s, k);
    }
    s.step(k);
    if (k == 5) continue;
    if (k == 6) {
      ASSERT_TRUE(ref.predict(torque_at(k)));
    }
    ref.step(torque_at(k), std::atan2(9.81 * std::sin(tilt_at(k)), 9.81 * std::cos(tilt_at(k))), gyro_at(k));
    const auto m = s.published<msg::AttitudeEstimate>("r3/attitude");
    ASSERT_NEAR(m.tilt(), ref.state()(0), 1e-13) << k;
    ASSERT_NEAR(m.tilt_rate(), ref.state()(1), 1e-13) << k;
    ASSERT_NEAR(m.stddev()[0], std::sqrt(ref.covariance()(0, 0)), 1e-15) << k;
  }
  EXPECT_EQ(s.scenario().components[0].component->dropped_late_samples(), 1u);
}

TEST(AttitudeFilter, BadSamplesAreRefusedAndLeaveTheEstimateAlone) {
  expect_refused_without_effect(
      kFilter, {}, {"r3/attitude"}, 8, 4, feed_filter,
      {
          {"acc_x NaN", [](ServiceUnderTest& s, int64_t k) { return s.deliver("r3/imu", imu(s, k, kNaN, 9.81, 0)); },
           Rejection::non_finite},
          {"gyro 2e4 rad/s",
           [](ServiceUnderTest& s, int64_t k) { return s.deliver("r3/imu", imu(s, k, 0, 9.81, 2e4)); },
           Rejection::out_of_range},
          {"acc_z -inf", [](ServiceUnderTest& s, int64_t k) { return s.deliver("r3/imu", imu(s, k, 0, -kInf, 0)); },
           Rejection::non_finite},
          {"IMU before the epoch",
           [](ServiceUnderTest& s, int64_t) { return s.deliver("r3/imu", imu(s, -1, 0, 9.81, 0)); },
           Rejection::negative_time},
          {"torque NaN", [](ServiceUnderTest& s, int64_t k) { return s.deliver("r3/cmd", torque(s, k, kNaN)); },
           Rejection::non_finite},
      });
}

TEST(AttitudeFilter, BadParametersAreConfigurationErrors) {
  expect_config_errors(kFilter, {
                                    {"services.att.filter=particle", {"services.att.filter"}},
                                    {"services.att.r_tilt_deg=0", {"services.att.r_tilt_deg"}},
                                    {"services.att.q_rate_degps=-1", {"services.att.q_rate_degps"}},
                                    {"services.att.imu_rate=30", {"services.att.imu_rate"}},
                                    {"services.att.com_height=-0.1", {"services.att", "com_height"}},
                                    {"services.att.process_model=quadratic", {"services.att.process_model"}},
                                });
}

// --- balancing_controller ---------------------------------------------------------------

const std::string kController = R"(name: bal_part
step: 0.01
services:
  ctl: {type: balancing_controller, robot: r3}
)";

msg::TravelState travel(const ServiceUnderTest& s, int64_t k, double x, double v) {
  auto m = s.stamped<msg::TravelState>(k);
  m.distance(x), m.speed(v);
  return m;
}

msg::AttitudeEstimate attitude(const ServiceUnderTest& s, int64_t k, double theta, double theta_dot) {
  auto m = s.stamped<msg::AttitudeEstimate>(k);
  m.tilt(theta), m.tilt_rate(theta_dot);
  return m;
}

Eigen::RowVector4d default_gain() {
  const alg::WheeledInvertedPendulum plant{alg::WheeledPendulumParams{}};
  return alg::BalancingController(alg::BalancingControllerParams{}, plant).gain();
}

TEST(BalancingController, StateFeedbackByHand) {
  // T = -K [x - x_ref, v - v_ref, theta, theta'], K placed at poles (-2, -3, -9, -10).
  ServiceUnderTest s(kController);
  EXPECT_EQ(s.message_type("r3/odometry"), "TravelState");
  EXPECT_EQ(s.message_type("r3/attitude"), "AttitudeEstimate");
  EXPECT_EQ(s.message_type("r3/reference"), "TravelState");
  s.deliver("r3/odometry", travel(s, 0, 0.1, 0.0));
  s.step(0);  // no attitude estimate yet: zero torque
  EXPECT_EQ(s.published<msg::WheelTorqueCommand>("r3/cmd").torque(), 0.0);
  s.deliver("r3/attitude", attitude(s, 0, 0.0, 0.0));
  s.deliver("r3/reference", travel(s, 0, 0.1, 0.0));
  s.step(1);  // on the reference, upright: nothing to do
  EXPECT_EQ(s.out("r3/cmd", "torque"), 0.0);
  const Eigen::RowVector4d K = default_gain();
  s.deliver("r3/odometry", travel(s, 2, 0.12, 0.05));
  s.deliver("r3/attitude", attitude(s, 2, 0.01, -0.02));
  s.deliver("r3/reference", travel(s, 2, 0.1, 0.03));
  s.step(2);
  const double expected = -(K(0) * 0.02 + K(1) * 0.02 + K(2) * 0.01 + K(3) * -0.02);
  ASSERT_LT(std::abs(expected), 4.0);  // inside the saturation
  EXPECT_NEAR(s.published<msg::WheelTorqueCommand>("r3/cmd").torque(), expected, 1e-12);
  EXPECT_NE(expected, 0.0);
  // A large tilt saturates at max_torque = 4 N m, with the sign of -K theta.
  s.deliver("r3/attitude", attitude(s, 3, 3.0, 0.0));
  s.step(3);
  ASSERT_GT(std::abs(K(0) * 0.02 + K(1) * 0.02 + K(2) * 3.0), 4.0);
  EXPECT_EQ(std::abs(s.out("r3/cmd", "torque")), 4.0);
  EXPECT_EQ(std::signbit(s.out("r3/cmd", "torque")), std::signbit(-K(2)));
}

TEST(BalancingController, BadSamplesAreRefusedAndLeaveTheTorqueAlone) {
  const Feed feed = [](ServiceUnderTest& s, int64_t k) {
    const double t = 0.01 * static_cast<double>(k);
    ASSERT_EQ(s.deliver("r3/odometry", travel(s, k, 0.3 * t, 0.3)), Rejection::none);
    ASSERT_EQ(s.deliver("r3/attitude", attitude(s, k, 0.02 - t, 0.01)), Rejection::none);
    ASSERT_EQ(s.deliver("r3/reference", travel(s, k, 0.25 * t, 0.25)), Rejection::none);
  };
  expect_refused_without_effect(
      kController, {}, {"r3/cmd"}, 8, 4, feed,
      {
          {"speed NaN", [](ServiceUnderTest& s, int64_t k) { return s.deliver("r3/odometry", travel(s, k, 0, kNaN)); },
           Rejection::non_finite},
          {"tilt 2e6 rad",
           [](ServiceUnderTest& s, int64_t k) { return s.deliver("r3/attitude", attitude(s, k, 2e6, 0)); },
           Rejection::out_of_range},
          {"reference before the epoch",
           [](ServiceUnderTest& s, int64_t) { return s.deliver("r3/reference", travel(s, -2, 5, 5)); },
           Rejection::negative_time},
      });
}

TEST(BalancingController, BadParametersAreConfigurationErrors) {
  expect_config_errors(kController, {
                                        {"services.ctl.poles=[-2, -3, -9]", {"services.ctl.poles", "4 poles"}},
                                        {"services.ctl.poles=[-2, -3, -9, 1]", {"services.ctl", "pole"}},
                                        // Found by fuzzing: a pole that is not a number threw yaml-cpp's
                                        // own exception out of the loader; .nan was taken.
                                        {"services.ctl.poles=[-2, -3, -9, x]",
                                         {"services.ctl.poles", "expected a finite number, got 'x'"}},
                                        {"services.ctl.poles=[-2, -3, -9, .nan]", {"services.ctl.poles", "finite"}},
                                        {"services.ctl.max_torque=0", {"services.ctl", "max_torque"}},
                                        {"services.ctl.gain=1", {"services.ctl.gain", "unknown key"}},
                                    });
}

// --- motion_profile ---------------------------------------------------------------------

const std::string kProfile = R"(name: prof_part
step: 0.01
services:
  profile: {type: motion_profile, robot: r3}
)";

TEST(MotionProfile, HoldRampCruiseByHand) {
  // hold 1 s, raised-cosine ramp of 1.5 s to 0.3 m/s: mid-ramp (t = 1.75 s) v = 0.15 and
  // x = 0.3 * 1.5 * (1/4 - 1/(2 pi)); at t = 3.5 s: x = 0.3 * 1.5 / 2 + 0.3 * 1 = 0.525.
  ServiceUnderTest s(kProfile);
  s.step(50);
  auto m = s.published<msg::TravelState>("r3/reference");
  EXPECT_EQ(m.distance(), 0.0);
  EXPECT_EQ(m.speed(), 0.0);
  s.step(175);
  m = s.published<msg::TravelState>("r3/reference");
  EXPECT_NEAR(m.speed(), 0.15, 1e-12);
  EXPECT_NEAR(m.distance(), 0.45 * (0.25 - 1.0 / (2.0 * std::numbers::pi)), 1e-12);
  s.step(350);
  EXPECT_NEAR(s.out("r3/reference", "v"), 0.3, 1e-12);
  EXPECT_NEAR(s.out("r3/reference", "x"), 0.525, 1e-12);
  EXPECT_EQ(s.check_output("r3/reference"), Rejection::none);
}

TEST(MotionProfile, BadParametersAreConfigurationErrors) {
  expect_config_errors(kProfile, {
                                     {"services.profile.ramp_time=0", {"services.profile", "ramp_time"}},
                                     {"services.profile.hold_time=-1", {"services.profile", "hold_time"}},
                                     {"services.profile.speed=fast", {"services.profile.speed"}},
                                 });
}

}  // namespace
}  // namespace plexus::services_test
