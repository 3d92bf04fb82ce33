#include "plexus/scenario/metric.hpp"

#include "named_registry.hpp"
#include "plexus/scenario/params.hpp"

namespace plexus::scenario {
namespace {

detail::NamedRegistry<MetricType>& metric_type_registry() {
  static detail::NamedRegistry<MetricType> registry("metric type");  // built on first use
  return registry;
}

}  // namespace

MetricRegistration::MetricRegistration(std::string name, std::string summary, MetricFactory factory) {
  metric_type_registry().add(MetricType{std::move(name), std::move(summary), std::move(factory)});
}

const MetricType* find_metric_type(const std::string& name) { return metric_type_registry().find(name); }

std::vector<const MetricType*> metric_types() { return metric_type_registry().all(); }

const SignalSpec& MetricSetup::signal(const std::string& key) const {
  const auto name = entry_.required<std::string>(key);
  std::string known;
  for (const auto& s : signals_) {
    if (s.name == name) return s;
    known += (known.empty() ? "" : ", ") + s.name;
  }
  entry_.fail(key, "no signal '" + name + "' in this scenario (signals: " + known + ")");
}

int MetricSetup::field(const SignalSpec& spec, const std::string& key) const {
  const auto name = entry_.required<std::string>(key);
  for (std::size_t i = 0; i < spec.fields.size(); ++i)
    if (spec.fields[i] == name) return static_cast<int>(i);
  entry_.fail(key, "signal '" + spec.name + "' has no field '" + name + "'");
}

std::vector<std::string> MetricSetup::fields(const std::vector<const SignalSpec*>& specs, const std::string& key,
                                             const std::vector<std::string>& fallback) const {
  entry_.node(key);  // marks it read even when absent
  const std::vector<std::string> names = entry_.has(key) ? required_names(entry_, key, kMaxSignalFields) : fallback;
  for (const auto* spec : specs)
    for (const auto& n : names) {
      bool found = false;
      for (const auto& f : spec->fields) found = found || f == n;
      if (!found) entry_.fail(key, "signal '" + spec->name + "' has no field '" + n + "'");
    }
  return names;
}

std::pair<double, double> MetricSetup::window() const {
  const double from = entry_.optional<double>("from", 0.0);
  const double to = entry_.optional<double>("to", duration_);
  if (from < 0.0 || from > duration_) entry_.fail("from", "must be in [0, duration]");
  if (to < from || to > duration_) entry_.fail("to", "must be in [from, duration]");
  return {from, to};
}

}  // namespace plexus::scenario
