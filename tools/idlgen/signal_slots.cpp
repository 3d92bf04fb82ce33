#include "signal_slots.hpp"

#include <limits>

namespace plexus::idlgen {
namespace {

void limits(Primitive p, double& lo, double& hi) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  switch (p) {
    case Primitive::f32:
    case Primitive::f64:
      lo = -inf;
      hi = inf;
      return;
    case Primitive::boolean:
      lo = 0;
      hi = 1;
      return;
    case Primitive::i8:
      lo = -128;
      hi = 127;
      return;
    case Primitive::u8:
      lo = 0;
      hi = 255;
      return;
    case Primitive::i16:
      lo = -32768;
      hi = 32767;
      return;
    case Primitive::u16:
      lo = 0;
      hi = 65535;
      return;
    case Primitive::i32:
      lo = -2147483648.0;
      hi = 2147483647.0;
      return;
    case Primitive::u32:
      lo = 0;
      hi = 4294967295.0;
      return;
    case Primitive::i64:
      lo = -9223372036854775808.0;
      hi = 9223372036854775807.0;
      return;
    case Primitive::u64:
      lo = 0;
      hi = 18446744073709551615.0;
      return;
    default: lo = hi = 0; return;
  }
}

}  // namespace

std::string Slot::path() const { return array ? member->name + "[" + std::to_string(index) + "]" : member->name; }

bool is_signal_member(const Member& m) {
  return m.type.kind == TypeRef::Kind::primitive && m.type.primitive != Primitive::char_ && m.dims.size() <= 1;
}

const Member* count_member(const Struct& s) {
  for (const auto& m : s.members)
    if (m.count) return &m;
  return nullptr;
}

const char* cpp_type(Primitive p) {
  switch (p) {
    case Primitive::boolean: return "bool";
    case Primitive::octet:
    case Primitive::u8: return "uint8_t";
    case Primitive::char_: return "char";
    case Primitive::i8: return "int8_t";
    case Primitive::i16: return "int16_t";
    case Primitive::u16: return "uint16_t";
    case Primitive::i32: return "int32_t";
    case Primitive::u32: return "uint32_t";
    case Primitive::i64: return "int64_t";
    case Primitive::u64: return "uint64_t";
    case Primitive::f32: return "float";
    case Primitive::f64: return "double";
    case Primitive::none: break;
  }
  return "void";
}

const char* slot_kind(Primitive p) {
  switch (p) {
    case Primitive::boolean: return "boolean";
    case Primitive::octet:
    case Primitive::u8: return "u8";
    case Primitive::i8: return "i8";
    case Primitive::i16: return "i16";
    case Primitive::u16: return "u16";
    case Primitive::i32: return "i32";
    case Primitive::u32: return "u32";
    case Primitive::i64: return "i64";
    case Primitive::u64: return "u64";
    case Primitive::f32: return "f32";
    case Primitive::f64: return "f64";
    default: break;
  }
  return "";
}

std::vector<Slot> signal_slots(const Struct& s) {
  std::vector<Slot> out;
  for (const auto& m : s.members) {
    if (!is_signal_member(m)) continue;
    const std::size_t n = m.dims.empty() ? 1 : m.dims[0];
    double lo = 0, hi = 0;
    limits(m.type.primitive, lo, hi);
    if (m.range_min) lo = *m.range_min;
    if (m.range_max) hi = *m.range_max;
    for (std::size_t i = 0; i < n; ++i) {
      FieldNames names;
      if (m.fields.empty()) {
        names.push_back(m.dims.empty() ? m.name : m.name + "[" + std::to_string(i) + "]");
      } else {
        // One entry per element, or one entry with '#' standing for the 1-based index.
        const FieldNames& given = m.fields.size() == 1 && n > 1 ? m.fields[0] : m.fields[i];
        for (std::string name : given) {
          if (const auto hash = name.find('#'); hash != std::string::npos) name.replace(hash, 1, std::to_string(i + 1));
          names.push_back(name);
        }
      }
      for (std::size_t a = 0; a < names.size(); ++a) {
        Slot sl;
        sl.field = names[a];
        sl.primary = a == 0;
        sl.member = &m;
        sl.index = i;
        sl.array = !m.dims.empty();
        sl.min = lo;
        sl.max = hi;
        sl.kind = slot_kind(m.type.primitive);
        out.push_back(sl);
      }
    }
  }
  return out;
}

}  // namespace plexus::idlgen
