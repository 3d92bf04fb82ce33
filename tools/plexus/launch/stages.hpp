// The stages of `plexus launch` (launch.cpp runs them in order) and what each hands on:
//
//   plan       stage_plan.cpp       the scenario, this host's processes, their vendors, the
//                                   network and the security of every participant (LaunchPlan)
//   preflight  stage_preflight.cpp  the QoS profiles named, every host checked over ssh, or
//                                   the launcher that started this share answered
//   start      stage_start.cpp      the launcher's participant, the run folder, the log relay,
//                                   each process's part of the scenario, every process started
//   run        stage_run.cpp        the lockstep clock, the realtime monitor, or (on a host
//                                   without the clock) serving until this host's processes end
//   summarise  stage_summarise.cpp  launch.json, the metrics, the report and the exit code
//
// Bad input throws InputError (exit 2) before any process starts: in the plan and preflight
// stages, and (--record, --kill, the run folder) early in the start stage.
#pragma once

#include <sys/types.h>

#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "launch_options.hpp"
#include "launch_plan.hpp"
#include "launch_security.hpp"
#include "log_relay.hpp"
#include "plexus/runtime/participant.hpp"
#include "plexus/runtime/qos.hpp"
#include "plexus/scenario/scenario.hpp"
#include "plexus/scenario/signal_log.hpp"
#include "realtime_run.hpp"
#include "remote_protocol.hpp"
#include "remote_session.hpp"
#include "remote_share.hpp"
#include "signal_recorder.hpp"
#include "status_console.hpp"
#include "supervisor.hpp"
#include "web_monitor.hpp"

namespace plexus::cli {

/// Set by SIGINT and SIGTERM (SIGHUP too on a share started over ssh), by a process that
/// died for good and by a lost host: the run ends.
extern std::atomic<bool> g_launch_stop;
/// The SIGINT / SIGTERM that interrupted the run (0: none).
extern std::atomic<int> g_launch_signal;
/// Installs the handler that sets g_launch_signal and g_launch_stop.
void stop_on_signal(int signal);

/// What the plan stage decided: nothing has started yet.
struct LaunchPlan {
  int64_t command_ns = 0;                  ///< monotonic time of the command (startup_s counts from it)
  std::unique_ptr<RemoteSession> session;  ///< --remote: the launcher that started this share over ssh
  RemoteRequest request;                   ///< --remote: the scenario and the options it sent
  std::vector<scenario::Override> overrides;
  scenario::Scenario sc;
  bool one_command = false;               ///< hosts with ssh, no --host: this host starts the others
  std::vector<std::string> remote_hosts;  ///< one_command: the hosts started over ssh
  std::string vendor;                     ///< the launcher's, and each process's without one of its own
  int domain = 0;
  std::string qos_file;
  rt::QosProfiles profiles;
  rt::QosProfile lockstep_qos;  ///< the profile of the clock and of the signals
  rt::NetworkOptions net;       ///< loopback, or this host's address with every host as a peer
  std::string peers;            ///< net.peers, comma-separated, for the children's --peers
  bool runs_clock = true;       ///< the clock (and the run folder) live on the first host
  bool realtime = false;
  std::vector<Process> procs;       ///< this host's processes to start, vendors resolved
  std::vector<Process> everywhere;  ///< every process of the scenario: what the clock waits for
  std::string vendors_label;        ///< for the headline: the vendor, or "mixed: fast + cyclone"
  LaunchSecurity security;
  std::vector<std::string> externals;  ///< --external: declared, provided by something else

  bool is_external(const Process& p) const;
};

/// What runs from the start stage on, and how the run ends. Members are destroyed in reverse
/// order: the processes are stopped first, the launcher's participant after the teardown bound
/// is armed (done), the other hosts' sessions last.
struct LaunchRun {
  std::unique_ptr<RemoteShares> remotes;         ///< one command: the other hosts (preflight)
  std::unique_ptr<SignalRecorder> recorder;      ///< --record
  std::unique_ptr<WebMonitor> monitor;           ///< --monitor
  std::unique_ptr<rt::Participant> participant;  ///< the clock's, or the realtime monitor's
  std::string run_dir;
  std::optional<StatusConsole> console;
  std::optional<ConsoleLogging> console_logging;
  std::optional<LogRelay> relay;
  FaultClock fault;
  std::atomic<bool> run_active{true};  ///< realtime: restarts allowed (false once the run has ended)
  std::optional<ProcessSupervisor> supervisor;
  pid_t foxglove_bridge = 0;  ///< --foxglove: the bridge beside the run (not supervised: no heartbeat)
  bool supervising = false;   ///< the watcher runs: whatever ends the launcher stops every process
  int64_t launched_ns = 0;    ///< monotonic time every process of this host had been started
  double startup_s = -1;      ///< from the command to every process running
  double teardown_s = -1;     ///< from the end of the run to every process stopped, on every host

  LaunchRun() = default;
  LaunchRun(const LaunchRun&) = delete;
  LaunchRun& operator=(const LaunchRun&) = delete;
  /// Whatever ends the run (an error from DDS included), no child outlives the launcher.
  ~LaunchRun();

  /// Stops the watcher, every process and every other host, then drains the children's
  /// last log lines. Repeatable.
  void stop_all();
  /// Ends a failed run: everything stopped, the run folder marked failed with the cause (a
  /// lost host, else `what`, else a process that died), one line. Returns done(rc).
  int failure(const std::string& what, int rc = 1);
  /// Ends a run stopped by SIGINT or SIGTERM (interrupted_run). Returns done(128 + signal).
  int interrupted();
  /// True when another host was lost (its share failed or its session ended).
  bool host_lost() const;
  /// The process of this host that died for good ("" if none), as exit_report says it.
  /// Complete after stop_all().
  std::string death() const;
  /// "<service> exited with code N", followed by its last line when it ended itself (N
  /// below 128: its one-line error), waiting up to `wait_ms` for that line.
  std::string exit_report(const std::string& service, int status, int wait_ms = 0) const;
  /// Arms the teardown bound (plexus/base/teardown_deadline.hpp) and returns `rc`: every
  /// return from the start stage on goes through it before the participant is deleted, so a
  /// vendor's shutdown that hangs cannot keep the launcher, and what waits for it, from ending.
  static int done(int rc);
};

/// The lockstep run's result, for the summary.
struct LockstepOutcome {
  scenario::RunLog log;
  double wall = 0;
  nlohmann::ordered_json response = nlohmann::ordered_json::object();  ///< per producer (lockstep_status.hpp)
};

/// 1. Reads the scenario (or, with --remote, the launcher's request) and decides what runs
/// where, with which vendor and identity. `o` takes what a --remote request carries.
LaunchPlan plan_launch(LaunchOptions& o);
/// 2. Checks, before anything starts, the QoS profiles the scenario names and every host:
/// over ssh (one command: run.remotes), or by answering the launcher (--remote). False when
/// that launcher gave up.
bool preflight_launch(const LaunchOptions& o, LaunchPlan& plan, LaunchRun& run);
/// 3. Opens the recording, the participant, the run folder and the log relay, writes each
/// process's part of the scenario, starts every process of this host and watches them.
void start_launch(const LaunchOptions& o, LaunchPlan& plan, LaunchRun& run);
/// 4. On a host without the clock: serves until this host's processes end with the run.
/// Returns the exit code.
int serve_launch(const LaunchOptions& o, LaunchPlan& plan, LaunchRun& run);
/// 4. Lockstep: runs the clock to the end (`out`), with the live status line. Returns an
/// exit code when the run ended early (interrupted, a failure), else nothing.
std::optional<int> run_lockstep_launch(const LaunchOptions& o, LaunchPlan& plan, LaunchRun& run, LockstepOutcome& out);
/// 4. Realtime: starts the processes together and records the run (realtime_run.hpp). Returns
/// an exit code when the run ended early, else nothing.
std::optional<int> run_realtime_launch(const LaunchOptions& o, LaunchPlan& plan, LaunchRun& run, RealtimeResult& out);
/// 5. The lockstep run's summary and metrics (finish_run), the report with --report. Returns the exit code.
int summarise_lockstep(const LaunchOptions& o, const LaunchPlan& plan, LaunchRun& run, const LockstepOutcome& out);
/// 5. The realtime run's summary and metrics, the report with --report. Returns the exit code
/// (1 when a process died for good).
int summarise_realtime(const LaunchOptions& o, const LaunchPlan& plan, LaunchRun& run, RealtimeResult& out);

}  // namespace plexus::cli
