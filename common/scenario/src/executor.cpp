#include "plexus/scenario/executor.hpp"

#include "plexus/scenario/step_executor.hpp"

namespace plexus::scenario {

RunLog run_scenario(Scenario& scenario, const StepObserver& observer) {
  StepExecutor exec(scenario);
  RunLog log;
  log.base_step = scenario.step;
  log.steps = scenario.steps;
  log.signals.resize(exec.signals().size());
  for (std::size_t s = 0; s < exec.signals().size(); ++s) {
    auto& trace = log.signals[s];
    trace.spec = exec.signals()[s];
    const auto samples = static_cast<std::size_t>(scenario.steps / trace.spec.period_steps + 1);
    trace.steps.reserve(samples);
    trace.values.reserve(samples * trace.width());
  }
  const StepExecutor::RemoteInput none = [](std::size_t, int64_t, SignalSample&) {};  // everything is local
  const StepExecutor::OutputSink record = [&log](std::size_t signal, const SignalSample& sample) {
    log.record(signal, sample);
  };
  constexpr int64_t kObserveEvery = 4096;
  for (int64_t k = 0; k <= scenario.steps; ++k) {
    exec.step(k, none, record);
    if (observer && (k % kObserveEvery == 0 || k == scenario.steps)) observer(k, scenario.steps);
  }
  return log;
}

}  // namespace plexus::scenario
