// What a DDS back end needs to know about a generated message type.
//
// One C++ type per message: service code uses the class fastddsgen generates
// from its IDL. Both back ends are generic over it through this record, which
// plexus_idlgen generates for every IDL struct (cmake/PlexusMessages.cmake);
// nothing here is written by hand per message. registry.hpp finds them by name.
#pragma once

#include <nlohmann/json_fwd.hpp>

#include <cstddef>
#include <string_view>
#include <vector>

struct dds_topic_descriptor;  // Cyclone DDS, from the idlc output of the same IDL

namespace eprosima::fastdds::dds {
class TopicDataType;
}

namespace plexus::msg {

class StampHeader;

/// An enum member of a message type: where to_json() puts it, and its enumerators in order.
struct EnumMember {
  const char* json_pointer;  ///< "/state", "/link/state"
  const char* const* names;  ///< names[i]: the enumerator of value i
  std::size_t count;
};

struct TypeSupport {
  /// Scoped IDL name, identical for both vendors ("plexus::msg::Pose2D").
  const char* type_name;
  /// New fastddsgen TopicDataType (serialisation, sizes), its decode checked
  /// (checked_fast_type.hpp); the caller owns it.
  eprosima::fastdds::dds::TopicDataType* (*make_fast_type)();
  /// idlc topic descriptor: type name and keys for Cyclone.
  const dds_topic_descriptor* cyclone_descriptor;
  /// Largest serialised size, including the 4-byte encapsulation header.
  std::size_t max_cdr_size;
  /// Serialises a sample (a T) as XCDR1 with its encapsulation header into buf.
  /// Returns the length, or 0 if it does not fit.
  std::size_t (*serialize)(const void* sample, unsigned char* buf, std::size_t capacity);
  /// Deserialises CDR (with encapsulation header, either endianness) into a T.
  /// False for data that is truncated or otherwise malformed.
  bool (*deserialize)(const unsigned char* buf, std::size_t length, void* sample);

  // For tools that pick the type at run time (plexus topic/record/replay):
  /// A new default-constructed sample (a T); free it with destroy().
  void* (*create)();
  void (*destroy)(void* sample);
  /// The sample's fields as JSON (generated from the IDL member declarations).
  nlohmann::ordered_json (*to_json)(const void* sample);
  /// The sample's StampHeader (every plexus message starts with one), or nullptr for a
  /// type without a `StampHeader header` member.
  StampHeader* (*header)(void* sample);
  /// True for a type with a sequence or string member (LatencyProbe): its CDR size varies.
  bool variable_size;
  /// The self-contained IDL text that defines the type (its file with its includes resolved):
  /// the `omgidl` schema of MCAP recordings and the Foxglove WebSocket.
  const char* schema;
  /// The IDL file it is defined in, as included ("plexus/msg/pose.idl").
  const char* idl_file;
  /// Its enum members (in nested structs too, arrays left out), for output that names
  /// enumerators (`plexus topic echo`); to_json() writes their integer, as the wire does.
  const EnumMember* enum_members = nullptr;
  std::size_t enum_member_count = 0;
};

/// `j` (to_json of a sample of `ts`) with each enum member's integer replaced by its
/// enumerator's name ("state": "SERVICE_RUNNING"); a value out of the enum's range stays a number.
nlohmann::ordered_json with_enum_names(const TypeSupport& ts, nlohmann::ordered_json j);

/// The TypeSupport of a scoped IDL type name ("plexus::msg::Pose2D": exact), or nullptr. Every
/// type of every message package loaded (registry.hpp).
const TypeSupport* find_type_support(std::string_view type_name);
/// Every registered type's TypeSupport, packages in load order, types in IDL file order.
const std::vector<const TypeSupport*>& all_type_supports();

/// Specialised for every message type by the generated messages.cpp.
template <class T>
const TypeSupport& type_support();

}  // namespace plexus::msg
