// Distributed lockstep: the scenario's components split over processes (and hosts),
// stepping exactly as `plexus sim` does.
//
// Protocol:
//  - the clock (in `plexus launch`) publishes ClockStep k on `lockstep/clock`;
//  - every host runs base step k of its components (StepExecutor) once the clock has
//    published a step >= k - lead_steps (it may run ahead of the clock by that much). An
//    input produced in another process is read from the topic named like the signal
//    (`<robot>/<topic>`), as the IDL message type its producer declares (wire.hpp; doubles
//    carried bit-exact, the step in the header's data time): the host waits for exactly the
//    sample the in-process executor would use
//    (the latest one due at step k, or k-1 for a delayed input), so the lead changes the
//    speed, never the result;
//  - every output sample is published on its topic;
//  - the clock records every signal; when all samples due at step k have arrived, it
//    publishes ClockStep k+1 (every clock_stride-th step: a host may run ahead anyway).
//    After the last step it publishes the end-of-run step.
// The same scenario and seed therefore give the same log and digest as `plexus sim`,
// whatever the vendors and the split. Waiting is bounded: a missing sample fails the run
// after the timeout with a message naming the signal, its producer and the step.
//
// Threads: a host's steps and the clock's recording run on the DDS receive threads, the
// thread that received a sample going on as far as it allows (src/work_pump.hpp,
// StepExecutor::step_from), one thread at a time; the thread that called run() only
// watches the stop flag, the bounded waits (a wait of a second or more is logged with its
// step and producer) and the end (docs/performance.md, section 4).
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "plexus/distributed/wire.hpp"
#include "plexus/runtime/participant.hpp"
#include "plexus/scenario/executor.hpp"
#include "plexus/scenario/scenario.hpp"
#include "plexus/scenario/step_executor.hpp"

namespace plexus::distributed {

/// ClockStep::step_index that ends the run.
inline constexpr uint64_t kEndOfRun = ~uint64_t{0};

/// The scenario's base step in ns, as every host converts step <-> header data time.
int64_t step_ns(const scenario::Scenario& sc);
inline const char* const kClockTopic = "lockstep/clock";

/// Largest lead_steps: a producer can then be at most this many steps ahead of a consumer,
/// well inside a host's per-signal ring (32 samples) and the lockstep profile's keep_last 64.
inline constexpr int64_t kMaxLeadSteps = 16;

struct LockstepOptions {
  double timeout_s = 10.0;  ///< longest wait for one sample or one clock step
  /// Host: ClockStep k lets it run steps up to k + lead_steps as soon as their inputs are
  /// there (0: strictly the clock's step). Results are identical for any lead (every input
  /// is the exact sample); a lead takes the clock's round trip off a closed loop's critical
  /// path. Clamped to [0, kMaxLeadSteps].
  int64_t lead_steps = 8;
  /// Its name (the participant's): it then answers `plexus param` for it (param_server.hpp).
  std::string service{};
};

/// Clock: publishes ClockStep k only for k a multiple of this (and the last step). A host
/// may run lead_steps past the latest tick, so a tick every lead/2 steps still leaves it
/// lead/2 steps of slack while sparing (stride - 1) / stride of the clock's messages and
/// their acknowledgements: at lead 8 a tick every 4 steps (docs/performance.md, lockstep).
inline int64_t clock_stride(const LockstepOptions& o) {
  return std::max<int64_t>(1, std::clamp<int64_t>(o.lead_steps, 0, kMaxLeadSteps) / 2);
}

/// A run that cannot go on: a producer stopped answering, or data arrived out of order.
class LockstepError : public std::runtime_error {
 public:
  /// `awaited`: the component whose sample the clock waited for when it gave up ("" when the
  /// error is not such a timeout), so that the launcher can ask that process for the cause.
  explicit LockstepError(const std::string& what, std::string awaited = {})
      : std::runtime_error(what), awaited_(std::move(awaited)) {}
  const std::string& awaited() const { return awaited_; }

 private:
  std::string awaited_;
};

/// Runs the hosted components of a scenario as the clock commands.
class LockstepHost {
 public:
  /// `hosted[i]`: component i runs in this process. Creates the endpoints.
  LockstepHost(scenario::Scenario& scenario, std::vector<bool> hosted, rt::Participant& participant,
               const rt::QosProfile& qos, LockstepOptions options = {});
  ~LockstepHost();

  /// Steps until the end of run (returns the number of steps run) or until `stop` is set.
  /// Throws LockstepError when an input or the clock stays silent past the timeout.
  int64_t run(const std::atomic<bool>& stop);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// The lockstep clock: steps the run and records every signal.
class LockstepClock {
 public:
  LockstepClock(scenario::Scenario& scenario, rt::Participant& participant, const rt::QosProfile& qos,
                LockstepOptions options = {});
  ~LockstepClock();

  /// Waits until `hosts` hosts follow the clock and every signal has a producer; throws
  /// LockstepError naming what is missing after `timeout_s`.
  void wait_ready(int hosts, double timeout_s, const std::atomic<bool>& stop);

  /// Called with every signal sample the clock takes (signal index, the message type, the
  /// message as received, its metadata, its CDR as received), for `plexus launch --record`.
  using SampleTap = std::function<void(std::size_t signal, const msg::TypeSupport& type, const void* message,
                                       const rt::SampleMeta&, const std::vector<unsigned char>& cdr)>;
  /// Runs every step and returns the log (the same as `plexus sim`'s). Throws LockstepError.
  /// `observer` and `tap` are called on the thread that records (a DDS receive thread, one
  /// at a time, never after run() returns): keep them short, as a status line once a second.
  scenario::RunLog run(const std::atomic<bool>& stop, const scenario::StepObserver& observer = {},
                       const SampleTap& tap = {});
  /// The scenario's signals, by the index SampleTap reports.
  const std::vector<scenario::SignalSpec>& signals() const;

  /// How fast each producer answers: from the clock publishing the tick that released step k
  /// (a host runs up to lead_steps past the latest tick: the first tick at or after k - lead)
  /// to the producer publishing its sample of step k, for the steps after the first lead_steps (both wall-clock stamps:
  /// one machine, or synchronised clocks), over the most recent samples (up to 4096) since the previous call. Call it
  /// from the observer (the thread that records); it does not allocate once `out` has grown
  /// to the producer count.
  struct ProducerStatus {
    std::string producer;
    uint64_t samples = 0;
    double response_p50_us = 0, response_p99_us = 0, response_max_us = 0;
  };
  void producer_status(std::vector<ProducerStatus>& out);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace plexus::distributed
