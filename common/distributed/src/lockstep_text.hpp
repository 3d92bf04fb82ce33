// What the lockstep host and clock say in their errors and logs, one way.
#pragma once

#include <cstdint>
#include <string>

#include "plexus/scenario/format.hpp"

namespace plexus::distributed {

inline int64_t lockstep_ns(double s) { return static_cast<int64_t>(s * 1e9); }
inline std::string lockstep_step(int64_t k) { return "step " + std::to_string(k); }
/// "0.5 s", "30 s": a duration as set, not truncated to whole seconds.
inline std::string lockstep_seconds(double s) { return scenario::format_number(s) + " s"; }

}  // namespace plexus::distributed
