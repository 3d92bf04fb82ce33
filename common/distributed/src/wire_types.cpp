// Every IDL message type a scenario signal travels as, described once: which member each
// signal field fills, and the member's physical range (the subscriber's edge check).
// docs/topics.md lists the same table for users; a new type is one entry here.
//
// Field names are the ones components declare (services/<executable>/*.cpp); a member
// may answer to several names where two components call the same quantity differently
// (HeadingEstimate.direction[0] is paper 000's z3 and paper 003's z2). Joint arrays answer
// to <prefix>1 .. <prefix>16.
//
// Ranges are generous physical bounds (a garbage value is refused, a real one never):
// positions within 1000 km, speeds below 1e4 m/s, counts within their type.
#include <string>

#include "plexus/distributed/wire.hpp"

namespace plexus::distributed {
namespace {

using K = WireSlot::Kind;
using Member = void* (*)(void*);

#define PLEXUS_SCALAR(T, m) [](void* msg_) -> void* { return &static_cast<msg::T*>(msg_)->m(); }
#define PLEXUS_ARRAY(T, m) [](void* msg_) -> void* { return static_cast<msg::T*>(msg_)->m().data(); }
#define PLEXUS_COUNT(T) [](void* msg_) -> uint16_t* { return &static_cast<msg::T*>(msg_)->count(); }

constexpr double kLength = 1e6;    // m
constexpr double kAngle = 1e6;     // rad (continuous headings are not wrapped)
constexpr double kSpeed = 1e4;     // m/s, rad/s
constexpr double kAccel = 1e7;     // m/s^2, rad/s^2
constexpr double kJerk = 1e10;     // rad/s^3
constexpr double kTorque = 1e7;    // N m
constexpr double kTorqueRate = 1e10;  // N m/s
constexpr double kDerived = 1e12;  // path function values and derivatives, observer states

WireSlot f64(std::string field, Member m, double bound, const char* unit, std::size_t index = 0) {
  return {std::move(field), K::f64, m, index, -bound, bound, unit};
}
WireSlot f64_range(std::string field, Member m, double lo, double hi, const char* unit, std::size_t index = 0) {
  return {std::move(field), K::f64, m, index, lo, hi, unit};
}
WireSlot integer(std::string field, K kind, Member m, double lo, double hi) { return {std::move(field), kind, m, 0, lo, hi, ""}; }

/// <prefix>1 .. <prefix>16 on the 16 elements of a joint array.
void joints(std::vector<WireSlot>& out, const std::string& prefix, Member m, double bound, const char* unit) {
  for (std::size_t i = 0; i < 16; ++i) out.push_back(f64(prefix + std::to_string(i + 1), m, bound, unit, i));
}

template <class T>
WireType type(const char* name, std::vector<WireSlot> slots, uint16_t* (*count)(void*) = nullptr) {
  return {name, &msg::type_support<T>(), std::move(slots), count};
}

std::vector<WireType> make_types() {
  using namespace msg;
  std::vector<WireType> t;

  // --- pose.idl
  t.push_back(type<PositionMeasurement>("PositionMeasurement", {
      f64("x", PLEXUS_SCALAR(PositionMeasurement, x), kLength, "m"),
      f64("y", PLEXUS_SCALAR(PositionMeasurement, y), kLength, "m"),
      f64("z", PLEXUS_SCALAR(PositionMeasurement, z), kLength, "m"),
      f64_range("stddev", PLEXUS_SCALAR(PositionMeasurement, stddev), 0, kLength, "m"),
  }));
  t.push_back(type<Pose2D>("Pose2D", {
      f64("x", PLEXUS_SCALAR(Pose2D, x), kLength, "m"),
      f64("y", PLEXUS_SCALAR(Pose2D, y), kLength, "m"),
      f64("theta", PLEXUS_SCALAR(Pose2D, theta), kAngle, "rad"),
  }));
  t.push_back(type<PlanarReference>("PlanarReference", {
      f64("x", PLEXUS_ARRAY(PlanarReference, position), kLength, "m", 0),
      f64("y", PLEXUS_ARRAY(PlanarReference, position), kLength, "m", 1),
      f64("dx", PLEXUS_ARRAY(PlanarReference, velocity), kSpeed, "m/s", 0),
      f64("dy", PLEXUS_ARRAY(PlanarReference, velocity), kSpeed, "m/s", 1),
      f64("ddx", PLEXUS_ARRAY(PlanarReference, acceleration), kAccel, "m/s^2", 0),
      f64("ddy", PLEXUS_ARRAY(PlanarReference, acceleration), kAccel, "m/s^2", 1),
  }));
  t.push_back(type<PathSample>("PathSample", {
      f64("x", PLEXUS_ARRAY(PathSample, position), kLength, "m", 0),
      f64("y", PLEXUS_ARRAY(PathSample, position), kLength, "m", 1),
      f64("h", PLEXUS_SCALAR(PathSample, h), kDerived, ""),
      f64("hx", PLEXUS_ARRAY(PathSample, gradient), kDerived, "", 0),
      f64("hy", PLEXUS_ARRAY(PathSample, gradient), kDerived, "", 1),
      f64("hxx", PLEXUS_ARRAY(PathSample, hessian), kDerived, "", 0),
      f64("hxy", PLEXUS_ARRAY(PathSample, hessian), kDerived, "", 1),
      f64("hyy", PLEXUS_ARRAY(PathSample, hessian), kDerived, "", 2),
  }));
  t.push_back(type<SkidSteerTruth>("SkidSteerTruth", {
      f64("x", PLEXUS_SCALAR(SkidSteerTruth, x), kLength, "m"),
      f64("y", PLEXUS_SCALAR(SkidSteerTruth, y), kLength, "m"),
      f64("theta", PLEXUS_SCALAR(SkidSteerTruth, theta), kAngle, "rad"),
      f64("y_l", PLEXUS_SCALAR(SkidSteerTruth, y_l), kLength, "m"),
      f64("y_r", PLEXUS_SCALAR(SkidSteerTruth, y_r), kLength, "m"),
      f64("x_G", PLEXUS_SCALAR(SkidSteerTruth, x_g), kLength, "m"),
      integer("terrain", K::i32, PLEXUS_SCALAR(SkidSteerTruth, terrain_id), -1, 1e6),
      f64("a_z", PLEXUS_SCALAR(SkidSteerTruth, vertical_acceleration), kAccel, "m/s^2"),
      f64("v_l", PLEXUS_SCALAR(SkidSteerTruth, left), kSpeed, "m/s"),
      f64("v_r", PLEXUS_SCALAR(SkidSteerTruth, right), kSpeed, "m/s"),
  }));

  // --- estimates.idl
  t.push_back(type<HeadingEstimate>("HeadingEstimate", {
      f64("theta", PLEXUS_SCALAR(HeadingEstimate, heading), kAngle, "rad"),
      f64("speed", PLEXUS_SCALAR(HeadingEstimate, speed), kSpeed, "m/s"),
      f64("z3", PLEXUS_ARRAY(HeadingEstimate, direction), kDerived, "", 0),  // paper 000
      f64("z2", PLEXUS_ARRAY(HeadingEstimate, direction), kDerived, "", 0),  // paper 003
      f64("z4", PLEXUS_ARRAY(HeadingEstimate, direction), kDerived, "", 1),
      f64_range("L", PLEXUS_SCALAR(HeadingEstimate, gain), 0, kDerived, "1/s"),
  }));
  t.push_back(type<IcrEstimate>("IcrEstimate", {
      f64("x", PLEXUS_SCALAR(IcrEstimate, x), kLength, "m"),
      f64("y", PLEXUS_SCALAR(IcrEstimate, y), kLength, "m"),
      f64("theta", PLEXUS_SCALAR(IcrEstimate, theta), kAngle, "rad"),
      f64("y_l", PLEXUS_SCALAR(IcrEstimate, y_l), kLength, "m"),
      f64("y_r", PLEXUS_SCALAR(IcrEstimate, y_r), kLength, "m"),
      f64("x_G", PLEXUS_SCALAR(IcrEstimate, x_g), kLength, "m"),
      f64_range("sd_x", PLEXUS_ARRAY(IcrEstimate, stddev), 0, kLength, "m", 0),
      f64_range("sd_y", PLEXUS_ARRAY(IcrEstimate, stddev), 0, kLength, "m", 1),
      f64_range("sd_theta", PLEXUS_ARRAY(IcrEstimate, stddev), 0, kAngle, "rad", 2),
      f64_range("sd_y_l", PLEXUS_ARRAY(IcrEstimate, stddev), 0, kLength, "m", 3),
      f64_range("sd_y_r", PLEXUS_ARRAY(IcrEstimate, stddev), 0, kLength, "m", 4),
      f64_range("sd_x_G", PLEXUS_ARRAY(IcrEstimate, stddev), 0, kLength, "m", 5),
      integer("resets", K::u32, PLEXUS_SCALAR(IcrEstimate, resets), 0, 4294967295.0),
  }));
  t.push_back(type<TerrainClass>("TerrainClass", {
      integer("class", K::i32, PLEXUS_SCALAR(TerrainClass, terrain_id), -1, 1e6),
      f64_range("confidence", PLEXUS_SCALAR(TerrainClass, confidence), 0, 1, ""),
      integer("windows", K::u32, PLEXUS_SCALAR(TerrainClass, windows), 0, 4294967295.0),
      integer("votes", K::u16, PLEXUS_SCALAR(TerrainClass, votes), 0, 65535),
  }));
  t.push_back(type<AttitudeEstimate>("AttitudeEstimate", {
      f64("theta", PLEXUS_SCALAR(AttitudeEstimate, tilt), kAngle, "rad"),
      f64("theta_dot", PLEXUS_SCALAR(AttitudeEstimate, tilt_rate), kSpeed, "rad/s"),
      f64("drift", PLEXUS_SCALAR(AttitudeEstimate, gyro_drift), kSpeed, "rad/s"),
      f64_range("theta_std", PLEXUS_ARRAY(AttitudeEstimate, stddev), 0, kAngle, "rad", 0),
      f64_range("theta_dot_std", PLEXUS_ARRAY(AttitudeEstimate, stddev), 0, kSpeed, "rad/s", 1),
      f64_range("drift_std", PLEXUS_ARRAY(AttitudeEstimate, stddev), 0, kSpeed, "rad/s", 2),
  }));
  {
    std::vector<WireSlot> s;
    joints(s, "q", PLEXUS_ARRAY(LinkJointState, position), kAngle, "rad");
    joints(s, "dq", PLEXUS_ARRAY(LinkJointState, velocity), kSpeed, "rad/s");
    joints(s, "ddq", PLEXUS_ARRAY(LinkJointState, acceleration), kAccel, "rad/s^2");
    joints(s, "dddq", PLEXUS_ARRAY(LinkJointState, jerk), kJerk, "rad/s^3");
    joints(s, "tau", PLEXUS_ARRAY(LinkJointState, torque), kTorque, "N m");
    joints(s, "dtau", PLEXUS_ARRAY(LinkJointState, torque_rate), kTorqueRate, "N m/s");
    joints(s, "phi", PLEXUS_ARRAY(LinkJointState, motor_position), kAngle, "rad");
    joints(s, "dphi", PLEXUS_ARRAY(LinkJointState, motor_velocity), kSpeed, "rad/s");
    t.push_back(type<LinkJointState>("LinkJointState", std::move(s), PLEXUS_COUNT(LinkJointState)));
  }

  // --- imu.idl
  t.push_back(type<Imu>("Imu", {
      f64("wx", PLEXUS_ARRAY(Imu, angular_velocity), kSpeed, "rad/s", 0),
      f64("wy", PLEXUS_ARRAY(Imu, angular_velocity), kSpeed, "rad/s", 1),
      f64("gyro", PLEXUS_ARRAY(Imu, angular_velocity), kSpeed, "rad/s", 1),  // balancing: about the wheel axis
      f64("wz", PLEXUS_ARRAY(Imu, angular_velocity), kSpeed, "rad/s", 2),
      f64("ax", PLEXUS_ARRAY(Imu, linear_acceleration), kAccel, "m/s^2", 0),
      f64("acc_x", PLEXUS_ARRAY(Imu, linear_acceleration), kAccel, "m/s^2", 0),
      f64("ay", PLEXUS_ARRAY(Imu, linear_acceleration), kAccel, "m/s^2", 1),
      f64("az", PLEXUS_ARRAY(Imu, linear_acceleration), kAccel, "m/s^2", 2),
      f64("acc_z", PLEXUS_ARRAY(Imu, linear_acceleration), kAccel, "m/s^2", 2),
      f64("a_z", PLEXUS_ARRAY(Imu, linear_acceleration), kAccel, "m/s^2", 2),  // skid-steer vibration
  }));
  t.push_back(type<BalancingTruth>("BalancingTruth", {
      f64("x", PLEXUS_SCALAR(BalancingTruth, distance), kLength, "m"),
      f64("v", PLEXUS_SCALAR(BalancingTruth, speed), kSpeed, "m/s"),
      f64("theta", PLEXUS_SCALAR(BalancingTruth, tilt), kAngle, "rad"),
      f64("theta_dot", PLEXUS_SCALAR(BalancingTruth, tilt_rate), kSpeed, "rad/s"),
      f64("x_ddot", PLEXUS_SCALAR(BalancingTruth, acceleration), kAccel, "m/s^2"),
      f64("theta_ddot", PLEXUS_SCALAR(BalancingTruth, tilt_acceleration), kAccel, "rad/s^2"),
  }));

  // --- wheel.idl
  t.push_back(type<UnicycleCommand>("UnicycleCommand", {
      f64("v", PLEXUS_SCALAR(UnicycleCommand, v), kSpeed, "m/s"),
      f64("omega", PLEXUS_SCALAR(UnicycleCommand, omega), kSpeed, "rad/s"),
  }));
  t.push_back(type<TrackSpeeds>("TrackSpeeds", {
      f64("v_l", PLEXUS_SCALAR(TrackSpeeds, left), kSpeed, "m/s"),
      f64("v_r", PLEXUS_SCALAR(TrackSpeeds, right), kSpeed, "m/s"),
  }));
  t.push_back(type<TrackCommand>("TrackCommand", {
      f64("v_l", PLEXUS_SCALAR(TrackCommand, left), kSpeed, "m/s"),
      f64("v_r", PLEXUS_SCALAR(TrackCommand, right), kSpeed, "m/s"),
  }));
  t.push_back(type<WheelTorqueCommand>("WheelTorqueCommand", {
      f64("torque", PLEXUS_SCALAR(WheelTorqueCommand, torque), kTorque, "N m"),
  }));
  t.push_back(type<TravelState>("TravelState", {
      f64("x", PLEXUS_SCALAR(TravelState, distance), kLength, "m"),
      f64("v", PLEXUS_SCALAR(TravelState, speed), kSpeed, "m/s"),
  }));

  // --- joint.idl
  {
    std::vector<WireSlot> s;
    joints(s, "phi", PLEXUS_ARRAY(JointState, position), kAngle, "rad");
    joints(s, "dphi", PLEXUS_ARRAY(JointState, velocity), kSpeed, "rad/s");
    joints(s, "tau", PLEXUS_ARRAY(JointState, effort), kTorque, "N m");
    t.push_back(type<JointState>("JointState", std::move(s), PLEXUS_COUNT(JointState)));
  }
  {
    std::vector<WireSlot> s;
    joints(s, "u", PLEXUS_ARRAY(JointCommand, effort), kTorque, "N m");
    t.push_back(type<JointCommand>("JointCommand", std::move(s), PLEXUS_COUNT(JointCommand)));
  }
  {
    std::vector<WireSlot> s;
    joints(s, "q", PLEXUS_ARRAY(JointReference, position), kAngle, "rad");
    joints(s, "dq", PLEXUS_ARRAY(JointReference, velocity), kSpeed, "rad/s");
    joints(s, "ddq", PLEXUS_ARRAY(JointReference, acceleration), kAccel, "rad/s^2");
    joints(s, "dddq", PLEXUS_ARRAY(JointReference, jerk), kJerk, "rad/s^3");
    t.push_back(type<JointReference>("JointReference", std::move(s), PLEXUS_COUNT(JointReference)));
  }
  {
    std::vector<WireSlot> s;
    joints(s, "q", PLEXUS_ARRAY(FlexibleJointTruth, link_position), kAngle, "rad");
    joints(s, "dq", PLEXUS_ARRAY(FlexibleJointTruth, link_velocity), kSpeed, "rad/s");
    joints(s, "phi", PLEXUS_ARRAY(FlexibleJointTruth, motor_position), kAngle, "rad");
    joints(s, "dphi", PLEXUS_ARRAY(FlexibleJointTruth, motor_velocity), kSpeed, "rad/s");
    joints(s, "tau", PLEXUS_ARRAY(FlexibleJointTruth, torque), kTorque, "N m");
    t.push_back(type<FlexibleJointTruth>("FlexibleJointTruth", std::move(s), PLEXUS_COUNT(FlexibleJointTruth)));
  }
  return t;
}

#undef PLEXUS_SCALAR
#undef PLEXUS_ARRAY
#undef PLEXUS_COUNT

}  // namespace

const std::vector<WireType>& wire_types() {
  static const std::vector<WireType> types = make_types();
  return types;
}

}  // namespace plexus::distributed
