// Why a lockstep run failed, followed to the process it stopped on. The clock's timeout
// names the sample it waited for; when that sample's producer runs on this host, its process
// most likely waits for a sample itself and fails on its own within its --timeout, naming
// the next producer (its last line, lockstep_wait.hpp); and so on, to the first process that
// does not fail (stopped, hung, or on another host). Two processes of one chain time out
// within moments of each other, in either order; following the chain names the same cause
// whichever reports first (docs/distributed.md, "Faults").
#pragma once

#include <string>

#include "plexus/distributed/lockstep.hpp"
#include "stages.hpp"

namespace plexus::cli {

/// The cause of a run that `error` ended, as plexus launch says it: the last wait of the
/// chain that timed out, from the process that reported it ("plant_simulator r1 exited with
/// code 1: plant_simulator: lockstep: no sample of 'r1/cmd' (produced by 'controller') ..."),
/// or the clock's own message when the chain ends at once. Starts from a process that died
/// when the clock stopped without a timeout of its own. Waits up to `timeout_s` + 0.5 s
/// for each process of the chain; call it before anything is stopped.
std::string lockstep_failure_cause(const LaunchRun& run, const LaunchPlan& plan,
                                   const distributed::LockstepError& error, double timeout_s);

}  // namespace plexus::cli
