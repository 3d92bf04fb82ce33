// Text in a message's fixed-size char array (`char service[64]` in IDL: std::array<char, 64>
// in both vendors' generated C++): NUL-terminated, so the longest text is N - 1 characters.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstring>
#include <string>
#include <string_view>

namespace plexus::msg {

/// The text up to its NUL (all N characters when there is none).
template <std::size_t N>
std::string text_of(const std::array<char, N>& a) {
  return std::string(a.data(), strnlen(a.data(), N));
}

/// Writes `text`, cut to N - 1 characters, and NULs after it. Does not allocate.
template <std::size_t N>
void set_text(std::array<char, N>& a, std::string_view text) {
  a.fill('\0');
  std::memcpy(a.data(), text.data(), std::min(text.size(), N - 1));
}

/// Whether `text` fits whole (N - 1 characters at most).
template <std::size_t N>
bool fits(const std::array<char, N>&, std::string_view text) {
  return text.size() < N;
}

}  // namespace plexus::msg
