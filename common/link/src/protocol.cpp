// The messages of bridge protocol version 1 (docs/bridges.md lists the same table). A new
// message is one entry here and one row there; an id is never reused for another meaning.
#include "plexus/link/protocol.hpp"

namespace plexus::link {
namespace {

std::vector<MessageLayout> make_layouts() {
  using D = Direction;
  return {
      // --- unicycle (paper 000)
      {0x10,
       D::to_host,
       "position",
       "PositionMeasurement",
       {"x", "y", "z", "stddev"},
       "measured position (m) and its standard deviation (m)"},
      {0x11,
       D::to_host,
       "truth/state",
       "Pose2D",
       {"x", "y", "theta"},
       "ground truth pose (m, m, rad, continuous) from an external reference"},
      // --- balancing robot (paper 002)
      {0x20,
       D::to_host,
       "imu",
       "Imu",
       {"wx", "wy", "wz", "ax", "ay", "az"},
       "angular velocity (rad/s) and specific force (m/s^2), body axes"},
      {0x21, D::to_host, "odometry", "TravelState", {"x", "v"}, "wheel travel (m) and speed (m/s)"},
      {0x22,
       D::to_host,
       "truth/state",
       "BalancingTruth",
       {"x", "v", "theta", "theta_dot", "x_ddot", "theta_ddot"},
       "ground truth: travel, speed, tilt, tilt rate, acceleration, tilt acceleration"},
      // --- device time (docs/bridges.md "Device time")
      {kTimeResponseId,
       D::to_host,
       "",
       "",
       {"t1", "t2", "t3"},
       "time response: the request's t1 echoed, device clock at its arrival (t2) and at this frame's departure (t3), "
       "s"},
      {kTimeRequestId,
       D::to_device,
       "",
       "",
       {"t1", "reserved1", "reserved2"},
       "time request: host clock at departure (t1, s); reserved fields zero (the request is as long as the response)"},
      // --- commands
      {0x80,
       D::to_device,
       "cmd",
       "UnicycleCommand",
       {"v", "omega"},
       "unicycle command: speed (m/s), turn rate (rad/s)"},
      {0x81, D::to_device, "cmd", "WheelTorqueCommand", {"torque"}, "wheel torque (N m, both wheels together)"},
      {kStopId, D::to_device, "", "", {}, "stop now: zero velocity, zero torque"},
  };
}

}  // namespace

const std::vector<MessageLayout>& message_layouts() {
  static const std::vector<MessageLayout> layouts = make_layouts();
  return layouts;
}

const MessageLayout* find_layout(uint8_t id) {
  for (const auto& l : message_layouts())
    if (l.id == id) return &l;
  return nullptr;
}

const MessageLayout* find_layout(std::string_view topic, std::string_view idl_type, Direction direction) {
  constexpr std::string_view scope = "plexus::msg::";
  if (idl_type.substr(0, scope.size()) == scope) idl_type.remove_prefix(scope.size());
  for (const auto& l : message_layouts())
    if (l.direction == direction && topic == l.topic && idl_type == l.idl_type) return &l;
  return nullptr;
}

}  // namespace plexus::link
