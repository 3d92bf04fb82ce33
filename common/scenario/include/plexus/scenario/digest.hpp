// The run digest: a hash of the plant-state trajectory that proves two runs identical.
//
// FNV-1a 64 over, for each plant-produced signal in declaration order, for each sample in
// step order, the 8 bytes of the step (int64, little-endian host order) followed by the
// 8 bytes of each field value (IEEE-754 double). Printed as 16 lower-case hex digits.
// The distributed lockstep runner must hash the same bytes in the same order.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "plexus/scenario/signal_log.hpp"

namespace plexus::scenario {

inline constexpr uint64_t kFnv1aOffset = 0xcbf29ce484222325ULL;

/// FNV-1a 64 of `size` bytes, continuing from `hash`.
uint64_t fnv1a64(const void* data, std::size_t size, uint64_t hash = kFnv1aOffset);

/// 16 lower-case hex digits.
std::string hex16(uint64_t value);

/// The digest of a run (see above).
uint64_t run_digest(const RunLog& log);

/// A 64-bit seed derived from a scenario seed and a component name, so that each
/// component has its own random stream and changing one does not move the others.
/// Always below 2^63, so the resolved scenario can state it as a YAML integer.
uint64_t derive_seed(uint64_t scenario_seed, const std::string& name);

}  // namespace plexus::scenario
