// The lockstep executor: runs a scenario's components in one process, faster than real
// time, deterministically.
//
// Semantics (the distributed lockstep clock reproduces exactly these):
//  - base step k = 0 .. steps, time t = k * step (computed, never accumulated);
//  - a component with period p runs at step k when k % p == 0;
//  - within a step, components run by stage: plants, sensors, reference generators,
//    estimators, controllers; inside a stage, in scenario order;
//  - an input whose producer is in an earlier stage reads the latest sample produced at
//    a step <= k (so a sensor sees the plant state of step k); an input whose producer
//    is in the same or a later stage reads the latest sample produced at a step <= k-1
//    (so a plant applies the command computed at the previous step: zero-order hold).
//    The order of components inside a stage therefore never changes a result;
//  - before its producer's first sample, an input is invalid (step -1, fields zero).
// Every output sample is recorded; nothing is allocated inside the step loop.
#pragma once

#include <cstdint>
#include <functional>

#include "plexus/scenario/scenario.hpp"
#include "plexus/scenario/signal_log.hpp"

namespace plexus::scenario {

/// Called every few thousand steps with the current step, for progress reporting.
using StepObserver = std::function<void(int64_t step, int64_t steps)>;

/// Runs the scenario to the end and returns every recorded sample. A scenario runs once.
RunLog run_scenario(Scenario& scenario, const StepObserver& observer = {});

}  // namespace plexus::scenario
