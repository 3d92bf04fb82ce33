// The bridge protocol's messages (docs/bridges.md "Messages"): each frame id names one
// typed topic of docs/topics.md and the fields its payload carries, in the order listed,
// each with its wire type (the built-in table: little-endian IEEE-754 f64 throughout; a
// robot's own table may use f32 and scaled integers). A field is named as the topic's signal field
// (wire_types.cpp), so the DDS side converts a payload into its IDL message through the
// same table as every other signal.
//
// Device -> host frames carry sensor samples (and, when the device has it, ground truth
// from an external reference such as motion capture); host -> device frames carry the
// command and the explicit stop.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace plexus::link {

enum class Direction : uint8_t { to_host, to_device };

/// How one field travels: little-endian, IEEE-754 for f32/f64, two's complement for the
/// signed integers. An integer field carries round(value / scale): the SI value is raw * scale.
enum class WireKind : uint8_t { f64, f32, i8, u8, i16, u16, i32, u32 };
std::size_t wire_size(WireKind k);
const char* to_string(WireKind k);
/// "f64", "f32", "i8", "u8", "i16", "u16", "i32", "u32"; false for anything else.
bool parse_wire_kind(std::string_view text, WireKind& k);
inline bool is_integer(WireKind k) { return k != WireKind::f64 && k != WireKind::f32; }

/// Fields in one frame at most: a signal's (scenario::kMaxSignalFields is 136), and each
/// field is at least a byte of kMaxPayload.
inline constexpr std::size_t kMaxFields = 128;

struct WireField {
  std::string name;               ///< the signal field (the IDL member's field name: "x", "q3")
  WireKind kind = WireKind::f64;  ///< on the wire
  double scale = 1.0;             ///< integers: SI value = raw * scale, > 0
};

struct MessageLayout {
  uint8_t id = 0;
  Direction direction = Direction::to_host;
  std::string topic;              ///< `<robot>/<topic>` suffix: "position", "truth/state", "cmd"
  std::string idl_type;           ///< short IDL type name: "PositionMeasurement"
  std::vector<WireField> fields;  ///< payload, in this order
  std::string meaning;            ///< one line for docs and errors
  std::size_t payload_size() const;
  /// The fields' SI values from `payload` (payload_size() bytes) into values[0 .. fields).
  void decode(const uint8_t* payload, double* values) const;
  /// values[0 .. fields) into `payload`; an integer is rounded to its nearest step and held
  /// at its type's limits (a non-finite value becomes 0). Returns the bytes written.
  std::size_t encode(const double* values, uint8_t* payload) const;
};
/// The built-in table's joint arrays (the arm's frames): a field named with `#` stands for
/// one field per joint, `#` = 1 .. n in that order ("phi#": phi1 .. phin), n the arm's joints.
/// A robot's frames are sized for its arm before use (for_joints(), bridge::robot_frames).
inline constexpr std::size_t kMaxJoints = 16;
/// Whether a layout has per-joint fields.
bool per_joint(const MessageLayout& l);
/// The layout for an arm of n joints (1 .. kMaxJoints): each `#` field becomes n fields.
MessageLayout for_joints(const MessageLayout& l, std::size_t n);
/// How many joints a signal's fields carry for a per-joint layout: the longest run 1, 2, ...
/// of its first `#` field among `fields` ("phi1", "phi2": 2); 0 if none.
std::size_t joints_in(const MessageLayout& l, const std::vector<std::string>& fields);

/// A device's frames: the built-in table of protocol version 1, or a robot's own
/// (`source.frames`, docs/bridges.md, "A device's own frames").
using FrameTable = std::vector<MessageLayout>;

/// Host -> device: stop now (zero velocity, zero torque), no payload. The bridge sends it
/// instead of a command that is older than its deadline, once per command period while no
/// fresh command arrives.
inline constexpr uint8_t kStopId = 0x8F;

/// Device time (docs/bridges.md, "Device time"): the two-way exchange that maps the
/// device's clock to the host's. Host -> device: `t1` (the host's send time, s, echoed back)
/// and two reserved f64 (zero), so that the request is as long as the response and their
/// times on the wire are equal. Device -> host: `t1` echoed, `t2` (the device's clock when
/// the request arrived) and `t3` (when the response left), both s. No topic.
inline constexpr uint8_t kTimeRequestId = 0x8E;
inline constexpr uint8_t kTimeResponseId = 0x0E;

/// Cycle sync (docs/bridges.md, "Cycle sync"), with device time: host -> device, the run's
/// steps in the device's clock: `origin` (s, device clock) is when the run's step `step` (an
/// integer, as an f64; negative before the run's start) falls, and `period` (s, device clock)
/// the step's length. A device that follows it runs its steps at origin + n period and
/// numbers them as the run does, so that its samples are taken where and when the run's
/// plant steps fall, as a fieldbus's distributed clock does. No reply; a device that cannot
/// follow ignores it. Three f64, as the time exchange's frames.
inline constexpr uint8_t kCycleId = 0x8D;
inline constexpr std::size_t kCyclePayload = 24;

/// Whether an id belongs to the link itself (STOP, the time exchange, the cycle): never a table's.
inline bool is_link_id(uint8_t id) {
  return id == kStopId || id == kTimeRequestId || id == kTimeResponseId || id == kCycleId;
}

/// Every message of protocol version kProtocolVersion, by id: the default table.
const FrameTable& message_layouts();
/// By id; nullptr if the id is not in the table (default: the built-in one).
const MessageLayout* find_layout(uint8_t id);
const MessageLayout* find_layout(const FrameTable& table, uint8_t id);
/// The message carrying a topic of a type in one direction; nullptr if none.
const MessageLayout* find_layout(std::string_view topic, std::string_view idl_type, Direction direction);
const MessageLayout* find_layout(const FrameTable& table, std::string_view topic, std::string_view idl_type,
                                 Direction direction);

}  // namespace plexus::link
