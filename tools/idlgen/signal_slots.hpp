// The signal fields of a message type (docs/sdk.md, "Messages"): each numeric member, or each
// element of a one-dimensional numeric array, is a slot with one or more field names, a unit
// and an accepted range. Scenario components read and write these fields by name; typed ports
// use the first name of each slot, in member order.
#pragma once

#include <string>
#include <vector>

#include "idl_model.hpp"

namespace plexus::idlgen {

struct Slot {
  std::string field;     ///< the field name
  bool primary = false;  ///< the first name of its element (the others are aliases)
  const Member* member = nullptr;
  std::size_t index = 0;  ///< element of an array member (0 for a scalar)
  bool array = false;
  double min = 0, max = 0;   ///< accepted range (the type's limits, or +-inf for floating point)
  std::string kind;          ///< f64, f32, i8, u8, i16, u16, i32, u32, i64, u64, boolean
  std::string path() const;  ///< "position[0]" or "x"
};

/// True for a member that carries signal fields (numbers, scalar or one-dimensional array).
bool is_signal_member(const Member& m);
/// The slots of `s`, in member order, aliases right after their primary name.
std::vector<Slot> signal_slots(const Struct& s);
/// The member marked [count], or nullptr.
const Member* count_member(const Struct& s);
/// The C++ scalar type of a primitive ("double", "uint16_t").
const char* cpp_type(Primitive p);
/// The slot kind of a primitive.
const char* slot_kind(Primitive p);

}  // namespace plexus::idlgen
