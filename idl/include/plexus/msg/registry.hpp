// The message types a process knows: every package's generated code registers its types here
// when its library is loaded (plexus_msgs, a user's package, a plugin), so every tool finds a
// type by name (`plexus topic echo`, record, replay, launch, the edge check).
//
// Each type is described by its TypeSupport (both vendors' code) and its WireType: the
// signal fields its members carry, with their kinds, units and accepted ranges, all generated
// from the IDL (`@unit`, `@range` and the `[fields: ...]` comment tags; docs/sdk.md).
#pragma once

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "plexus/msg/type_support.hpp"

namespace plexus::msg {

/// The message member one signal field occupies.
struct WireSlot {
  enum class Kind : uint8_t { f64, f32, i8, u8, i16, u16, i32, u32, i64, u64, boolean };
  std::string field;  ///< the field name components use ("x", "q3")
  Kind kind = Kind::f64;
  void* (*member)(void* message) = nullptr;  ///< the member's address (an array's first element)
  std::size_t index = 0;                     ///< element within an array member
  double min = 0.0, max = 0.0;               ///< accepted range, inclusive (the edge check)
  const char* unit = "";                     ///< @unit, for docs and errors
  bool primary = true;                       ///< the first name of its element (typed ports' layout)
  const char* path = "";                     ///< the member it fills ("position[0]")
};

/// One IDL message type as signals see it.
struct WireType {
  const char* name = "";  ///< short IDL name ("Pose2D")
  const TypeSupport* support = nullptr;
  std::vector<WireSlot> slots;  ///< member order; aliases right after their primary name
  /// Types with a [count] member (joint arrays): the number of valid array entries.
  uint16_t* (*count)(void* message) = nullptr;
};

/// Reads a slot of `message` as a double.
double read_slot(const WireSlot& slot, void* message);
/// Writes `v` into a slot of `message`, converted to the member's type.
void write_slot(const WireSlot& slot, void* message, double v);

/// Registers the types of one package (a static object of its generated code). A second,
/// different type under a registered name aborts the program at load with one line naming both
/// packages (a build error, as two component types of one name are).
struct PackageRegistration {
  PackageRegistration(const char* package, std::initializer_list<const WireType*> types);
};

/// A type by its scoped name ("plexus::msg::Pose2D") or its short name ("Pose2D") when no other
/// registered type has that short name; nullptr if none (names are case-sensitive).
const WireType* find_wire_type(std::string_view name);
/// Every registered type as signals see it, in the order of all_type_supports().
const std::vector<const WireType*>& all_wire_types();
/// The package that registered a type ("plexus_msgs"), or "" for an unknown type.
std::string package_of(std::string_view type_name);

}  // namespace plexus::msg
