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
// measured at the launcher, from the first second of samples: a sample's arrival there
// minus its publish time (the producer's clock, corrected by its host's clock offset).
#pragma once

#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "launch_plan.hpp"
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

/// Collects each hop's latencies over the run's first second (after the first 100 ms, whose
/// samples include the start) and then gives its verdict once: a warning for each loop that
/// does not fit, or with `strict` a BudgetError.
class BudgetCheck {
 public:
  BudgetCheck(std::vector<LoopBudget> loops, bool strict);
  /// The signals as the caller numbers them (sample()'s `signal`).
  void bind(const std::vector<scenario::SignalSpec>& signals);
  /// A sample of signal `signal` arrived `latency_ns` after it was published, at `since_start_ns`.
  void sample(std::size_t signal, int64_t latency_ns, int64_t since_start_ns);
  /// Past the measurement window: logs the verdict (once). Throws BudgetError when strict.
  void conclude(int64_t since_start_ns);
  /// For launch.json: loop -> {deadline_us, fits, hops: [{signal, from, to, slot_us, samples,
  /// p50_us, p99_us}]} (fits: null before the verdict).
  nlohmann::ordered_json record() const;

  static constexpr int64_t kFromNs = 100'000'000;
  static constexpr int64_t kUntilNs = 1'100'000'000;

 private:
  std::vector<LoopBudget> loops_;
  std::vector<std::vector<std::pair<std::size_t, std::size_t>>> by_signal_;  // signal -> (loop, hop)
  bool strict_ = false;
  bool concluded_ = false;
};

/// The q-quantile of latencies in ns, in us (0 for none).
double percentile_us(std::vector<int64_t> v, double q);

}  // namespace plexus::cli
