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

#include "plexus/base/participants_per_host.hpp"
#include "plexus/scenario/component.hpp"
#include "plexus/scenario/expectation.hpp"
#include "plexus/scenario/metric.hpp"
#include "plexus/scenario/overrides.hpp"
#include "plexus/scenario/parameter_change.hpp"

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
  /// Realtime, an estimator: seconds with no fresh measurement after which it is blind (its
  /// own `blind_after_s`, else the scenario's clock.blind_after_s). The right grace depends on
  /// the loop: 0.3 s is 2 cm of the RFID robot's motion, and 300 open-loop steps of a 1 kHz arm.
  double blind_after_s = 0.3;
  /// Realtime: SCHED_FIFO priority of its loop (0: normal scheduling; its own `priority`, else
  /// the scenario's clock.priority) and the CPU it is pinned to (-1: none), passed as the
  /// service's --priority and --cpu.
  int priority = 0;
  int cpu = -1;
  /// port -> "file:line: services.x.remap.port" of each `remap` entry, so that a wiring error
  /// a remap causes names the remap.
  std::map<std::string, std::string> remap_where;
};

/// A signal this document reads but does not produce: a part of a scenario (one process's
/// share, written by `plexus launch`) or a service run on its own. Top-level `inputs:` key.
struct ExternalInput {
  int64_t period_steps = 0;  ///< the producer's period (0: the reading component's own)
  ComponentKind stage =
      ComponentKind::plant;  ///< the producer's stage: a reader in the same or an earlier stage reads it one step late
  bool staged = false;       ///< stage given (else: read without delay)
  std::string qos;           ///< the producer's QoS profile (empty: "state")
  std::string producer;      ///< the producing component's name, for messages (empty: unknown)
};

/// One frame of a device's own table (robot key `source.frames`, docs/bridges.md, "A
/// device's own frames"), as the scenario states it: checked against the IDL here (the type
/// exists, each field is a member's field, the wire type fits the member); ids, sizes and
/// the link's own ids are checked where the table is built (services/bridge/robot_frames).
struct DeclaredFrame {
  struct Field {
    std::string name;
    std::string wire = "f64";  ///< f64 f32 i8 u8 i16 u16 i32 u32
    double scale = 1.0;        ///< integers: SI value = raw * scale
  };
  int id = 0;
  bool to_device = false;
  std::string topic, type;  ///< below the robot ("position"); the IDL type's short or scoped name
  std::vector<Field> fields;
  std::string meaning;
  std::string where;  ///< "file:line: robots.r1.source.frames[2]"
};

/// Where a robot's sensor topics come from and where its command goes (robot key `source`,
/// docs/bridges.md): the plant simulator (the default), a serial or UDP bridge to a device,
/// or the replay of a recording. Under `plexus launch` the robot's process is the source's
/// executable; `plexus sim` simulates only.
struct RobotSource {
  enum class Type { simulator, serial_bridge, udp_bridge, replay };
  Type type = Type::simulator;
  std::string where;            ///< "file:line: robots.r1.source", for errors
  std::string device;           ///< serial_bridge: tty path
  long baud = 1000000;          ///< serial_bridge: 115200 .. 1000000
  std::string bind, peer;       ///< udp_bridge: ADDR:PORT of the bridge and of the device
  double link_timeout_s = 0.5;  ///< bridges: no valid frame for this long -> DEGRADED
  double retry_s = 0.5;         ///< bridges: between attempts to open an absent device
  bool device_time = false;     ///< bridges: the device stamps its samples (docs/bridges.md, "Device time")
  double time_sync_hz = 50.0;   ///< bridges with device_time: time exchanges per second, 1 .. 200
  bool cycle_sync = false;      ///< bridges with device_time: send the run's cycle (docs/bridges.md, "Cycle sync")
  std::vector<DeclaredFrame> frames;  ///< bridges: the device's own frame table; empty: the built-in one
  std::string recording;              ///< replay: the recording (plexus record), absolute
};
const char* to_string(RobotSource::Type t);

/// DDS Security of every participant under `plexus launch` (top-level `security:`,
/// docs/security.md). `plexus sim` validates the keys and runs without DDS.
struct ScenarioSecurity {
  bool enabled = false;
  std::string where;       ///< "file:line: security", for errors
  std::string pki;         ///< the PKI folder (absolute): CA certificates, governance, identities/
  std::string governance;  ///< governance document (absolute); empty: <pki>/governance.p7s
  /// Process name (or plexus_launch) -> identity: a name in <pki>/identities, or a folder
  /// (absolute) holding cert.pem, key.pem and permissions.p7s. Absent: the process's name.
  std::map<std::string, std::string> identities;
  std::map<std::string, std::string> identity_where;  ///< process -> "file:line: security.identities.<process>"
};

/// A closed loop of the scenario (top-level `loops:`, docs/distributed.md, "Loops"): its
/// members, the budget a realtime placement must fit (checked by `plexus launch`), and
/// optionally the one process its members run in (a loop group, as ros2_control keeps a
/// controller and its hardware interface in one loop).
struct ScenarioLoop {
  std::string name;
  std::string where;                 ///< "file:line: loops.<name>", for messages
  std::vector<std::size_t> members;  ///< indices in Scenario::components: robots' plants and sensors, services
  /// Non-empty: every member runs in one process of this name under `plexus launch`, on one
  /// tick, its signals passed in memory (each still published for the other processes).
  std::string process;
  double deadline_s = 0.0;  ///< `deadline`, or the period of its fastest member
};

struct ScenarioMetric {
  std::string name;
  std::string type;
  MetricFunction compute;
  /// Optional key `paper`: the published figure this metric reproduces, as text
  /// ("000 §6.3.2, Fig. 7: max V_t 0.05 m after 100 s"); the report's "paper" column.
  std::string paper = {};
};

struct Scenario {
  std::string file;
  /// Folder of relative file parameters: the file's, or a part's top-level `base_dir`.
  std::string base_dir;
  /// The libraries of its `plugins:` key (absolute paths), loaded before its components were built.
  std::vector<std::string> plugins;
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
  /// Realtime mode: an estimator none of whose measurements has been fresh for this long
  /// is blind (publishes nothing, so the controllers behind it hold); shorter gaps it
  /// bridges with its prediction. 0: blind at the first tick with no fresh measurement.
  double blind_after_s = 0.3;
  /// Realtime mode: SCHED_FIFO priority of every loop (its process's loop and DDS threads)
  /// whose robot or service sets no `priority` of its own (clock.priority; 0: normal).
  int loop_priority = 0;
  std::string dds_vendor;  ///< "fast" | "cyclone" | "" (launch default)
  int dds_domain = 0;
  /// dds.transport: "auto" | "udp" | "shm" (plexus/runtime/transport.hpp, docs/runtime.md).
  std::string dds_transport = "auto";
  /// dds.naming: "plexus" | "ros2", topic and type names on the wire (plexus/runtime/naming.hpp,
  /// docs/ros2.md); every process of the scenario the same.
  std::string dds_naming = "plexus";
  /// dds.participants_per_host: DDS participants of the domain one host may hold, which
  /// discovery probes on each peer (rt::NetworkOptions::max_participants_per_host). `plexus
  /// launch` raises it when a host runs more processes than it allows (docs/runtime.md).
  int dds_participants_per_host = kDefaultParticipantsPerHost;
  std::vector<std::string> hosts;                   ///< in document order; the first runs the clock
  std::map<std::string, std::string> host_address;  ///< host -> address ("" if not given)
  /// How `plexus launch` reaches a host over ssh (hosts.<h>.ssh, workdir, plexus): empty
  /// `ssh` for a host started by hand or the one the command runs on.
  struct HostAccess {
    std::string ssh;      ///< ssh destination, [user@]host or a Host alias of the ssh config
    std::string workdir;  ///< folder the remote share runs in (empty: the login folder)
    std::string plexus;   ///< plexus executable there (empty: the launcher's own path)
  };
  std::map<std::string, HostAccess> host_access;
  /// In execution order: by stage (ComponentKind), then in document order.
  std::vector<ScenarioComponent> components;
  std::vector<ScenarioLoop> loops;  ///< top-level `loops:`, in document order
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
  /// `parameter_changes:`, by step (parameter_change.hpp); a part keeps its own components' only.
  std::vector<ParameterChange> parameter_changes;
  /// Robot -> its source; robots without a `source` key are simulated (absent here).
  std::map<std::string, RobotSource> sources;
  /// What the components found questionable in their parameters (log_warnings).
  std::vector<ScenarioWarning> warnings;
  ScenarioSecurity security;
};

/// Logs a scenario's warnings once each: the short text at warn level, with `where_details`
/// appended when the details are recorded elsewhere (" (details: <run>/summary.md)"), and the
/// detail at info level. `quiet`: both at info (a process that `plexus launch` started:
/// the launcher, which loads the whole scenario, has already said it).
void log_warnings(const Scenario& scenario, const std::string& where_details = {}, bool quiet = false);

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
