#include "plexus/scenario/metric.hpp"

#include <cstdio>
#include <cstdlib>
#include <map>

namespace plexus::scenario {
namespace {

std::map<std::string, MetricType>& types() {
  static std::map<std::string, MetricType> registry;
  return registry;
}

}  // namespace

MetricRegistration::MetricRegistration(std::string name, std::string summary, MetricFactory factory) {
  auto [it, added] = types().emplace(name, MetricType{name, std::move(summary), std::move(factory)});
  if (!added) {
    std::fprintf(stderr, "plexus: metric type '%s' registered twice\n", name.c_str());
    std::abort();
  }
}

const MetricType* find_metric_type(const std::string& name) {
  auto it = types().find(name);
  return it == types().end() ? nullptr : &it->second;
}

std::vector<const MetricType*> metric_types() {
  std::vector<const MetricType*> out;
  for (const auto& [name, type] : types()) out.push_back(&type);
  return out;
}

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
  std::vector<std::string> names = fallback;
  if (entry_.has(key)) {
    names.clear();
    for (const auto& n : entry_.sequence(key)) {
      if (!n.IsScalar()) entry_.fail(key, "expected a list of field names");
      names.push_back(n.Scalar());
    }
    if (names.empty()) entry_.fail(key, "needs at least one field");
  } else {
    entry_.node(key);  // mark as read
  }
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
