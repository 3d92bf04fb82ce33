#include "plexus/scenario/executor.hpp"

#include <unistd.h>

#include <cstdio>
#include <string>

#include "plexus/base/input_error.hpp"
#include "plexus/scenario/format.hpp"
#include "plexus/scenario/step_executor.hpp"

namespace plexus::scenario {
namespace {

/// `plexus sim` keeps every sample of every signal in memory (the run log): refuse, naming
/// `duration`, a run whose log would not fit in half of this machine's memory, instead of
/// dying of std::bad_alloc halfway.
void check_log_fits(const Scenario& sc, const std::vector<SignalSpec>& signals) {
  double bytes = 0.0;
  for (const auto& s : signals)
    bytes += (static_cast<double>(sc.steps) / static_cast<double>(s.period_steps) + 1.0) *
             (8.0 * static_cast<double>(s.fields.size()) + 8.0);
  const double memory = static_cast<double>(::sysconf(_SC_PHYS_PAGES)) * static_cast<double>(::sysconf(_SC_PAGE_SIZE));
  if (memory > 0.0 && bytes > 0.5 * memory) {
    char buf[256];
    std::snprintf(buf, sizeof buf,
                  "duration: %s s of %zu signals needs %.3g GB to record, more than half of this machine's %.3g GB: "
                  "shorten the run or lower the sensor rates",
                  format_number(sc.duration).c_str(), signals.size(), bytes * 1e-9, memory * 1e-9);
    throw InputError(sc.file + ": " + buf);
  }
}

}  // namespace

RunLog run_scenario(Scenario& scenario, const StepObserver& observer) {
  StepExecutor exec(scenario);
  check_log_fits(scenario, exec.signals());
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
