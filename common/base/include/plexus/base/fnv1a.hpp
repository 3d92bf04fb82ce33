#pragma once
// FNV-1a 64 and its printed form: the run digest (plexus/scenario/digest.hpp), the preflight's
// fingerprint and bounded names (bounded_name.hpp) all hash with it.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

namespace plexus {

inline constexpr uint64_t kFnv1aOffset = 0xcbf29ce484222325ULL;

/// FNV-1a 64 of `size` bytes, continuing from `hash`.
inline uint64_t fnv1a64(const void* data, std::size_t size, uint64_t hash = kFnv1aOffset) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) {
    hash ^= p[i];
    hash *= 0x100000001b3ULL;
  }
  return hash;
}

/// 16 lower-case hex digits.
inline std::string hex16(uint64_t value) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(value));
  return buf;
}

}  // namespace plexus
