// Realtime mode: the scenario's components on wall-clock loops, latest-sample semantics.
//
//  - Each host runs its components in one absolute-deadline loop (PeriodicLoop) whose period
//    is the greatest common divisor of their periods (a host of 100 Hz services on a 1 kHz
//    grid ticks at 100 Hz); a component runs at the steps its period divides.
//  - An input from another process is read from the recent samples received on its typed
//    topic `<signal>` (wire.hpp: data times are wall-clock times on the run's grid): the
//    sample of the step the sim would read if it has arrived, else the newest older one, a
//    read counted as late. It is stale when the newest sample is older than
//    `input_deadline_periods` periods of its producer (scenario `clock.input_deadline_periods`,
//    default 3), or none has arrived.
//  - An estimator that reads from another process runs each of its steps once the samples
//    that step reads have arrived, at most one of its periods after the step's tick (then
//    with what has arrived: late reads); so a sample that comes after its tick is still used
//    at its own step, as `plexus sim` uses it, and the estimate of that step is published
//    when it is computed. Controllers and plants do not wait: they read at their tick.
//  - A controller with a stale input runs hold() instead of step(): its documented safe
//    output (by default all zero: zero velocity, zero torque). It recovers by itself at the
//    first tick where its inputs are fresh again. Other components run on the last sample,
//    but an estimator none of whose measurements (inputs from plants and sensors) is fresh is
//    blind: it steps, and its outputs are not published, so its consumers' inputs go stale
//    in turn and a controller behind it holds (a dead plant simulator stops every loop).
//  - Every output carries in its header the origin time of the newest input it was
//    computed from, in this process or another (a sensor starts a chain; an output computed
//    from no measurement, a reference's, carries kNoMeasurementOrigin), so the latency from
//    a sensor sample to the command at the plant can be measured from the data.
//  - All loops tick on one wall-clock grid, the run's start (carried by the start signal)
//    plus whole base periods, each host at the phase of its stage (stage_phase): plants and
//    sensors at 0, references and estimators a quarter period later, controllers (and hosts
//    that also run a controller) at half a period. A sensor sample then reaches the
//    estimator, the estimate the controller and the command the plant within one base
//    period, as in `plexus sim`, when each hop takes less than a quarter period; a later hop
//    costs that input one period. Hosts on different machines share the grid as well as
//    their clocks agree.
//  - Every host publishes a Heartbeat with its loop statistics on `health/<service>` once a
//    second. Under `plexus launch` it starts when the launcher's start signal (ClockStep 0
//    on `lockstep/clock`) arrives, so all processes begin together; a service started on its
//    own starts at once and runs until it is stopped (its controllers hold their safe output
//    until their inputs arrive).
#pragma once

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "plexus/runtime/participant.hpp"
#include "plexus/runtime/periodic_loop.hpp"
#include "plexus/runtime/qos.hpp"
#include "plexus/scenario/scenario.hpp"

namespace plexus::distributed {

/// Header origin of a sample computed from no measurement (a reference, an open-loop
/// command): older than any real origin, so a measured input wins the newest-origin rule,
/// and skipped by the launcher's sensor-to-command statistics.
inline constexpr int64_t kNoMeasurementOrigin = 1;

/// The heartbeat topic of a service: `health/<service>`, with every character a DDS topic
/// name may not hold (Cyclone DDS accepts letters, digits, `_` and `/`) replaced by `_`, so
/// "plant_simulator r1" publishes on `health/plant_simulator_r1`.
std::string health_topic(const std::string& service);

/// A heartbeat naming its sender: `service` and `robot` (cut to the message's 31
/// characters), this process's pid and its host name; the rest zero. The first call starts
/// the clock of heartbeat_uptime_s().
msg::Heartbeat heartbeat_of(const std::string& service, const std::string& robot = {});
/// Seconds since this process first called heartbeat_of (its start, within its set-up):
/// Heartbeat.uptime_s. No system call.
double heartbeat_uptime_s();

/// The phase, as a fraction of the base period, at which a host of these components ticks:
/// 0 if it hosts a plant or a sensor, else 0.5 if it hosts a controller, else 0.25 (references
/// and estimators). Components of one host run in the scenario's order within a tick, so a
/// host of an estimator and its controller (a `process` group) reads the sensors half a
/// period after they were taken and leaves the command half a period to reach the plant.
double stage_phase(const scenario::Scenario& sc, const std::vector<bool>& hosted);

/// The start of a run (docs/distributed.md, "Start-up"): in its first kSeconds (at least
/// kMinTicks ticks) a host that starts with the run waits for the samples due at each step
/// before it reads them, at most kWaitPeriods of its periods each; afterwards it never waits.
/// A host that joins a running loop (a restarted service) never waits: the loop's other
/// members keep their deadlines and its consumers hold their safe output until it publishes,
/// so a wait would only lengthen their hold. The first write of each DDS writer costs 0.3-0.5
/// ms on both vendors and the first deliveries up to 2 ms (measured at 1 kHz on loopback;
/// 20-80 us later), so without the wait a 1 kHz loop's first hops arrive late: its
/// controller's first steps hold and its plant integrates them with no command, a start
/// `plexus sim` never has. The flexible-joint arm at 1 kHz with its plant in another process
/// (repro.realtime.arm_vdc_ekf_1khz_*) then tracked 0.6-1.2 mrad RMS after 1 s in 3 of 6 runs
/// (sim 0.03); with the wait 0.03-0.37 in 12 of 12. The device emulator following the run's
/// cycle starts its plant by the same rule (tools/device_emulator, docs/bridges.md).
struct StartupWait {
  static constexpr double kSeconds = 0.05;
  static constexpr int64_t kMinTicks = 3;
  static constexpr int64_t kWaitPeriods = 2;
  /// The ticks of the start at this period (s).
  static int64_t ticks(double period_s) {
    return std::max<int64_t>(kMinTicks, static_cast<int64_t>(std::ceil(kSeconds / period_s)));
  }
};

/// The QoS profile of a signal: its producer's `qos` key, else "state".
const rt::QosProfile& signal_qos(const scenario::Scenario& sc, const std::string& producer,
                                 const rt::QosProfiles& profiles);
/// The QoS profile a reader uses for a signal: its producer's, from the part's `inputs:` when
/// the producer runs in another process.
const rt::QosProfile& input_qos(const scenario::Scenario& sc, const scenario::SignalSpec& spec,
                                const rt::QosProfiles& profiles);

struct RealtimeOptions {
  std::string service;   ///< name in heartbeats and logs
  rt::LoopOptions loop;  ///< rate_hz is set from the scenario's base step
  /// Under `plexus launch`: wait for the launcher's start signal (the run's common grid).
  /// Alone: start at once, on a grid of its own.
  bool wait_for_start = false;
  double start_timeout_s = 30;  ///< longest wait for the launcher's start signal
};

/// What a realtime host did, for the launcher and the logs.
struct RealtimeReport {
  int64_t ticks = 0;
  uint64_t holds = 0;                 ///< controller steps replaced by the safe output
  uint64_t blind_steps = 0;           ///< estimator steps with no fresh measurement (outputs not published)
  uint64_t stale_inputs = 0;          ///< input reads that found a stale sample
  uint64_t late_inputs = 0;           ///< input reads that found an older sample than the sim would read
  uint64_t deferred_steps = 0;        ///< estimator steps run after their tick, once their samples had arrived
  uint64_t dropped_late_samples = 0;  ///< samples the components dropped or bridged by their late-sample rules
  uint64_t rejected_inputs = 0;       ///< received samples refused at the edge (non-finite, malformed)
  rt::LoopStats loop;
};

class RealtimeHost {
 public:
  RealtimeHost(scenario::Scenario& scenario, std::vector<bool> hosted, rt::Participant& participant,
               const rt::QosProfiles& profiles, RealtimeOptions options);
  ~RealtimeHost();

  /// Waits for the start signal (if asked to), then runs scenario.steps + 1 ticks (or until `stop`).
  RealtimeReport run(const std::atomic<bool>& stop);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace plexus::distributed
