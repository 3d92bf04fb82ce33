// A lockstep host's wait that timed out, as the host says it: the one line a service prints
// when its run fails, which `plexus launch` reads back to follow a failed run to its cause
// (a wait on a process that waits on another, ..., on one that stopped answering;
// docs/distributed.md, "Faults"). The message and its parser, in one place.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace plexus::distributed {

struct LockstepWait {
  std::string sample;    ///< the signal whose sample did not come
  std::string producer;  ///< the component that produces it
};

/// "lockstep: no sample of 'S' (produced by 'P') for step K within T s".
std::string lockstep_wait_message(const LockstepWait& wait, int64_t step, double timeout_s);

/// The wait that `line` reports (lockstep_wait_message's text anywhere in it, as after a
/// program's or the launcher's prefix), or nothing.
std::optional<LockstepWait> parse_lockstep_wait(std::string_view line);

}  // namespace plexus::distributed
