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

#include "plexus/base/fnv1a.hpp"
#include "plexus/scenario/signal_log.hpp"

namespace plexus::scenario {

using plexus::fnv1a64;  // plexus/base/fnv1a.hpp
using plexus::hex16;
using plexus::kFnv1aOffset;

/// The digest of a run (see above).
uint64_t run_digest(const RunLog& log);

/// A 64-bit seed derived from a scenario seed and a component name, so that each
/// component has its own random stream and changing one does not move the others.
/// Always below 2^63, so the resolved scenario can state it as a YAML integer.
uint64_t derive_seed(uint64_t scenario_seed, const std::string& name);

}  // namespace plexus::scenario
