#pragma once
// A name cut to a length limit without losing its uniqueness: the first bytes, then "~" and
// the 16 hex digits of a 64-bit FNV-1a hash of the whole name. Names within the limit are
// returned unchanged. Used where a name derived from a list (a process hosting 20 robots'
// components, say) meets a limit of the platform: DDS discovery strings (Fast DDS 2.9 drops a
// participant announcement whose name exceeds 251 bytes; docs/runtime.md, Known limits) and
// file names (255 bytes on Linux). Deterministic, so every process derives the same name.
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

namespace plexus {

inline std::string bounded_name(std::string_view name, std::size_t max_bytes) {
  if (name.size() <= max_bytes) return std::string(name);
  uint64_t h = 14695981039346656037ull;  // FNV-1a, 64 bits
  for (const char c : name) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ull;
  }
  char tail[18];
  std::snprintf(tail, sizeof tail, "~%016llx", static_cast<unsigned long long>(h));
  const std::size_t keep = max_bytes > 17 ? max_bytes - 17 : 0;
  return std::string(name.substr(0, keep)) + std::string(tail).substr(0, max_bytes - keep);
}

}  // namespace plexus
