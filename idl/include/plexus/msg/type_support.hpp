// What a DDS back end needs to know about a generated message type.
//
// One C++ type per message: service code uses the class fastddsgen generates
// from idl/. Both back ends are generic over it through this record, which the
// build generates for every IDL struct (see idl/CMakeLists.txt); nothing here is
// written by hand per message.
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
  /// True for a type with a sequence member (LatencyProbe): its CDR size varies.
  bool variable_size;
};

/// The TypeSupport of a scoped IDL type name ("plexus::msg::Pose2D", case-sensitive, exact),
/// or nullptr. Covers every topic type, fixed and variable size.
const TypeSupport* find_type_support(std::string_view type_name);
/// Every topic type's TypeSupport, in IDL file order.
const std::vector<const TypeSupport*>& all_type_supports();

/// Specialised for every message type by the generated messages.cpp.
template <class T>
const TypeSupport& type_support();

}  // namespace plexus::msg
