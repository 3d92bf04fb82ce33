// A scenario: what to run (robots, their plants and sensors, the services), for how
// long, with which seed, and what to measure. Loaded from YAML and fully validated:
// every component is built, every port is bound and every metric is set up before
// anything runs, so a bad scenario fails with exit code 2 and one line naming file,
// line and key. The format is documented in docs/scenarios.md.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "plexus/scenario/component.hpp"
#include "plexus/scenario/expectation.hpp"
#include "plexus/scenario/metric.hpp"
#include "plexus/scenario/overrides.hpp"

namespace plexus::scenario {

enum class ClockMode { lockstep, realtime };

/// A component of the scenario, built and validated.
struct ScenarioComponent {
  std::unique_ptr<Component> component;
  std::string type;  ///< registered type name
  ComponentKind kind{};
  int64_t period_steps = 1;
  std::string where;  ///< "file:line: yaml.path", for errors about this component
  std::string host;   ///< host it runs on under `plexus launch` (empty: any)
  std::string qos;    ///< QoS profile name for its outputs (empty: the default)
  std::string dds;    ///< DDS vendor of its process under `plexus launch` (empty: the run's)
  /// `plexus launch`: services with the same `process` run in one process of that name
  /// (empty: a process of their own, named after the service).
  std::string process;
  /// `plexus launch`, realtime mode: restart the service's process when it dies
  /// ("on_failure", the default), whenever it exits ("always"), or not ("never").
  std::string restart = "on_failure";
};

struct ScenarioMetric {
  std::string name;
  std::string type;
  MetricFunction compute;
};

struct Scenario {
  std::string file;
  YAML::Node resolved;  ///< the tree after overrides, with derived seeds written in
  std::string name;
  std::string description;
  double duration = 0.0;  ///< s
  double step = 0.0;      ///< s, base step
  int64_t steps = 0;      ///< duration / step
  uint64_t seed = 0;
  ClockMode clock = ClockMode::lockstep;
  /// Realtime mode: an input older than this many periods of its producer is stale.
  double input_deadline_periods = 3.0;
  std::string dds_vendor;  ///< "fast" | "cyclone" | "" (launch default)
  int dds_domain = 0;
  std::vector<std::string> hosts;                   ///< in document order; the first runs the clock
  std::map<std::string, std::string> host_address;  ///< host -> address ("" if not given)
  /// In execution order: by stage (ComponentKind), then in document order.
  std::vector<ScenarioComponent> components;
  std::vector<SignalSpec> signals;  ///< every signal, in component order
  std::vector<ScenarioMetric> metrics;
  std::vector<Expectation> expectations;
};

/// Loads, overrides and validates a scenario file; throws InputError (exit 2) for any problem.
Scenario load_scenario(const std::string& path, const std::vector<Override>& overrides = {});

/// Same, from YAML text; `origin` names it in errors.
Scenario load_scenario_text(const std::string& text, const std::string& origin,
                            const std::vector<Override>& overrides = {});

}  // namespace plexus::scenario
