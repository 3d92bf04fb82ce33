// plexus launch's processes on this host while they run: each started with its output on the
// log relay, and a watcher thread that injects the --kill faults, notes every exit, restarts
// a process per its policy (realtime) and ends the run when one dies for good.
#pragma once

#include <atomic>
#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "launch_plan.hpp"
#include "log_relay.hpp"
#include "realtime_run.hpp"

namespace plexus::cli {

/// Realtime: how long a run goes on after a process died for good (a plant simulator, a
/// service with `restart: never`), recording the others' reaction, before it fails. A
/// second: many input deadlines at any rate a scenario uses (3 periods: 30 ms at 100 Hz).
constexpr int64_t kFatalGraceNs = 1'000'000'000;

/// --kill PROCESS@SECONDS: the process to SIGKILL that long after the start, by name. Throws
/// InputError for a malformed argument, a process not on this host, or a lockstep run.
std::map<std::string, double> parse_kills(const std::vector<std::string>& kills, const std::vector<Process>& procs,
                                          bool realtime);

class ProcessSupervisor {
 public:
  /// `procs` (this host's, with their arguments) outlive the supervisor. `run_active`: restarts
  /// are allowed (realtime); `stop` is set when a process died for good.
  ProcessSupervisor(std::vector<Process>& procs, LogRelay& relay, FaultClock& fault,
                    const std::atomic<bool>& run_active, std::atomic<bool>& stop, bool realtime,
                    std::map<std::string, double> kill_at);
  ~ProcessSupervisor();
  ProcessSupervisor(const ProcessSupervisor&) = delete;
  ProcessSupervisor& operator=(const ProcessSupervisor&) = delete;

  /// Starts `p` (p.args), its output through the relay, and notes the command in its log.
  void start(Process& p);
  /// Starts the watcher thread.
  void watch();
  /// Ends the watcher and stops every process still running. Repeatable.
  void stop();
  /// A process's exit: its service name and exit code (128 + N: killed by signal N).
  struct Exit {
    std::string service;
    int status = 0;
  };
  /// The first process that died for good (ended with a code other than 0, a signal's too,
  /// and not restarted): nothing if none.
  std::optional<Exit> first_death() const;
  /// While the watcher runs: the exit code of process `service` once it exited on its own,
  /// waiting up to `timeout_ns` for it; nothing if it still runs (or the watcher has stopped).
  std::optional<int> await_exit(const std::string& service, int64_t timeout_ns) const;
  /// The process --kill killed ("" if none). Read after stop().
  const std::string& killed() const { return killed_; }

 private:
  void inject_kill(Process& p, int64_t started_ns);
  void reap(Process& p);
  void restart_if_due(Process& p);

  std::vector<Process>& procs_;
  LogRelay& relay_;
  FaultClock& fault_;
  const std::atomic<bool>& run_active_;
  std::atomic<bool>& stop_;
  const bool realtime_;
  std::map<std::string, double> kill_at_;  // watcher thread only, like the three below
  mutable std::mutex exits_mu_;            // guards the two below: the watcher writes, the launcher reads
  std::optional<Exit> first_death_;
  std::map<std::string, int> exits_;  // service -> exit code of its last exit, by the watcher
  std::string killed_;
  int64_t fatal_stop_ns_ = 0;  // realtime: when to stop after a death that is not restarted
  std::atomic<bool> watching_{true};
  std::thread watcher_;
};

}  // namespace plexus::cli
