// A message type as a signal, for typed ports (plexus::scenario::Component::add_input<T> and
// add_output<T>, docs/sdk.md): its fields in member order, and the copy between a message object
// and a signal's values. Specialised for every topic type with numeric members by the generated
// header of its package (plexus_idlgen); a type without one cannot be a typed port.
#pragma once

namespace plexus::msg {

/// Specialisations have:
///   static constexpr std::size_t size;                            the number of fields
///   static constexpr std::array<std::string_view, size> fields;   their names (the first of each slot)
///   static void store(const T&, double* values);                  message -> values
///   static void load(const double* values, T&);                   values -> message
template <class T>
struct SignalLayout;

}  // namespace plexus::msg
