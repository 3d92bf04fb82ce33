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
  /// Seconds between the process's death and its restart (systemd's RestartSec), >= 0.
  double restart_delay = 0.0;
};

/// A signal this document reads but does not produce: a part of a scenario (one process's
/// share, written by `plexus launch`) or a service run on its own. Top-level `inputs:` key.
struct ExternalInput {
  int64_t period_steps = 0;  ///< the producer's period (0: the reading component's own)
  ComponentKind stage = ComponentKind::plant;  ///< the producer's stage: a reader in the same or an earlier stage reads it one step late
  bool staged = false;       ///< stage given (else: read without delay)
  std::string qos;           ///< the producer's QoS profile (empty: "state")
  std::string producer;      ///< the producing component's name, for messages (empty: unknown)
};

/// Where a robot's sensor topics come from and where its command goes (robot key `source`,
/// docs/bridges.md): the plant simulator (the default), a serial or UDP bridge to a device,
/// or the replay of a recording. Under `plexus launch` the robot's process is the source's
/// executable; `plexus sim` simulates only.
struct RobotSource {
  enum class Type { simulator, serial_bridge, udp_bridge, replay };
  Type type = Type::simulator;
  std::string where;             ///< "file:line: robots.r1.source", for errors
  std::string device;            ///< serial_bridge: tty path
  long baud = 1000000;           ///< serial_bridge: 115200 .. 1000000
  std::string bind, peer;        ///< udp_bridge: ADDR:PORT of the bridge and of the device
  double link_timeout_s = 0.5;   ///< bridges: no valid frame for this long -> DEGRADED
  double retry_s = 0.5;          ///< bridges: between attempts to open an absent device
  std::string recording;         ///< replay: the recording (plexus record), absolute
};
const char* to_string(RobotSource::Type t);

struct ScenarioMetric {
  std::string name;
  std::string type;
  MetricFunction compute;
};

struct Scenario {
  std::string file;
  /// Folder of relative file parameters: the file's, or a part's top-level `base_dir`.
  std::string base_dir;
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
  std::vector<SignalSpec> signals;  ///< every signal, in component order (then external inputs)
  /// A part of a scenario (one process's components, or one service on its own): inputs no
  /// component produces are read from other processes, scheduled by `inputs` (else at the
  /// reader's own rate), and `robots` may be absent. A whole scenario (false) refuses them.
  bool partial = false;
  std::map<std::string, ExternalInput> inputs;  ///< by signal name
  /// Runs until stopped (a service on its own: no `duration`); steps is then kUntilStopped.
  bool until_stopped = false;
  std::vector<ScenarioMetric> metrics;
  std::vector<Expectation> expectations;
  /// Robot -> its source; robots without a `source` key are simulated (absent here).
  std::map<std::string, RobotSource> sources;
};

/// Steps of a run that goes on until it is stopped (Scenario::until_stopped).
inline constexpr int64_t kUntilStopped = int64_t{1} << 60;

struct LoadOptions {
  /// A part of a scenario (Scenario::partial): `robots` optional, services' `robot` any name,
  /// top-level `inputs:` allowed, `duration` optional (absent: until stopped), `seed`
  /// optional (0), no metrics or expectations.
  bool partial = false;
};

/// Loads, overrides and validates a scenario file; throws InputError (exit 2) for any problem.
Scenario load_scenario(const std::string& path, const std::vector<Override>& overrides = {}, LoadOptions options = {});

/// Same, from YAML text; `origin` names it in errors.
Scenario load_scenario_text(const std::string& text, const std::string& origin,
                            const std::vector<Override>& overrides = {}, LoadOptions options = {});

/// Same, from a YAML tree (a service's parameters embedded in a document it builds).
Scenario load_scenario_tree(YAML::Node root, const std::string& origin, const std::vector<Override>& overrides = {},
                            LoadOptions options = {});

/// Parses a stage name ("plant" .. "controller"); false if unknown.
bool parse_component_kind(const std::string& name, ComponentKind& kind);

}  // namespace plexus::scenario
