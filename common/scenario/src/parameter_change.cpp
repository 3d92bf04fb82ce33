#include "plexus/scenario/parameter_change.hpp"

#include <cmath>
#include <exception>

#include "plexus/base/logging.hpp"
#include "plexus/scenario/scenario.hpp"

namespace plexus::scenario {

namespace {

bool runs_here(const std::vector<bool>& hosted, std::size_t c) { return hosted.empty() || hosted[c]; }

/// Every tunable parameter that runs here, "<component>.<key>", for messages.
std::string known_parameters(const Scenario& sc, const std::vector<bool>& hosted) {
  std::string list;
  for (std::size_t c = 0; c < sc.components.size(); ++c)
    if (runs_here(hosted, c))
      for (const auto& t : sc.components[c].component->tunables())
        list += (list.empty() ? "" : ", ") + tunable_name(sc, {c, &t});
  return list.empty() ? "none here" : list;
}

}  // namespace

std::optional<TunableRef> find_tunable(const Scenario& sc, const std::vector<bool>& hosted, const std::string& name,
                                       std::string& why) {
  const auto dot = name.rfind('.');
  std::optional<TunableRef> found;
  int matches = 0;
  for (std::size_t c = 0; c < sc.components.size(); ++c) {
    if (!runs_here(hosted, c)) continue;
    const Component& comp = *sc.components[c].component;
    if (dot != std::string::npos && name.compare(0, dot, comp.name()) == 0 && dot == comp.name().size()) {
      if (const auto* t = comp.tunable(name.substr(dot + 1))) return TunableRef{c, t};
    } else if (const auto* t = comp.tunable(name)) {
      found = TunableRef{c, t};
      ++matches;
    }
  }
  if (matches == 1) return found;
  why = matches > 1 ? "'" + name + "' is a parameter of more than one component: name it <component>." + name +
                          " (tunable: " + known_parameters(sc, hosted) + ")"
                    : "no tunable parameter '" + name + "' (tunable: " + known_parameters(sc, hosted) + ")";
  return std::nullopt;
}

spdlog::logger& parameter_log() {
  static const std::shared_ptr<spdlog::logger> logger = named_logger("param");
  return *logger;
}

std::string tunable_name(const Scenario& sc, const TunableRef& ref) {
  return sc.components[ref.component].component->name() + "." + ref.parameter->key;
}

std::string try_set(const TunableParameter& parameter, double value) {
  if (!std::isfinite(value)) return parameter.key + ": must be a finite number";
  try {
    parameter.set(value);
  } catch (const std::exception& e) {  // the component's validator (validation::ParameterError, InputError)
    return e.what();
  }
  return "";
}

std::string check_value(const TunableParameter& parameter, double value) {
  const double previous = parameter.get();
  std::string why = try_set(parameter, value);
  if (why.empty()) try_set(parameter, previous);  // accepted before, so accepted again
  return why;
}

}  // namespace plexus::scenario
