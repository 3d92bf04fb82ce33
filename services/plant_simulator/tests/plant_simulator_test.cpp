// plant_simulator: the plants (unicycle, skid_steer, flexible_joint_arm,
// wheeled_inverted_pendulum) and the sensors (position_sensor, measurement, pose_sensor,
// track_speed_sensor, imu_z_sensor, balancing_imu, wheel_odometry, joint_encoders).
// Plants: command message in -> edge check -> one step of the dynamics -> truth message out.
// Sensors run with their plant, so in the executable their input is in process; here the
// plant is not hosted and its truth arrives as its IDL message (edge-checked), the sensor
// model runs, and the measurement message goes out.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "plexus/algorithms/arm/flexible_joint_plant.hpp"
#include "plexus/algorithms/balancing/imu_sensor.hpp"
#include "plexus/algorithms/balancing/wheeled_inverted_pendulum.hpp"
#include "plexus/algorithms/core/random.hpp"
#include "plexus/algorithms/skid_steer/skid_steer_plant.hpp"
#include "plexus/algorithms/skid_steer/skid_steer_sensors.hpp"
#include "plexus/algorithms/unicycle/unicycle_plant.hpp"
#include "service_harness.hpp"

namespace plexus::services_test {
namespace {

// The component types of services/plant_simulator/ whose data path this file tests.
const Covers kCovers{"unicycle",        "skid_steer",    "flexible_joint_arm", "wheeled_inverted_pendulum",
                     "position_sensor", "measurement",   "pose_sensor",        "track_speed_sensor",
                     "imu_z_sensor",    "balancing_imu", "wheel_odometry",     "joint_encoders"};

namespace alg = plexus::algorithms;
constexpr double kPi = std::numbers::pi;

// --- unicycle ---------------------------------------------------------------------------

const std::string kUnicycle = R"(name: plant_part
step: 0.01
robots:
  r1:
    plant: {type: unicycle, x0: 1.0, y0: 2.0, theta0: 0.5}
    sensors:
      position: {type: position_sensor, kind: rfid_grid}
      gps: {type: measurement, fields: [x, y], quantum: 0.5, message: PositionMeasurement}
)";

msg::UnicycleCommand unicycle_command(const ServiceUnderTest& s, int64_t k, double v, double omega) {
  auto m = s.stamped<msg::UnicycleCommand>(k);
  m.v(v), m.omega(omega);
  return m;
}

TEST(UnicyclePlant, OneStepByHand) {
  ServiceUnderTest s(kUnicycle, {"r1/plant"});
  EXPECT_EQ(s.remote_inputs(), std::vector<std::string>{"r1/cmd"});
  s.step(0);  // the initial pose
  auto m = s.published<msg::Pose2D>("r1/truth/state");
  EXPECT_EQ(m.x(), 1.0);
  EXPECT_EQ(m.y(), 2.0);
  EXPECT_EQ(m.theta(), 0.5);
  s.step(1);  // no command yet: it stays
  EXPECT_EQ(s.out("r1/truth/state", "x"), 1.0);
  ASSERT_EQ(s.deliver("r1/cmd", unicycle_command(s, 1, 2.0, 0.0)), Rejection::none);
  s.step(2);  // straight at 2 m/s for 0.01 s along theta = 0.5
  m = s.published<msg::Pose2D>("r1/truth/state");
  EXPECT_DOUBLE_EQ(m.x(), 1.0 + 0.02 * std::cos(0.5));
  EXPECT_DOUBLE_EQ(m.y(), 2.0 + 0.02 * std::sin(0.5));
  EXPECT_DOUBLE_EQ(m.theta(), 0.5);
  s.deliver("r1/cmd", unicycle_command(s, 2, 1.0, 3.0));
  s.step(3);  // an arc: the exact step
  const auto e = alg::unicycle_step({1.0 + 0.02 * std::cos(0.5), 2.0 + 0.02 * std::sin(0.5), 0.5}, {1.0, 3.0}, 0.01);
  EXPECT_DOUBLE_EQ(s.out("r1/truth/state", "x"), e.x);
  EXPECT_DOUBLE_EQ(s.out("r1/truth/state", "y"), e.y);
  EXPECT_DOUBLE_EQ(s.out("r1/truth/state", "theta"), 0.53);
}

TEST(UnicyclePlant, BadCommandsAreRefusedAndLeaveTheStateAlone) {
  const Feed feed = [](ServiceUnderTest& s, int64_t k) {
    ASSERT_EQ(s.deliver("r1/cmd", unicycle_command(s, k, 1.0, 0.1 * static_cast<double>(k))), Rejection::none);
  };
  expect_refused_without_effect(
      kUnicycle, {"r1/plant"}, {"r1/truth/state"}, 8, 4, feed,
      {
          {"v NaN", [](ServiceUnderTest& s, int64_t k) { return s.deliver("r1/cmd", unicycle_command(s, k, kNaN, 0)); },
           Rejection::non_finite},
          {"omega -1e5",
           [](ServiceUnderTest& s, int64_t k) { return s.deliver("r1/cmd", unicycle_command(s, k, 0, -1e5)); },
           Rejection::out_of_range},
          {"before the epoch",
           [](ServiceUnderTest& s, int64_t) { return s.deliver("r1/cmd", unicycle_command(s, -1, 5, 5)); },
           Rejection::negative_time},
      });
}

TEST(UnicyclePlant, BadParametersAreConfigurationErrors) {
  expect_config_errors(kUnicycle, {
                                      {"robots.r1.plant.v_noise_std=-1", {"robots.r1.plant.v_noise_std"}},
                                      {"robots.r1.plant.x0=east", {"robots.r1.plant.x0"}},
                                      {"robots.r1.plant.z0=1", {"robots.r1.plant.z0", "unknown key"}},
                                  });
}

// --- position_sensor, measurement (unicycle truth) --------------------------------------

msg::Pose2D pose(const ServiceUnderTest& s, int64_t k, double x, double y, double theta) {
  auto m = s.stamped<msg::Pose2D>(k);
  m.x(x), m.y(y), m.theta(theta);
  return m;
}

TEST(PositionSensor, RfidGridByHand) {
  // Nearest tag of a 0.1 m grid: (0.123, -0.051) -> (0.1, -0.1) (paper 000 6.3.2).
  ServiceUnderTest s(kUnicycle, {"r1/position"});
  EXPECT_EQ(s.message_type("r1/truth/state"), "plexus::msg::Pose2D");  // a typed port: the scoped name
  ASSERT_EQ(s.deliver("r1/truth/state", pose(s, 0, 0.123, -0.051, 0.0)), Rejection::none);
  s.step(0);
  const auto m = s.published<msg::PositionMeasurement>("r1/position");
  EXPECT_DOUBLE_EQ(m.x(), 0.1);
  EXPECT_DOUBLE_EQ(m.y(), -0.1);
  ServiceUnderTest exact(kUnicycle, {"r1/position"}, {"robots.r1.sensors.position.kind=exact"});
  exact.deliver("r1/truth/state", pose(exact, 0, 0.123, -0.051, 0.0));
  exact.step(0);
  EXPECT_EQ(exact.out("r1/position", "x"), 0.123);
}

TEST(Measurement, QuantisesTheFieldsByHand) {
  ServiceUnderTest s(kUnicycle, {"r1/gps"});
  EXPECT_EQ(s.message_type("r1/gps"), "PositionMeasurement");
  s.deliver("r1/truth/state", pose(s, 0, 0.74, -0.26, 3.0));
  s.step(0);
  auto m = s.published<msg::PositionMeasurement>("r1/gps");
  EXPECT_EQ(m.x(), 0.5);
  EXPECT_EQ(m.y(), -0.5);
  s.deliver("r1/truth/state", pose(s, 1, 1.49, 0.2, 3.0));
  s.step(1);
  m = s.published<msg::PositionMeasurement>("r1/gps");
  EXPECT_EQ(m.x(), 1.5);
  EXPECT_EQ(m.y(), 0.0);
}

TEST(UnicycleSensors, BadTruthIsRefusedAndLeavesTheMeasurementAlone) {
  const Feed feed = [](ServiceUnderTest& s, int64_t k) {
    ASSERT_EQ(s.deliver("r1/truth/state", pose(s, k, 0.3 * static_cast<double>(k), 1.0, 0.0)), Rejection::none);
  };
  const std::vector<BadSample> bad{
      {"x NaN", [](ServiceUnderTest& s, int64_t k) { return s.deliver("r1/truth/state", pose(s, k, kNaN, 0, 0)); },
       Rejection::non_finite},
      {"theta 1e7", [](ServiceUnderTest& s, int64_t k) { return s.deliver("r1/truth/state", pose(s, k, 0, 0, 1e7)); },
       Rejection::out_of_range},
  };
  expect_refused_without_effect(kUnicycle, {"r1/position"}, {"r1/position"}, 6, 3, feed, bad);
  expect_refused_without_effect(kUnicycle, {"r1/gps"}, {"r1/gps"}, 6, 3, feed, bad);
}

TEST(UnicycleSensors, BadParametersAreConfigurationErrors) {
  expect_config_errors(
      kUnicycle, {
                     {"robots.r1.sensors.position.kind=laser", {"robots.r1.sensors.position.kind"}},
                     {"robots.r1.sensors.position.kind=gaussian", {"robots.r1.sensors.position.sigma"}},
                     {"robots.r1.sensors.position.grid_spacing=0", {"robots.r1.sensors.position", "grid_spacing"}},
                     {"robots.r1.sensors.gps.quantum=-0.5", {"robots.r1.sensors.gps.quantum"}},
                     {"robots.r1.sensors.gps.fields=[]", {"robots.r1.sensors.gps.fields"}},
                     {"robots.r1.sensors.gps.fields=[x, w]", {"robots.r1.sensors.gps", "w"}},
                 });
}

// --- skid_steer and its sensors ---------------------------------------------------------

const std::string kSkidSteer = R"(name: plant_part
step: 0.01
robots:
  r2:
    plant: {type: skid_steer, seed: 7}
    sensors:
      gps: {type: pose_sensor, position_std: 0.0, heading_std_deg: 0.0}
      wheels: {type: track_speed_sensor, seed: 11, noise_std: 0.1}
      imu: {type: imu_z_sensor, noise_std: 0.0, bias: 0.5}
)";

msg::TrackCommand track_command(const ServiceUnderTest& s, int64_t k, double v_l, double v_r) {
  auto m = s.stamped<msg::TrackCommand>(k);
  m.left(v_l), m.right(v_r);
  return m;
}

TEST(SkidSteerPlant, OneStepOfTheIcrKinematics) {
  // Terrain A (concrete) from 0 s: pose after 0.01 s = icr_pose_step with its ICRs; the
  // vibration a_z as the plant draws it from its seed (7).
  ServiceUnderTest s(kSkidSteer, {"r2/plant"});
  EXPECT_EQ(s.message_type("r2/cmd"), "TrackCommand");
  s.step(0);
  const alg::IcrParams icr = alg::paper_terrains()[0].icr;
  EXPECT_EQ(s.out("r2/truth/state", "y_l"), icr.y_l);
  ASSERT_EQ(s.deliver("r2/cmd", track_command(s, 0, 0.3, 0.5)), Rejection::none);
  s.step(1);
  const alg::Pose2 p = alg::icr_pose_step({0, 0, 0}, alg::icr_body_velocity(icr, {0.3, 0.5}), 0.01);
  const auto m = s.published<msg::SkidSteerTruth>("r2/truth/state");
  EXPECT_DOUBLE_EQ(m.x(), p.x);
  EXPECT_DOUBLE_EQ(m.y(), p.y);
  EXPECT_DOUBLE_EQ(m.theta(), p.theta);
  EXPECT_DOUBLE_EQ(m.theta(), 0.01 * 0.2 / (icr.y_l - icr.y_r));  // omega = (v_r - v_l) / (y_l - y_r)
  EXPECT_EQ(m.terrain_id(), 0);
  EXPECT_EQ(m.left(), 0.3);
  EXPECT_EQ(m.right(), 0.5);
  alg::SkidSteerPlantParams params;
  alg::SkidSteerPlant ref(params);
  alg::Rng rng(7);
  EXPECT_DOUBLE_EQ(m.vertical_acceleration(), ref.step(0.0, {0.3, 0.5}, rng).a_z);
}

TEST(SkidSteerPlant, BadCommandsAreRefusedAndLeaveTheStateAlone) {
  const Feed feed = [](ServiceUnderTest& s, int64_t k) {
    ASSERT_EQ(s.deliver("r2/cmd", track_command(s, k, 0.2, 0.2 + 0.05 * static_cast<double>(k))), Rejection::none);
  };
  expect_refused_without_effect(
      kSkidSteer, {"r2/plant"}, {"r2/truth/state"}, 8, 4, feed,
      {
          {"left NaN", [](ServiceUnderTest& s, int64_t k) { return s.deliver("r2/cmd", track_command(s, k, kNaN, 0)); },
           Rejection::non_finite},
          {"right 2e4 m/s",
           [](ServiceUnderTest& s, int64_t k) { return s.deliver("r2/cmd", track_command(s, k, 0, 2e4)); },
           Rejection::out_of_range},
      });
}

TEST(SkidSteerPlant, BadParametersAreConfigurationErrors) {
  expect_config_errors(kSkidSteer,
                       {
                           {"robots.r2.plant.schedule=[[0, mud]]", {"robots.r2.plant.schedule", "mud"}},
                           {"robots.r2.plant.schedule=[[0]]", {"robots.r2.plant.schedule"}},
                           {"robots.r2.plant.terrains={ice: {y_l: -1, y_r: 1, x_G: 0}}", {"robots.r2.plant", "y_l"}},
                           {"robots.r2.plant.vibration_speed_exponent=-1", {"robots.r2.plant", "speed_exponent"}},
                       });
}

msg::SkidSteerTruth skid_truth(const ServiceUnderTest& s, int64_t k, double x, double y, double theta, double v_l,
                               double v_r, double a_z) {
  auto m = s.stamped<msg::SkidSteerTruth>(k);
  m.x(x), m.y(y), m.theta(theta), m.y_l(0.3), m.y_r(-0.3), m.x_g(0.05), m.terrain_id(1);
  m.vertical_acceleration(a_z), m.left(v_l), m.right(v_r);
  return m;
}

TEST(PoseSensor, WrapsTheHeadingByHand) {
  ServiceUnderTest s(kSkidSteer, {"r2/gps"});
  EXPECT_EQ(s.message_type("r2/truth/state"), "SkidSteerTruth");
  ASSERT_EQ(s.deliver("r2/truth/state", skid_truth(s, 0, 1.5, -2.5, 4.0, 0, 0, 9.81)), Rejection::none);
  s.step(0);
  const auto m = s.published<msg::Pose2D>("r2/gps");
  EXPECT_EQ(m.x(), 1.5);
  EXPECT_EQ(m.y(), -2.5);
  EXPECT_DOUBLE_EQ(m.theta(), 4.0 - 2 * kPi);  // a compass reads (-pi, pi]
  ServiceUnderTest raw(kSkidSteer, {"r2/gps"}, {"robots.r2.sensors.gps.wrap_heading=false"});
  raw.deliver("r2/truth/state", skid_truth(raw, 0, 1.5, -2.5, 4.0, 0, 0, 9.81));
  raw.step(0);
  EXPECT_EQ(raw.out("r2/gps", "theta"), 4.0);
}

TEST(TrackSpeedSensor, NoiseFromItsOwnSeed) {
  ServiceUnderTest s(kSkidSteer, {"r2/wheels"});
  s.deliver("r2/truth/state", skid_truth(s, 0, 0, 0, 0, 0.4, 0.6, 9.81));
  s.step(0);
  alg::Rng rng(11);
  const alg::TrackSpeeds m = alg::TrackSpeedSensor(0.1).measure({0.4, 0.6}, rng);
  const auto out = s.published<msg::TrackSpeeds>("r2/wheels");
  EXPECT_DOUBLE_EQ(out.left(), m.v_l);
  EXPECT_DOUBLE_EQ(out.right(), m.v_r);
  EXPECT_NE(out.left(), 0.4);
  ServiceUnderTest clean(kSkidSteer, {"r2/wheels"}, {"robots.r2.sensors.wheels.noise_std=0"});
  clean.deliver("r2/truth/state", skid_truth(clean, 0, 0, 0, 0, 0.4, 0.6, 9.81));
  clean.step(0);
  EXPECT_EQ(clean.out("r2/wheels", "v_l"), 0.4);
  EXPECT_EQ(clean.out("r2/wheels", "v_r"), 0.6);
}

TEST(ImuZSensor, AddsItsBiasByHand) {
  ServiceUnderTest s(kSkidSteer, {"r2/imu"});
  s.deliver("r2/truth/state", skid_truth(s, 0, 0, 0, 0, 0, 0, 9.7));
  s.step(0);
  const auto m = s.published<msg::Imu>("r2/imu");
  EXPECT_DOUBLE_EQ(m.linear_acceleration()[2], 10.2);
  EXPECT_EQ(m.linear_acceleration()[0], 0.0);
}

TEST(SkidSteerSensors, BadTruthIsRefusedAndLeavesTheMeasurementAlone) {
  const Feed feed = [](ServiceUnderTest& s, int64_t k) {
    const double t = 0.01 * static_cast<double>(k);
    ASSERT_EQ(s.deliver("r2/truth/state", skid_truth(s, k, t, -t, 3.0 + t, 0.3, 0.5, 9.81 + t)), Rejection::none);
  };
  const std::vector<BadSample> bad{
      {"a_z NaN",
       [](ServiceUnderTest& s, int64_t k) {
         return s.deliver("r2/truth/state", skid_truth(s, k, 0, 0, 0, 0, 0, kNaN));
       },
       Rejection::non_finite},
      {"terrain id -2",
       [](ServiceUnderTest& s, int64_t k) {
         auto m = skid_truth(s, k, 0, 0, 0, 0, 0, 9.81);
         m.terrain_id(-2);
         return s.deliver("r2/truth/state", m);
       },
       Rejection::out_of_range},
      {"v_l inf",
       [](ServiceUnderTest& s, int64_t k) {
         return s.deliver("r2/truth/state", skid_truth(s, k, 0, 0, 0, kInf, 0, 9.81));
       },
       Rejection::non_finite},
  };
  for (const char* sensor : {"r2/gps", "r2/wheels", "r2/imu"})
    expect_refused_without_effect(kSkidSteer, {sensor}, {sensor}, 6, 3, feed, bad);
}

TEST(SkidSteerSensors, BadParametersAreConfigurationErrors) {
  expect_config_errors(kSkidSteer,
                       {
                           {"robots.r2.sensors.gps.position_std=-0.01", {"robots.r2.sensors.gps.position_std"}},
                           {"robots.r2.sensors.wheels.noise_std=-1", {"robots.r2.sensors.wheels.noise_std"}},
                           {"robots.r2.sensors.imu.bias=.inf", {"robots.r2.sensors.imu", "bias"}},
                           {"robots.r2.sensors.gps.wrap_heading=sometimes", {"robots.r2.sensors.gps.wrap_heading"}},
                       });
}

// --- flexible_joint_arm and joint_encoders ----------------------------------------------

const std::string kArm = R"(name: plant_part
step: 0.001
robots:
  r4:
    plant: {type: flexible_joint_arm, q0: [0.3, -0.2]}
    sensors:
      joint_states: {type: joint_encoders}
)";

msg::JointCommand joint_command(const ServiceUnderTest& s, int64_t k, double u1, double u2) {
  auto m = s.stamped<msg::JointCommand>(k);
  m.count(2);
  m.effort()[0] = u1, m.effort()[1] = u2;
  return m;
}

TEST(FlexibleJointArm, StartsHeldBySpringsAndStepsLikeThePlant) {
  ServiceUnderTest s(kArm, {"r4/plant"});
  EXPECT_EQ(s.message_type("r4/cmd"), "JointCommand");
  s.step(0);
  // At rest at q0: the springs hold gravity, tau = G(q0), phi = q0 + tau / K.
  alg::ArmRigidBodyDynamics dyn(alg::ArmModel::paper_2dof());
  Eigen::VectorXd q0(2), g(2);
  q0 << 0.3, -0.2;
  dyn.bias(q0, Eigen::VectorXd::Zero(2), g);
  auto m = s.published<msg::FlexibleJointTruth>("r4/truth/state");
  EXPECT_EQ(m.count(), 2);
  for (int i = 0; i < 2; ++i) {
    EXPECT_DOUBLE_EQ(m.link_position()[i], q0(i));
    EXPECT_NEAR(m.torque()[i], g(i), 1e-9);
    EXPECT_NEAR(m.motor_position()[i], q0(i) + g(i) / 1e4, 1e-12);
  }
  alg::FlexibleJointArmPlant ref({alg::ArmModel::paper_2dof(), 1e-4});
  ref.reset_in_motion(q0, Eigen::VectorXd::Zero(2));
  Eigen::VectorXd u(2);
  for (int64_t k = 1; k < 4; ++k) {
    u << 20.0 * static_cast<double>(k), -5.0;
    ASSERT_EQ(s.deliver("r4/cmd", joint_command(s, k - 1, u(0), u(1))), Rejection::none);
    s.step(k);
    ref.step(u, 0.001);
  }
  m = s.published<msg::FlexibleJointTruth>("r4/truth/state");
  for (int i = 0; i < 2; ++i) {
    EXPECT_DOUBLE_EQ(m.link_position()[i], ref.state().q(i)) << i;
    EXPECT_DOUBLE_EQ(m.link_velocity()[i], ref.state().qd(i)) << i;
    EXPECT_DOUBLE_EQ(m.motor_velocity()[i], ref.state().phid(i)) << i;
  }
  EXPECT_GT(m.motor_velocity()[0], 0.0);  // the motor accelerated with u1 > 0
}

TEST(FlexibleJointArm, BadCommandsAreRefusedAndLeaveTheStateAlone) {
  const Feed feed = [](ServiceUnderTest& s, int64_t k) {
    ASSERT_EQ(s.deliver("r4/cmd", joint_command(s, k, 10.0 * static_cast<double>(k), 1.0)), Rejection::none);
  };
  expect_refused_without_effect(
      kArm, {"r4/plant"}, {"r4/truth/state"}, 6, 3, feed,
      {
          {"3 joints",
           [](ServiceUnderTest& s, int64_t k) {
             auto m = joint_command(s, k, 1, 1);
             m.count(3);
             return s.deliver("r4/cmd", m);
           },
           Rejection::wrong_count},
          {"u2 NaN", [](ServiceUnderTest& s, int64_t k) { return s.deliver("r4/cmd", joint_command(s, k, 0, kNaN)); },
           Rejection::non_finite},
          {"u1 -1e8", [](ServiceUnderTest& s, int64_t k) { return s.deliver("r4/cmd", joint_command(s, k, -1e8, 0)); },
           Rejection::out_of_range},
      });
}

msg::FlexibleJointTruth arm_truth(const ServiceUnderTest& s, int64_t k, double phi1, double phi2, double dphi1,
                                  double dphi2) {
  auto m = s.stamped<msg::FlexibleJointTruth>(k);
  m.count(2);
  m.link_position()[0] = phi1 - 0.001, m.link_position()[1] = phi2 - 0.001;
  m.motor_position()[0] = phi1, m.motor_position()[1] = phi2;
  m.motor_velocity()[0] = dphi1, m.motor_velocity()[1] = dphi2;
  m.torque()[0] = 10.0, m.torque()[1] = 10.0;
  return m;
}

TEST(JointEncoders, ReadTheMotorSide) {
  ServiceUnderTest s(kArm, {"r4/joint_states"});
  EXPECT_EQ(s.message_type("r4/truth/state"), "FlexibleJointTruth");
  ASSERT_EQ(s.deliver("r4/truth/state", arm_truth(s, 0, 0.5, -0.25, 1.5, -0.75)), Rejection::none);
  s.step(0);
  const auto m = s.published<msg::JointState>("r4/joint_states");
  EXPECT_EQ(m.count(), 2);
  EXPECT_EQ(m.position()[0], 0.5);
  EXPECT_EQ(m.position()[1], -0.25);
  EXPECT_EQ(m.velocity()[0], 1.5);
  EXPECT_EQ(m.velocity()[1], -0.75);
}

TEST(JointEncoders, BadTruthIsRefusedAndLeavesTheMeasurementAlone) {
  const Feed feed = [](ServiceUnderTest& s, int64_t k) {
    const double t = static_cast<double>(k);
    ASSERT_EQ(s.deliver("r4/truth/state", arm_truth(s, k, 0.1 * t, 0.2, t, -t)), Rejection::none);
  };
  expect_refused_without_effect(
      kArm, {"r4/joint_states"}, {"r4/joint_states"}, 6, 3, feed,
      {
          {"1 joint",
           [](ServiceUnderTest& s, int64_t k) {
             auto m = arm_truth(s, k, 0, 0, 0, 0);
             m.count(1);
             return s.deliver("r4/truth/state", m);
           },
           Rejection::wrong_count},
          {"dphi NaN",
           [](ServiceUnderTest& s, int64_t k) { return s.deliver("r4/truth/state", arm_truth(s, k, 0, 0, kNaN, 0)); },
           Rejection::non_finite},
      });
}

TEST(FlexibleJointArm, BadParametersAreConfigurationErrors) {
  expect_config_errors(kArm, {
                                 {"robots.r4.plant.q0=[1]", {"robots.r4.plant.q0", "2 numbers"}},
                                 {"robots.r4.plant.max_substep=0", {"robots.r4.plant", "max_substep"}},
                                 {"robots.r4.plant.mass=[1, -4]", {"robots.r4.plant", "mass"}},
                                 {"robots.r4.sensors.joint_states.dof=0", {"robots.r4.sensors.joint_states.dof"}},
                                 {"robots.r4.sensors.joint_states.position_noise_std=-1",
                                  {"robots.r4.sensors.joint_states.position_noise_std"}},
                             });
}

// --- wheeled_inverted_pendulum and its sensors ------------------------------------------

const std::string kPendulum = R"(name: plant_part
step: 0.01
robots:
  r3:
    plant: {type: wheeled_inverted_pendulum, theta0_deg: 2.0}
    sensors:
      imu: {type: balancing_imu, gyro_noise_degps: 0, drift_noise_psd: 0, initial_drift_degps: 0, accel_noise: 0}
      odometry: {type: wheel_odometry}
)";

msg::WheelTorqueCommand torque_command(const ServiceUnderTest& s, int64_t k, double torque) {
  auto m = s.stamped<msg::WheelTorqueCommand>(k);
  m.torque(torque);
  return m;
}

TEST(WheeledInvertedPendulum, StepsLikeThePlantAndSaturates) {
  ServiceUnderTest s(kPendulum, {"r3/plant"});
  EXPECT_EQ(s.message_type("r3/cmd"), "WheelTorqueCommand");
  s.step(0);
  const alg::WheeledInvertedPendulum ref{alg::WheeledPendulumParams{}};
  alg::WheeledPendulumState x;
  x.theta = 2.0 * kPi / 180.0;
  auto m = s.published<msg::BalancingTruth>("r3/truth/state");
  EXPECT_DOUBLE_EQ(m.tilt(), x.theta);
  EXPECT_DOUBLE_EQ(m.tilt_acceleration(), ref.accelerations(x, 0.0).theta_ddot);
  EXPECT_GT(m.tilt_acceleration(), 0.0);  // leaning forward, it falls forward
  s.deliver("r3/cmd", torque_command(s, 0, 1.5));
  s.step(1);
  auto acc = ref.step(x, 1.5, 0.01, 4);
  m = s.published<msg::BalancingTruth>("r3/truth/state");
  EXPECT_DOUBLE_EQ(m.distance(), x.x);
  EXPECT_DOUBLE_EQ(m.speed(), x.v);
  EXPECT_DOUBLE_EQ(m.tilt(), x.theta);
  EXPECT_DOUBLE_EQ(m.tilt_rate(), x.theta_dot);
  EXPECT_DOUBLE_EQ(m.acceleration(), acc.x_ddot);
  // 10 N m is beyond max_torque (4): the same step as 4 N m.
  s.deliver("r3/cmd", torque_command(s, 1, 10.0));
  s.step(2);
  acc = ref.step(x, 4.0, 0.01, 4);
  EXPECT_DOUBLE_EQ(s.out("r3/truth/state", "theta"), x.theta);
  EXPECT_DOUBLE_EQ(s.out("r3/truth/state", "x_ddot"), acc.x_ddot);
}

TEST(WheeledInvertedPendulum, BadCommandsAreRefusedAndLeaveTheStateAlone) {
  const Feed feed = [](ServiceUnderTest& s, int64_t k) {
    ASSERT_EQ(s.deliver("r3/cmd", torque_command(s, k, 0.5 - 0.1 * static_cast<double>(k))), Rejection::none);
  };
  expect_refused_without_effect(
      kPendulum, {"r3/plant"}, {"r3/truth/state"}, 8, 4, feed,
      {
          {"torque NaN", [](ServiceUnderTest& s, int64_t k) { return s.deliver("r3/cmd", torque_command(s, k, kNaN)); },
           Rejection::non_finite},
          {"torque 2e7 N m",
           [](ServiceUnderTest& s, int64_t k) { return s.deliver("r3/cmd", torque_command(s, k, 2e7)); },
           Rejection::out_of_range},
      });
}

TEST(WheeledInvertedPendulum, BadParametersAreConfigurationErrors) {
  expect_config_errors(kPendulum, {
                                      {"robots.r3.plant.substeps=0", {"robots.r3.plant.substeps"}},
                                      {"robots.r3.plant.body_mass=-3", {"robots.r3.plant", "body_mass"}},
                                      {"robots.r3.plant.theta0_deg=upright", {"robots.r3.plant.theta0_deg"}},
                                      {"robots.r3.plant.torque_noise_std=-1", {"robots.r3.plant.torque_noise_std"}},
                                  });
}

msg::BalancingTruth balancing_truth(const ServiceUnderTest& s, int64_t k, double x, double v, double theta,
                                    double theta_dot, double x_ddot, double theta_ddot) {
  auto m = s.stamped<msg::BalancingTruth>(k);
  m.distance(x), m.speed(v), m.tilt(theta), m.tilt_rate(theta_dot), m.acceleration(x_ddot),
      m.tilt_acceleration(theta_ddot);
  return m;
}

TEST(BalancingImu, NoiseFreeReadingsByHand) {
  // Upright: gyro = theta' (no drift, no noise); the accelerometer at d = 0.12 m on the body
  // axis reads f_xb = x'' + d theta'' = 0.5 + 0.12 = 0.62 and f_zb = g - d theta'^2
  // = 9.81 - 0.12 * 0.09 (the centripetal part of its circle about the axle).
  ServiceUnderTest s(kPendulum, {"r3/imu"});
  EXPECT_EQ(s.message_type("r3/truth/state"), "BalancingTruth");
  ASSERT_EQ(s.deliver("r3/truth/state", balancing_truth(s, 0, 0, 0, 0, 0.3, 0.5, 1.0)), Rejection::none);
  s.step(0);
  auto m = s.published<msg::Imu>("r3/imu");
  EXPECT_DOUBLE_EQ(m.angular_velocity()[1], 0.3);
  EXPECT_NEAR(m.linear_acceleration()[0], 0.62, 1e-12);
  EXPECT_NEAR(m.linear_acceleration()[2], 9.81 - 0.0108, 1e-12);
  // Tilted and turning: the model's specific force; a tilt rate of 3 rad/s saturates the
  // gyro at 150 deg/s.
  s.deliver("r3/truth/state", balancing_truth(s, 1, 0, 0, 0.2, 3.0, -0.4, 2.0));
  s.step(1);
  double fx = 0, fz = 0;
  alg::WheeledPendulumState st;
  st.theta = 0.2, st.theta_dot = 3.0;
  alg::ImuSensor::specific_force(st, {-0.4, 2.0}, 0.12, 9.81, fx, fz);
  m = s.published<msg::Imu>("r3/imu");
  EXPECT_DOUBLE_EQ(m.angular_velocity()[1], 150.0 * kPi / 180.0);
  EXPECT_NEAR(m.linear_acceleration()[0], fx, 1e-12);
  EXPECT_NEAR(m.linear_acceleration()[2], fz, 1e-12);
}

TEST(WheelOdometry, PassesTravelAndSpeed) {
  ServiceUnderTest s(kPendulum, {"r3/odometry"});
  s.deliver("r3/truth/state", balancing_truth(s, 0, 1.25, -0.5, 0.1, 0, 0, 0));
  s.step(0);
  const auto m = s.published<msg::TravelState>("r3/odometry");
  EXPECT_EQ(m.distance(), 1.25);
  EXPECT_EQ(m.speed(), -0.5);
}

TEST(BalancingSensors, BadTruthIsRefusedAndLeavesTheMeasurementAlone) {
  const Feed feed = [](ServiceUnderTest& s, int64_t k) {
    const double t = 0.01 * static_cast<double>(k);
    ASSERT_EQ(s.deliver("r3/truth/state", balancing_truth(s, k, t, 1.0, 0.05 - t, -0.2, 0.3, -1.0)), Rejection::none);
  };
  const std::vector<BadSample> bad{
      {"tilt NaN",
       [](ServiceUnderTest& s, int64_t k) {
         return s.deliver("r3/truth/state", balancing_truth(s, k, 0, 0, kNaN, 0, 0, 0));
       },
       Rejection::non_finite},
      {"tilt acceleration 1e9",
       [](ServiceUnderTest& s, int64_t k) {
         return s.deliver("r3/truth/state", balancing_truth(s, k, 0, 0, 0, 0, 0, 1e9));
       },
       Rejection::out_of_range},
      {"before the epoch",
       [](ServiceUnderTest& s, int64_t) {
         return s.deliver("r3/truth/state", balancing_truth(s, -4, 0, 0, 0, 0, 0, 0));
       },
       Rejection::negative_time},
  };
  // With noise: its random draws must not be consumed by a refused sample either.
  const std::string noisy = R"(name: plant_part
step: 0.01
robots:
  r3:
    plant: {type: wheeled_inverted_pendulum}
    sensors:
      imu: {type: balancing_imu}
      odometry: {type: wheel_odometry, noise_std: 0.01}
)";
  expect_refused_without_effect(noisy, {"r3/imu"}, {"r3/imu"}, 6, 3, feed, bad);
  expect_refused_without_effect(noisy, {"r3/odometry"}, {"r3/odometry"}, 6, 3, feed, bad);
}

TEST(BalancingSensors, BadParametersAreConfigurationErrors) {
  expect_config_errors(kPendulum,
                       {
                           {"robots.r3.sensors.imu.gyro_range_degps=0", {"robots.r3.sensors.imu.gyro_range_degps"}},
                           {"robots.r3.sensors.imu.gyro_noise_degps=-1", {"robots.r3.sensors.imu.gyro_noise_degps"}},
                           {"robots.r3.sensors.imu.accel_range=0", {"robots.r3.sensors.imu", "range"}},
                           {"robots.r3.sensors.odometry.noise_std=-1", {"robots.r3.sensors.odometry.noise_std"}},
                       });
}

}  // namespace
}  // namespace plexus::services_test
