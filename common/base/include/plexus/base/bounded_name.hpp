#pragma once
// A name cut to a length limit without losing its uniqueness: the first bytes, then "_" and
// the 16 hex digits of a 64-bit FNV-1a hash of the whole name ("_" keeps a cut topic name
// valid on Cyclone DDS, which takes only letters, digits, "_" and "/"). Names within the limit are
// returned unchanged. Used where a name derived from a list (a process hosting 20 robots'
// components, say) meets a limit of the platform: DDS discovery strings (Fast DDS 2.9 drops a
// participant announcement whose name exceeds 251 bytes; docs/runtime.md, Known limits) and
// file names (255 bytes on Linux). Deterministic, so every process derives the same name.
#include <string>
#include <string_view>

#include "plexus/base/fnv1a.hpp"

namespace plexus {

inline std::string bounded_name(std::string_view name, std::size_t max_bytes) {
  if (name.size() <= max_bytes) return std::string(name);
  const std::string tail = "_" + hex16(fnv1a64(name.data(), name.size()));
  const std::size_t keep = max_bytes > tail.size() ? max_bytes - tail.size() : 0;
  return std::string(name.substr(0, keep)) + tail.substr(0, max_bytes - keep);
}

}  // namespace plexus
