// How plexus's topic and type names appear on the wire (docs/ros2.md).
//
//   plexus  the default: a topic as plexus names it ("r1/position"), a type by its scoped IDL
//           name ("plexus::msg::PositionMeasurement").
//   ros2    ROS 2's DDS mapping (rmw_fastrtps, rmw_cyclonedds): topic "rt/r1/position" (the
//           ROS 2 topic /r1/position), type "plexus_msgs::msg::dds_::PositionMeasurement_"
//           (<package>::msg::dds_::<Type>_, the package being the message package that
//           registered the type: plexus_msgs for plexus's own). A ROS 2 node built with the
//           generated plexus_msgs interface package (build/ros2/plexus_msgs) then reads and
//           writes plexus topics with no bridge.
//
// Participant applies it to every endpoint it creates and maps discovered names back, so
// everything above the participant (services, tools, the launcher) keeps plexus's names.
#pragma once

#include <cctype>

#include <string>
#include <string_view>

#include "plexus/msg/type_support.hpp"

namespace plexus::rt {

enum class Naming { plexus, ros2 };

/// "plexus" or "ros2"; anything else throws InputError naming `origin` (the option or
/// file:line it came from).
Naming parse_naming(std::string_view name, std::string_view origin = "--naming");
const char* to_string(Naming n);

/// A character every vendor takes in a topic name: a letter, a digit, '_' or '/' (Cyclone DDS
/// 0.10 refuses any other, dds_topic.c is_valid_name; Fast DDS takes more). A name must also
/// not start with a digit. Participant::wire_names refuses others; health_topic replaces them.
inline bool topic_name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '/'; }

/// What ROS 2 names put in front of a topic on the wire (rmw: ros_topic_prefix).
inline constexpr std::string_view kRos2TopicPrefix = "rt/";

/// A topic's and its type's names on the wire.
struct DdsNames {
  std::string topic;
  std::string type;
};
DdsNames dds_names(Naming naming, const msg::TypeSupport& type, std::string_view topic);

/// Back from the wire (what discovery reports): the plexus topic name, or `dds_topic` as it is
/// when it is not of that naming's form (another naming's endpoint on the same domain).
std::string plexus_topic(Naming naming, std::string_view dds_topic);
/// The registered type's scoped IDL name, or `dds_type` as it is when no registered type has
/// that wire name.
std::string plexus_type(Naming naming, std::string_view dds_type);

}  // namespace plexus::rt
