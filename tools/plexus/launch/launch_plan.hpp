// The processes `plexus launch` starts for a scenario: which executable, which components,
// which vendor, and the `process` groups (docs/scenarios.md).
#pragma once

#include <sys/types.h>

#include <yaml-cpp/yaml.h>
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "plexus/scenario/scenario.hpp"

namespace plexus::cli {

/// One child process: a name, the executable, its selection argument and what it hosts.
struct Process {
  std::string name;
  std::string program;
  std::vector<std::string> select;  ///< --robots R1,R2 or --components S1,S2: the executable's selection
  /// Indices in Scenario::components of what it builds: its robots' plants and sensors, or
  /// its services.
  std::vector<std::size_t> components;
  std::string vendor;
  pid_t pid = 0;
  std::string restart = "never";  ///< realtime: never | on_failure | always (scenario `restart`)
  int64_t restart_delay_ns = 0;   ///< realtime: wait this long after its death (scenario `restart_delay`)
  int64_t restart_at_ns = 0;      ///< monotonic time of a pending restart (0: none)
  std::vector<std::string> args;  ///< as started, to restart it the same way
  int restarts = 0;
  int priority = 0;        ///< realtime: SCHED_FIFO priority of its loop (scenario `priority`; 0: none)
  int cpu = -1;            ///< realtime: the CPU its loop is pinned to (scenario `cpu`; -1: none)
  bool has_plant = false;  ///< a loop group with a robot's plant: never restarted

  /// The service name the process reports in its heartbeats and DDS participant.
  std::string service() const { return select.empty() ? program : program + " " + select.back(); }
  /// The file in build/bin it runs: the program, or `plexus` for a robot's replay.
  std::string executable() const { return program == "replay" ? "plexus" : program; }
};

/// The processes of a scenario: one plant_simulator per host for the robots on that host,
/// one process per service in the executable of its type, or one per `process` group (in the
/// executable of its members' type if they share one, else component_host); a robot in a
/// loop group (`loops:` with `process`) runs in its group's process. With `host`
/// set, only those assigned to it (components without a host run on the first host).
/// Throws InputError when the services of a group disagree on host, vendor or restart policy,
/// or a group takes another service's name.
std::vector<Process> plan(const scenario::Scenario& sc, const std::string& host);

/// Participants a host needs beside its processes: the launcher's, foxglove_bridge's, and room
/// for the tools a user attaches to a run (plexus topic, record, a second monitor).
inline constexpr int kParticipantsBesideProcesses = 6;

/// dds.participants_per_host, raised to what the busiest host needs: its processes and
/// kParticipantsBesideProcesses (docs/runtime.md, "Participants per host"). From the scenario
/// alone, so that every host of a run (over ssh too) derives the same value. Throws
/// InputError when that passes kMaxParticipantsPerHost.
int participants_per_host(const scenario::Scenario& sc);

/// A process's part of the scenario, as a document its executable loads (--part): the
/// top-level settings, its own robots or services (their resolved sections, derived seeds
/// written in, `host` left out) and `inputs:`, the schedule (period, stage, QoS profile) of
/// every signal it reads that another process produces. It builds nothing else.
YAML::Node part_document(const scenario::Scenario& sc, const Process& p);

/// A robot's replay (`source: {type: replay}`): the arguments of `plexus replay` for the
/// robot's sensor and truth topics, restamped to the run's clock, with a heartbeat.
std::vector<std::string> replay_args(const scenario::Scenario& sc, const Process& p);

/// launch.json's record of what this launcher started: process -> executable and vendor.
nlohmann::ordered_json process_table(const std::vector<Process>& procs);

}  // namespace plexus::cli
