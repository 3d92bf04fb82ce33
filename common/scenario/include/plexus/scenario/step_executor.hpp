// One base step of a scenario's components, with the lockstep semantics of executor.hpp,
// for any subset of the components. `plexus sim` runs every component in one process with
// it; a distributed lockstep host runs its share and gets the other inputs over DDS.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "plexus/scenario/scenario.hpp"
#include "plexus/scenario/signal.hpp"

namespace plexus::scenario {

class StepExecutor {
 public:
  /// Fills `sample` with the sample of `signal` due at step `due` (its producer is not
  /// hosted here). Called only with due >= 0; never for a signal produced locally.
  using RemoteInput = std::function<void(std::size_t signal, int64_t due, SignalSample& sample)>;
  /// Receives every output sample of a hosted component, in execution order.
  using OutputSink = std::function<void(std::size_t signal, const SignalSample& sample)>;
  /// Asked after a component's inputs are read: true runs step(), false runs hold()
  /// (realtime mode, stale inputs). Empty: always step().
  using Gate = std::function<bool(std::size_t component)>;

  /// Binds every port of the scenario (all components, hosted or not, so signal indices
  /// are the same in every process). `hosted[i]` says whether component i runs here;
  /// empty means all of them. Throws InputError for a wiring error.
  explicit StepExecutor(Scenario& scenario, std::vector<bool> hosted = {});
  ~StepExecutor();
  StepExecutor(const StepExecutor&) = delete;
  StepExecutor& operator=(const StepExecutor&) = delete;

  /// Every signal of the scenario, indexed as in the callbacks.
  const std::vector<SignalSpec>& signals() const;
  /// Signals that hosted components read but that no hosted component produces.
  std::vector<std::size_t> remote_inputs() const;
  /// Signals produced by hosted components.
  std::vector<std::size_t> local_outputs() const;
  /// The signals component i reads, each once.
  std::vector<std::size_t> inputs_of(std::size_t component) const;
  /// Whether component i runs here.
  bool hosted(std::size_t component) const { return hosted_[component]; }

  /// The step whose sample an input reads at step k: the latest multiple of the producer's
  /// period at or before k (or k-1 for a delayed input); -1 when there is none yet.
  static int64_t due_step(int64_t k, int64_t producer_period, bool delayed);

  /// Runs base step k of the hosted components. Does not allocate (the callbacks must not either).
  void step(int64_t k, const RemoteInput& remote, const OutputSink& sink, const Gate& gate = {});

  /// Runs step k of hosted component i alone, as step(k, ...) runs it in its turn (nothing
  /// when k is not one of its steps). A realtime host uses it to run an estimator's step
  /// once the samples that step reads have arrived (realtime.hpp). Does not allocate.
  void step_component(std::size_t component, int64_t k, const RemoteInput& remote, const OutputSink& sink,
                      const Gate& gate = {});

  /// Runs base step k of the hosted components from component `from` on, as step() runs
  /// them, and stops before the first one that steps at k and reads a sample produced in
  /// another process that `have(signal, due)` says has not arrived (remote_inputs_ready).
  /// Returns that component's index, or the component count once step k is complete; the
  /// next call resumes there. A distributed lockstep host runs its steps with it as samples
  /// arrive, on the thread that received them (lockstep.hpp). Does not allocate.
  template <class Have>
  std::size_t step_from(int64_t k, std::size_t from, Have&& have, const RemoteInput& remote, const OutputSink& sink) {
    const std::size_t n = scenario_.components.size();
    for (std::size_t ci = from; ci < n; ++ci) {
      if (!hosted_[ci] || k % scenario_.components[ci].period_steps != 0) continue;
      if (!remote_inputs_ready(ci, k, have)) return ci;
      run_component(ci, k, remote, sink, {});
    }
    return n;
  }

  /// Asks `have(signal, due)` for every input of component i produced in another process,
  /// with the step whose sample the component's step k reads; true if every answer is true
  /// (or it reads none). Does not allocate.
  template <class Have>
  bool remote_inputs_ready(std::size_t component, int64_t k, Have&& have) const {
    for (std::size_t n = 0, count = remote_input_count(component); n < count; ++n) {
      std::size_t signal = 0;
      const int64_t due = remote_input_due(component, n, k, signal);
      if (due >= 0 && !have(signal, due)) return false;
    }
    return true;
  }

 private:
  std::size_t remote_input_count(std::size_t component) const;
  /// The due step of component i's n-th input binding at step k (-1: not produced yet, or
  /// produced in this process), and its signal.
  int64_t remote_input_due(std::size_t component, std::size_t n, int64_t k, std::size_t& signal) const;
  /// Applies component ci's scheduled parameter changes due at or before step k (Scenario::parameter_changes).
  void apply_parameter_changes(std::size_t ci, int64_t k);
  void run_component(std::size_t ci, int64_t k, const RemoteInput& remote, const OutputSink& sink, const Gate& gate);

  struct Impl;
  Scenario& scenario_;
  std::vector<bool> hosted_;
  Impl* impl_;
};

}  // namespace plexus::scenario
