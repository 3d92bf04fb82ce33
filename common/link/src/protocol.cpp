// The messages of bridge protocol version 1 (docs/bridges.md lists the same table), the
// default frame table of every robot, and the wire types a robot's own table may use. A new
// message is one entry here and one row there; an id is never reused for another meaning.
#include "plexus/link/protocol.hpp"

#include <cmath>
#include <cstring>
#include <limits>

#include "plexus/link/frame.hpp"

namespace plexus::link {
namespace {

// The built-in table is written with field names only: f64 each.
struct Entry {
  uint8_t id;
  Direction direction;
  const char* topic;
  const char* idl_type;
  std::vector<const char*> fields;
  const char* meaning;
};

template <class T>
T saturate(double v) {
  if (!std::isfinite(v)) return T{0};
  const double r = std::nearbyint(v);
  if (r <= static_cast<double>(std::numeric_limits<T>::min())) return std::numeric_limits<T>::min();
  if (r >= static_cast<double>(std::numeric_limits<T>::max())) return std::numeric_limits<T>::max();
  return static_cast<T>(r);
}

template <class T>
void put_le(uint8_t* p, T v) {
  using U = std::make_unsigned_t<T>;
  U u;
  std::memcpy(&u, &v, sizeof u);
  for (std::size_t i = 0; i < sizeof u; ++i) p[i] = static_cast<uint8_t>(u >> (8 * i));
}

template <class T>
T get_le(const uint8_t* p) {
  using U = std::make_unsigned_t<T>;
  U u = 0;
  for (std::size_t i = 0; i < sizeof u; ++i) u = static_cast<U>(u | static_cast<U>(U{p[i]} << (8 * i)));
  T v;
  std::memcpy(&v, &u, sizeof v);
  return v;
}

FrameTable make_layouts() {
  using D = Direction;
  const std::vector<Entry> entries = {
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
      // --- skid-steer robot (paper 001)
      {0x30, D::to_host, "gps", "Pose2D", {"x", "y", "theta"}, "GPS position (m) and heading (rad)"},
      {0x31, D::to_host, "wheels", "TrackSpeeds", {"v_l", "v_r"}, "left and right track speeds (m/s)"},
      {0x32,
       D::to_host,
       "truth/state",
       "SkidSteerTruth",
       {"x", "y", "theta", "y_l", "y_r", "x_G", "terrain", "a_z", "v_l", "v_r"},
       "ground truth: pose (m, m, rad), the tracks' and the body's ICR (m), terrain index, body z "
       "acceleration (m/s^2), track speeds (m/s)"},
      // --- flexible-joint arm (paper 004): per joint, `#` is 1 .. n (n the arm's joints, 1..16)
      {0x40,
       D::to_host,
       "joint_states",
       "JointState",
       {"phi#", "dphi#", "tau#"},
       "motor positions (rad), then velocities (rad/s), then joint torques (N m): 3n fields"},
      {0x41,
       D::to_host,
       "truth/state",
       "FlexibleJointTruth",
       {"q#", "dq#", "phi#", "dphi#", "tau#"},
       "ground truth: link positions (rad) and velocities (rad/s), motor positions (rad) and velocities (rad/s), "
       "joint torques (N m): 5n fields"},
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
      {0x82,
       D::to_device,
       "cmd",
       "TrackCommand",
       {"v_l", "v_r"},
       "skid-steer command: left and right track speeds (m/s)"},
      {0x83, D::to_device, "cmd", "JointCommand", {"u#"}, "arm command: motor torque per joint (N m): n fields"},
      {kStopId, D::to_device, "", "", {}, "stop now: zero velocity, zero torque"},
  };
  FrameTable table;
  for (const Entry& e : entries) {
    MessageLayout l{e.id, e.direction, e.topic, e.idl_type, {}, e.meaning};
    for (const char* f : e.fields) l.fields.push_back({f, WireKind::f64, 1.0});
    table.push_back(std::move(l));
  }
  return table;
}

}  // namespace

std::size_t wire_size(WireKind k) {
  switch (k) {
    case WireKind::f64: return 8;
    case WireKind::f32: return 4;
    case WireKind::i8:
    case WireKind::u8: return 1;
    case WireKind::i16:
    case WireKind::u16: return 2;
    case WireKind::i32:
    case WireKind::u32: return 4;
  }
  return 0;
}

const char* to_string(WireKind k) {
  switch (k) {
    case WireKind::f64: return "f64";
    case WireKind::f32: return "f32";
    case WireKind::i8: return "i8";
    case WireKind::u8: return "u8";
    case WireKind::i16: return "i16";
    case WireKind::u16: return "u16";
    case WireKind::i32: return "i32";
    case WireKind::u32: return "u32";
  }
  return "?";
}

bool parse_wire_kind(std::string_view text, WireKind& k) {
  for (WireKind c : {WireKind::f64, WireKind::f32, WireKind::i8, WireKind::u8, WireKind::i16, WireKind::u16,
                     WireKind::i32, WireKind::u32})
    if (text == to_string(c)) {
      k = c;
      return true;
    }
  return false;
}

std::size_t MessageLayout::payload_size() const {
  std::size_t n = 0;
  for (const auto& f : fields) n += wire_size(f.kind);
  return n;
}

void MessageLayout::decode(const uint8_t* p, double* values) const {
  for (std::size_t i = 0; i < fields.size(); ++i) {
    const WireField& f = fields[i];
    double raw = 0.0;
    switch (f.kind) {
      case WireKind::f64: raw = get_f64_le(p); break;
      case WireKind::f32: {
        const uint32_t u = get_le<uint32_t>(p);
        float v;
        std::memcpy(&v, &u, sizeof v);
        raw = v;
        break;
      }
      case WireKind::i8: raw = get_le<int8_t>(p); break;
      case WireKind::u8: raw = get_le<uint8_t>(p); break;
      case WireKind::i16: raw = get_le<int16_t>(p); break;
      case WireKind::u16: raw = get_le<uint16_t>(p); break;
      case WireKind::i32: raw = get_le<int32_t>(p); break;
      case WireKind::u32: raw = get_le<uint32_t>(p); break;
    }
    values[i] = is_integer(f.kind) ? raw * f.scale : raw;
    p += wire_size(f.kind);
  }
}

std::size_t MessageLayout::encode(const double* values, uint8_t* p) const {
  uint8_t* const start = p;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    const WireField& f = fields[i];
    const double v = is_integer(f.kind) ? values[i] / f.scale : values[i];
    switch (f.kind) {
      case WireKind::f64: put_f64_le(p, v); break;
      case WireKind::f32: {
        const float x = static_cast<float>(v);
        uint32_t u;
        std::memcpy(&u, &x, sizeof u);
        put_le<uint32_t>(p, u);
        break;
      }
      case WireKind::i8: put_le<int8_t>(p, saturate<int8_t>(v)); break;
      case WireKind::u8: put_le<uint8_t>(p, saturate<uint8_t>(v)); break;
      case WireKind::i16: put_le<int16_t>(p, saturate<int16_t>(v)); break;
      case WireKind::u16: put_le<uint16_t>(p, saturate<uint16_t>(v)); break;
      case WireKind::i32: put_le<int32_t>(p, saturate<int32_t>(v)); break;
      case WireKind::u32: put_le<uint32_t>(p, saturate<uint32_t>(v)); break;
    }
    p += wire_size(f.kind);
  }
  return static_cast<std::size_t>(p - start);
}

bool per_joint(const MessageLayout& l) {
  for (const auto& f : l.fields)
    if (f.name.find('#') != std::string::npos) return true;
  return false;
}

MessageLayout for_joints(const MessageLayout& l, std::size_t n) {
  MessageLayout out = l;
  out.fields.clear();
  for (const auto& f : l.fields) {
    const std::size_t at = f.name.find('#');
    if (at == std::string::npos) {
      out.fields.push_back(f);
      continue;
    }
    for (std::size_t j = 1; j <= n; ++j) {
      WireField w = f;
      w.name.replace(at, 1, std::to_string(j));
      out.fields.push_back(std::move(w));
    }
  }
  return out;
}

std::size_t joints_in(const MessageLayout& l, const std::vector<std::string>& fields) {
  for (const auto& f : l.fields) {
    const std::size_t at = f.name.find('#');
    if (at == std::string::npos) continue;
    std::size_t n = 0;
    for (;;) {
      std::string name = f.name;
      name.replace(at, 1, std::to_string(n + 1));
      bool found = false;
      for (const auto& s : fields) found = found || s == name;
      if (!found) return n;
      ++n;
    }
  }
  return 0;
}

const FrameTable& message_layouts() {
  static const FrameTable layouts = make_layouts();
  return layouts;
}

const MessageLayout* find_layout(const FrameTable& table, uint8_t id) {
  for (const auto& l : table)
    if (l.id == id) return &l;
  return nullptr;
}

const MessageLayout* find_layout(uint8_t id) { return find_layout(message_layouts(), id); }

const MessageLayout* find_layout(const FrameTable& table, std::string_view topic, std::string_view idl_type,
                                 Direction direction) {
  constexpr std::string_view scope = "plexus::msg::";
  if (idl_type.substr(0, scope.size()) == scope) idl_type.remove_prefix(scope.size());
  for (const auto& l : table)
    if (l.direction == direction && topic == l.topic && idl_type == l.idl_type) return &l;
  return nullptr;
}

const MessageLayout* find_layout(std::string_view topic, std::string_view idl_type, Direction direction) {
  return find_layout(message_layouts(), topic, idl_type, direction);
}

}  // namespace plexus::link
