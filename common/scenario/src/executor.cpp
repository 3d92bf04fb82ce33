#include "plexus/scenario/executor.hpp"


#include "wiring.hpp"

namespace plexus::scenario {
namespace {

/// The bus slot of one signal: its current sample and the one before, so a delayed
/// reader can take "the latest sample before step k" whatever the execution order.
struct Slot {
  SignalSample current;
  SignalSample previous;
};

}  // namespace

RunLog run_scenario(Scenario& scenario, const StepObserver& observer) {
  const detail::Wiring w = detail::wire(scenario.components);
  RunLog log;
  log.base_step = scenario.step;
  log.steps = scenario.steps;
  log.signals.resize(w.signals.size());
  for (std::size_t s = 0; s < w.signals.size(); ++s) {
    auto& trace = log.signals[s];
    trace.spec = w.signals[s];
    const auto samples = static_cast<std::size_t>(scenario.steps / trace.spec.period_steps + 1);
    trace.steps.reserve(samples);
    trace.values.reserve(samples * trace.width());
  }
  std::vector<Slot> bus(w.signals.size());

  constexpr int64_t kObserveEvery = 4096;
  const std::size_t n = scenario.components.size();
  for (int64_t k = 0; k <= scenario.steps; ++k) {
    const double t = static_cast<double>(k) * scenario.step;
    for (std::size_t ci = 0; ci < n; ++ci) {
      auto& c = scenario.components[ci];
      if (k % c.period_steps != 0) continue;
      for (const auto& in : w.inputs[ci]) {
        const Slot& slot = bus[in.signal];
        const SignalSample& src = (in.delayed && slot.current.step >= k) ? slot.previous : slot.current;
        SignalSample& dst = in.port->sample();
        dst.step = src.step;
        for (std::size_t f = 0; f < in.width; ++f) dst.values[f] = src.values[in.field_of[f]];
      }
      c.component->step(k, t);
      for (const auto& out : w.outputs[ci]) {
        Slot& slot = bus[out.signal];
        SignalSample& sample = out.port->sample();
        sample.step = k;
        slot.previous = slot.current;
        slot.current = sample;
        auto& trace = log.signals[out.signal];
        trace.steps.push_back(k);
        trace.values.insert(trace.values.end(), sample.values.begin(), sample.values.begin() + trace.width());
      }
    }
    if (observer && (k % kObserveEvery == 0 || k == scenario.steps)) observer(k, scenario.steps);
  }
  return log;
}

}  // namespace plexus::scenario
