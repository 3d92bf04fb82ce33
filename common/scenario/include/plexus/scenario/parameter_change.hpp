// Parameters that change while a scenario runs (docs/parameters.md): a component's tunable
// parameters (Component::add_tunable), named "<component>.<key>" ("observer.L", "controller.k1")
// or, when only one component in the process has that key, "<key>".
//
// Two ways to change one, through the same code:
//  - the scenario's schedule, `parameter_changes: [{step: 500, key: observer.L, value: 2}]`,
//    which `plexus sim`, a lockstep launch and a realtime launch apply alike (a recorded
//    `plexus param set` in lockstep is replayed this way: same step, same digest);
//  - `plexus param set` while it runs (plexus/distributed/param_server.hpp).
// Either way the change is validated by the component's own validator, applied between two
// steps (before the component's first step >= the change's step), and logged.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <spdlog/logger.h>

#include "plexus/scenario/component.hpp"

namespace plexus::scenario {

struct Scenario;

/// One change of the schedule.
struct ParameterChange {
  int64_t step = 0;           ///< applied before the component's first step >= this one
  std::size_t component = 0;  ///< index in Scenario::components
  std::string key;            ///< the parameter's key in its component ("L")
  double value = 0.0;
  std::string where;  ///< "file:line: parameter_changes.0", for messages
};

/// A tunable parameter of one of the scenario's components.
struct TunableRef {
  std::size_t component = 0;
  const TunableParameter* parameter = nullptr;
};

/// Finds "<component>.<key>", or "<key>" when exactly one component `hosted` says runs here
/// has that key (empty `hosted`: every component). nullopt, with `why` one line that names
/// the known parameters, when there is no such parameter or "<key>" is ambiguous.
std::optional<TunableRef> find_tunable(const Scenario& sc, const std::vector<bool>& hosted, const std::string& name,
                                       std::string& why);

/// "<component>.<key>".
std::string tunable_name(const Scenario& sc, const TunableRef& ref);

/// Sets a tunable parameter: its validator's error as one line ("L: must be > 0 (got -1)"),
/// the value unchanged, or "" when it took the value.
std::string try_set(const TunableParameter& parameter, double value);

/// Checks that `value` would be accepted, leaving the parameter as it is (sets it, then sets
/// the previous value back): the reason when not, else "".
std::string check_value(const TunableParameter& parameter, double value);

/// The logger every parameter change is logged to ("param"; on stderr, as every log line).
spdlog::logger& parameter_log();

}  // namespace plexus::scenario
