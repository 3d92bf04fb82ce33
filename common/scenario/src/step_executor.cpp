#include "plexus/scenario/step_executor.hpp"

#include <algorithm>

#include "plexus/base/input_error.hpp"
#include "plexus/scenario/format.hpp"
#include "wiring.hpp"

namespace plexus::scenario {
namespace {

/// The bus slot of one local signal: its current sample and the one before, so a delayed
/// reader can take "the latest sample before step k" whatever the execution order.
struct Slot {
  SignalSample current;
  SignalSample previous;
};

}  // namespace

struct StepExecutor::Impl {
  detail::Wiring wiring;
  std::vector<Slot> bus;
  std::vector<bool> produced_here;  // per signal
  SignalSample remote_sample;       // scratch for remote inputs
  /// By component: its scheduled parameter changes (Scenario::parameter_changes, by step)
  /// and the next one to apply.
  std::vector<std::vector<const ParameterChange*>> changes;
  std::vector<std::size_t> next_change;
};

StepExecutor::StepExecutor(Scenario& scenario, std::vector<bool> hosted)
    : scenario_(scenario), hosted_(std::move(hosted)), impl_(new Impl{detail::wire(scenario), {}, {}, {}, {}, {}}) {
  if (hosted_.empty()) hosted_.assign(scenario_.components.size(), true);
  impl_->bus.resize(impl_->wiring.signals.size());
  impl_->produced_here.assign(impl_->wiring.signals.size(), false);
  for (std::size_t ci = 0; ci < scenario_.components.size(); ++ci)
    if (hosted_[ci])
      for (const auto& out : impl_->wiring.outputs[ci]) impl_->produced_here[out.signal] = true;
  impl_->changes.resize(scenario_.components.size());
  impl_->next_change.assign(scenario_.components.size(), 0);
  for (const auto& change : scenario_.parameter_changes)
    if (hosted_[change.component]) impl_->changes[change.component].push_back(&change);
}

StepExecutor::~StepExecutor() { delete impl_; }

const std::vector<SignalSpec>& StepExecutor::signals() const { return impl_->wiring.signals; }

std::vector<std::size_t> StepExecutor::remote_inputs() const {
  std::vector<bool> seen(impl_->wiring.signals.size(), false);
  std::vector<std::size_t> out;
  for (std::size_t ci = 0; ci < scenario_.components.size(); ++ci) {
    if (!hosted_[ci]) continue;
    for (const auto& in : impl_->wiring.inputs[ci])
      if (!impl_->produced_here[in.signal] && !seen[in.signal]) {
        seen[in.signal] = true;
        out.push_back(in.signal);
      }
  }
  return out;
}

std::vector<std::size_t> StepExecutor::local_outputs() const {
  std::vector<std::size_t> out;
  for (std::size_t s = 0; s < impl_->produced_here.size(); ++s)
    if (impl_->produced_here[s]) out.push_back(s);
  return out;
}

int64_t StepExecutor::due_step(int64_t k, int64_t producer_period, bool delayed) {
  const int64_t target = delayed ? k - 1 : k;
  if (target < 0) return -1;
  return target - target % producer_period;
}

std::vector<std::size_t> StepExecutor::inputs_of(std::size_t component) const {
  std::vector<std::size_t> out;
  for (const auto& in : impl_->wiring.inputs.at(component))
    if (std::find(out.begin(), out.end(), in.signal) == out.end()) out.push_back(in.signal);
  return out;
}

void StepExecutor::step(int64_t k, const RemoteInput& remote, const OutputSink& sink, const Gate& gate) {
  const std::size_t n = scenario_.components.size();
  for (std::size_t ci = 0; ci < n; ++ci)
    if (hosted_[ci]) run_component(ci, k, remote, sink, gate);
}

void StepExecutor::step_component(std::size_t component, int64_t k, const RemoteInput& remote, const OutputSink& sink,
                                  const Gate& gate) {
  if (hosted_.at(component)) run_component(component, k, remote, sink, gate);
}

std::size_t StepExecutor::remote_input_count(std::size_t component) const {
  return impl_->wiring.inputs.at(component).size();
}

int64_t StepExecutor::remote_input_due(std::size_t component, std::size_t n, int64_t k, std::size_t& signal) const {
  const auto& in = impl_->wiring.inputs[component][n];
  signal = in.signal;
  if (impl_->produced_here[in.signal]) return -1;
  return due_step(k, impl_->wiring.signals[in.signal].period_steps, in.delayed);
}

void StepExecutor::apply_parameter_changes(std::size_t ci, int64_t k) {
  const auto& changes = impl_->changes[ci];
  std::size_t& next = impl_->next_change[ci];
  for (; next < changes.size() && changes[next]->step <= k; ++next) {  // none: no work, no allocation
    const ParameterChange& change = *changes[next];
    const Component& c = *scenario_.components[ci].component;
    const TunableParameter* t = c.tunable(change.key);
    const double previous = t->get();
    if (const std::string why = try_set(*t, change.value); !why.empty())  // checked at load: cannot happen
      throw InputError(change.where + ": " + why);
    parameter_log().info("{}.{}: {} -> {} at step {} ({})", c.name(), change.key, format_number(previous),
                         format_number(change.value), k, change.where);
  }
}

void StepExecutor::run_component(std::size_t ci, int64_t k, const RemoteInput& remote, const OutputSink& sink,
                                 const Gate& gate) {
  auto& w = impl_->wiring;
  const double t = static_cast<double>(k) * scenario_.step;
  auto& c = scenario_.components[ci];
  if (k % c.period_steps != 0) return;
  apply_parameter_changes(ci, k);
  for (const auto& in : w.inputs[ci]) {
    const SignalSample* src = nullptr;
    const int64_t due = due_step(k, w.signals[in.signal].period_steps, in.delayed);
    if (impl_->produced_here[in.signal]) {
      const Slot& slot = impl_->bus[in.signal];
      src = (in.delayed && slot.current.step >= k) ? &slot.previous : &slot.current;
    } else {
      SignalSample& r = impl_->remote_sample;
      if (due < 0) {
        r = SignalSample{};  // not produced yet: invalid input, fields zero
      } else {
        remote(in.signal, due, r);
      }
      src = &r;
    }
    SignalSample& dst = in.port->sample();
    in.port->set_due(due);
    dst.step = src->step;
    for (std::size_t f = 0; f < in.width; ++f) dst.values[f] = in.absent[f] ? 0.0 : src->values[in.field_of[f]];
    in.port->refreshed();
  }
  if (!gate || gate(ci))
    c.component->step(k, t);
  else
    c.component->hold(k, t);
  for (const auto& out : w.outputs[ci]) {
    out.port->commit();
    Slot& slot = impl_->bus[out.signal];
    SignalSample& sample = out.port->sample();
    sample.step = k;
    slot.previous = slot.current;
    slot.current = sample;
    sink(out.signal, sample);
  }
}

}  // namespace plexus::scenario
