// JSON values of generated message members, for the generated to_json(const T&) of every
// IDL struct (idl/CMakeLists.txt). Numbers stay numbers, fixed arrays become JSON arrays,
// char[N] a string up to the first NUL, enums their integer, nested structs objects.
#pragma once

#include <nlohmann/json.hpp>

#include <array>
#include <cstddef>
#include <string>
#include <type_traits>
#include <vector>

namespace plexus::msg::detail {

template <class T>
nlohmann::ordered_json json_value(const T& v);

template <std::size_t N>
nlohmann::ordered_json json_value(const std::array<char, N>& a) {
  std::size_t n = 0;
  while (n < N && a[n] != '\0') ++n;
  // The bytes come from the wire, and JSON text is UTF-8: dump() threw on anything else, and
  // `plexus topic echo` stopped at the first such sample (found by fuzzing the subscriber
  // edge). An invalid sequence becomes U+FFFD (nlohmann's replace handler).
  const nlohmann::ordered_json raw = std::string(a.data(), n);
  return nlohmann::ordered_json::parse(raw.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace));
}

template <class T, std::size_t N>
nlohmann::ordered_json json_value(const std::array<T, N>& a) {
  nlohmann::ordered_json j = nlohmann::ordered_json::array();
  for (const auto& x : a) j.push_back(json_value(x));
  return j;
}

template <class T>
nlohmann::ordered_json json_value(const std::vector<T>& v) {
  nlohmann::ordered_json j = nlohmann::ordered_json::array();
  for (const auto& x : v) j.push_back(json_value(x));
  return j;
}

template <class T>
nlohmann::ordered_json json_value(const T& v) {
  if constexpr (std::is_enum_v<T>)
    return static_cast<long long>(v);
  else if constexpr (std::is_arithmetic_v<T>)
    return v;
  else
    return to_json(v);  // a nested generated struct (found by ADL in plexus::msg)
}

}  // namespace plexus::msg::detail
