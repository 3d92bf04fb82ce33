#include "idl_checks.hpp"

#include <algorithm>
#include <cctype>
#include <set>

#include "idl_parser.hpp"
#include "signal_slots.hpp"

namespace plexus::idlgen {
namespace {

std::string lower(std::string s) {
  for (auto& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

void check_type(const TypeRef& t, const Member& m) {
  if (t.kind == TypeRef::Kind::string && t.bound == 0)
    throw IdlError(m.where, "member '" + m.name + "': unbounded string; give a bound (string<32>) or use char[32]");
  if (t.kind == TypeRef::Kind::sequence) {
    if (t.bound == 0)
      throw IdlError(m.where, "member '" + m.name + "': unbounded sequence; give a bound (sequence<T, N>)");
    check_type(t.element.front(), m);
  }
}

void check_struct(const Struct& s, const std::set<std::string>& type_names) {
  if (s.extensibility != "final")
    throw IdlError(s.where, "struct '" + s.name +
                                "' must be @final (plexus interop rule: XCDR1 between Fast DDS and Cyclone DDS" +
                                (s.extensibility.empty() ? ")" : "; it is @" + s.extensibility + ")"));
  if (s.members.empty()) throw IdlError(s.where, "struct '" + s.name + "' has no member");
  std::set<std::string> seen, fields;
  for (const auto& m : s.members) {
    if (m.optional) throw IdlError(m.where, "member '" + m.name + "': @optional is not allowed (plexus interop rule)");
    if (m.key) throw IdlError(m.where, "member '" + m.name + "': @key is not allowed (plexus topics are keyless)");
    if (type_names.count(lower(m.name)))
      throw IdlError(m.where,
                     "member '" + m.name + "' is named like a type (IDL names are case-insensitive); rename it");
    if (!seen.insert(lower(m.name)).second)
      throw IdlError(m.where, "member '" + m.name + "' repeats a member name of '" + s.name + "' (ignoring case)");
    check_type(m.type, m);
    if (m.dims.size() > 1 && (m.unit || m.range_min || !m.fields.empty()))
      throw IdlError(m.where,
                     "member '" + m.name + "': @unit, @range and [fields] need a scalar or a one-dimensional array");
    const bool numeric = is_signal_member(m);
    if ((m.unit || m.range_min) && !numeric)
      throw IdlError(m.where, "member '" + m.name + "': @unit and @range apply to numbers only");
    const bool floating = m.type.primitive == Primitive::f32 || m.type.primitive == Primitive::f64;
    if (m.range_min && !floating && !m.range_integral)
      throw IdlError(m.where,
                     "member '" + m.name + "': @range of an integer member takes whole numbers (1000000, not 1e6)");
    if (m.range_min && *m.range_min > *m.range_max)
      throw IdlError(m.where, "member '" + m.name + "': @range min " + std::to_string(*m.range_min) + " is above max " +
                                  std::to_string(*m.range_max));
    if (!m.fields.empty()) {
      if (!numeric) throw IdlError(m.where, "member '" + m.name + "': [fields: ...] applies to numbers only");
      const std::size_t n = m.dims.empty() ? 1 : m.dims[0];
      const bool pattern = m.fields.size() == 1 && n > 1;
      if (pattern) {
        for (const auto& name : m.fields[0])
          if (name.find('#') == std::string::npos)
            throw IdlError(m.where, "member '" + m.name + "': [fields: " + name + "] for " + std::to_string(n) +
                                        " elements needs one name per element, or '#' for the element's 1-based index");
      } else if (m.fields.size() != n) {
        throw IdlError(m.where, "member '" + m.name + "': [fields: ...] names " + std::to_string(m.fields.size()) +
                                    " elements, the member has " + std::to_string(n));
      }
    }
    if (m.count && (m.type.kind != TypeRef::Kind::primitive || !m.dims.empty() || m.type.primitive != Primitive::u16))
      throw IdlError(m.where, "member '" + m.name + "': [count] marks an unsigned short scalar");
  }
  for (const auto& sl : signal_slots(s))
    if (!fields.insert(sl.field).second)
      throw IdlError(sl.member->where, "field name '" + sl.field + "' is used twice in '" + s.name + "'");
  if (count_member(s) &&
      std::none_of(s.members.begin(), s.members.end(), [](const Member& m) { return m.dims.size() == 1; }))
    throw IdlError(count_member(s)->where, "[count] in a struct without arrays");
}

}  // namespace

void check_model(const Model& model) {
  std::set<std::string> type_names;
  for (const auto& f : model.files) {
    for (const auto& s : f.structs) type_names.insert(lower(s.name));
    for (const auto& e : f.enums) type_names.insert(lower(e.name));
  }
  for (const auto& f : model.files) {
    if (!f.own) continue;
    for (const auto& s : f.structs) check_struct(s, type_names);
  }
}

}  // namespace plexus::idlgen
