// The timing budget of each closed loop a scenario declares (`loops:`, docs/distributed.md,
// "Loops: groups and timing budgets"), checked by `plexus launch` in realtime mode.
//
// A loop's hops are its links between two processes: a signal one member produces and
// another member, in another process, reads. In realtime each process ticks at the phase of
// its stage on the run's grid (distributed::stage_phase: plants 0, references and estimators
// a quarter base period later, controllers half a period), so a hop has until its reader's
// tick to arrive: its slot, the reader's phase after the producer's (a whole period when
// they share a phase), in base periods. A hop later than its slot is read one step late,
// as a late input. The loop fits its placement when every hop's measured latency (p99)
// is within its slot and their sum within the loop's deadline. The latency of a hop is
// measured at the launcher (BudgetCheck), over the run's first second.
#pragma once

#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include <map>
#include <memory>

#include "launch_plan.hpp"
#include "plexus/runtime/participant.hpp"
#include "plexus/runtime/qos.hpp"
#include "plexus/scenario/scenario.hpp"

namespace plexus::cli {

/// One link of a loop between two processes.
struct LoopHop {
  std::string name;                 ///< the signal
  std::string from, to;             ///< producer's and reader's processes
  double slot_s = 0.0;              ///< the time it has: the reader's tick after the producer's
  std::vector<int64_t> latency_ns;  ///< measured: publish to arrival at the launcher
};

/// A declared loop, its hops under this placement, and its deadline.
struct LoopBudget {
  std::string name;
  double deadline_s = 0.0;
  std::vector<LoopHop> hops;  ///< empty for a loop group (one process): nothing to check
};

/// The hops of each of the scenario's loops, when its processes are `procs` (the whole
/// scenario's, on every host).
std::vector<LoopBudget> loop_budgets(const scenario::Scenario& sc, const std::vector<Process>& procs);

/// Empty when the loop fits its budget; else one line naming the loop, its hops with their
/// latencies (p50/p99) and slots, and the deadline.
std::string budget_shortfall(const LoopBudget& loop);

/// `plexus launch --strict`: a loop that cannot fit its budget ends the run (exit 2).
struct BudgetError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Measures each hop over the run's first second (from 0.1 s, after the start's own
/// samples, to 1.1 s) and then gives its verdict once: a warning for each loop that does not
/// fit, or with `strict` a BudgetError. Each hop's signal has a reader of its own in the
/// launcher, on a thread that blocks until a sample arrives: a sample's latency is its arrival
/// there (a subscriber in another process, woken by the data as a service's reader is) minus
/// its publish time.
class BudgetCheck {
 public:
  BudgetCheck(std::vector<LoopBudget> loops, bool strict);
  ~BudgetCheck();
  BudgetCheck(const BudgetCheck&) = delete;
  BudgetCheck& operator=(const BudgetCheck&) = delete;
  /// Creates the readers of the hops' signals (before the start, so that they match).
  /// `publish_offset_ns`: by signal name, the clock offset of its producer's host.
  void bind(rt::Participant& participant, const std::vector<scenario::SignalSpec>& signals, int64_t step_ns,
            const rt::QosProfile& qos, const std::map<std::string, int64_t>& publish_offset_ns);
  /// The run started at monotonic time `t0_ns`: the readers' threads measure its first second.
  void start(int64_t t0_ns);
  /// Past the measurement window: logs the verdict (once). Throws BudgetError when strict.
  void conclude(int64_t now_ns);
  /// For launch.json: loop -> {deadline_us, fits, hops: [{signal, from, to, slot_us, samples,
  /// p50_us, p99_us}]} (fits: null before the verdict).
  nlohmann::ordered_json record() const;

  static constexpr int64_t kFromNs = 100'000'000;
  static constexpr int64_t kUntilNs = 1'100'000'000;

 private:
  struct Probe;
  void stop();
  std::vector<LoopBudget> loops_;
  std::vector<std::unique_ptr<Probe>> probes_;  // one per hop signal
  bool strict_ = false;
  bool concluded_ = false;
  int64_t t0_ns_ = 0;
};

/// The q-quantile of latencies in ns, in us (0 for none).
double percentile_us(std::vector<int64_t> v, double q);

}  // namespace plexus::cli
