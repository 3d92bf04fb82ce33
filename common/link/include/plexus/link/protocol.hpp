// The bridge protocol's messages (docs/bridges.md "Messages"): each frame id names one
// typed topic of docs/topics.md and the fields its payload carries, each a little-endian
// IEEE-754 f64, in the order listed. A field is named as the topic's signal field
// (wire_types.cpp), so the DDS side converts a payload into its IDL message through the
// same table as every other signal.
//
// Device -> host frames carry sensor samples (and, when the device has it, ground truth
// from an external reference such as motion capture); host -> device frames carry the
// command and the explicit stop.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

namespace plexus::link {

enum class Direction : uint8_t { to_host, to_device };

struct MessageLayout {
  uint8_t id = 0;
  Direction direction = Direction::to_host;
  const char* topic = "";           ///< `<robot>/<topic>` suffix: "position", "truth/state", "cmd"
  const char* idl_type = "";        ///< short IDL type name: "PositionMeasurement"
  std::vector<const char*> fields;  ///< payload: one f64 each, in this order
  const char* meaning = "";         ///< one line for docs and errors
  std::size_t payload_size() const { return fields.size() * 8; }
};

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

/// Every message of protocol version kProtocolVersion, by id.
const std::vector<MessageLayout>& message_layouts();
/// By id; nullptr if the id is not in the protocol.
const MessageLayout* find_layout(uint8_t id);
/// The message carrying a topic of a type in one direction; nullptr if none.
const MessageLayout* find_layout(std::string_view topic, std::string_view idl_type, Direction direction);

}  // namespace plexus::link
