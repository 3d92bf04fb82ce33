// `plexus launch SCENARIO` from one machine: the shares of the other hosts, each started
// over ssh as `plexus launch --remote` there (remote_session.hpp) with the scenario's text.
// Preflight before anything starts (reachable, same version, same scenario digest, the
// host's address on an interface, clock offset), then their log lines into this run's
// relay as `host/process`, per-host health for the status line, and a lost host ends the
// run. Stopping closes each session, which stops that host's processes.
#pragma once

#include <atomic>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "clock_offset.hpp"
#include "log_relay.hpp"
#include "plexus/scenario/scenario.hpp"
#include "remote_protocol.hpp"
#include "ssh_command.hpp"

namespace plexus::cli {

struct RemoteShareOptions {
  SshOptions ssh;
  std::string ssh_program = "ssh";
  std::string local_plexus;  ///< the plexus a host runs when it names none (this one's path)
  RemoteRequest request;     ///< the common part; host and out are set per host
  std::string out;           ///< --out given here: a host writes its folder to <out>-<host> (else its default)
  std::map<std::string, int64_t> clock_injection_ns;  ///< tests: --inject-clock-offset HOST=SECONDS
  int clock_samples = 16;
  double answer_timeout_s = 30.0;  ///< connect, start plexus there and load the scenario
};

class RemoteShares {
 public:
  /// `hosts`: the hosts to start (preflight.hpp ssh_hosts); `local` the one this command runs on.
  RemoteShares(const scenario::Scenario& sc, const std::string& local, std::vector<std::string> hosts,
               RemoteShareOptions options);
  ~RemoteShares();
  RemoteShares(const RemoteShares&) = delete;
  RemoteShares& operator=(const RemoteShares&) = delete;

  /// Starts every session at once and checks each host; throws InputError (exit 2) naming
  /// the first host that fails, after closing every session.
  void preflight(const std::string& version, const std::string& digest);
  /// Each host's clock minus this one's (after preflight).
  const ClockOffset& offset(const std::string& host) const;
  /// Prints the offsets; in realtime, throws InputError for an offset beyond the bound
  /// (clock_offset.hpp) unless `allow`.
  void check_offsets(double base_step_s, bool realtime, bool allow) const;
  /// Starts the processes everywhere: their lines go to `relay` as <host>/<process>; a host
  /// lost (its session ends, or its share fails) sets `stop` and failure().
  void start(LogRelay& relay, int local_processes, std::atomic<bool>& stop);
  /// "h1 4/4, h2 3/3 (0.4 ms), h3 lost": the per-host part of the status line.
  std::string health() const;
  /// Why the run must end ("" while every host is fine).
  std::string failure() const;
  /// Closes every session and waits (up to `grace_s`) for each share to stop its processes
  /// and exit, then kills what is left of the sessions. Idempotent.
  void stop(double grace_s = 15.0);
  /// launch.json's "hosts": address, ssh destination, clock offset, preflight time, state.
  nlohmann::ordered_json report() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// What this command line gives the other hosts, and how to reach them.
struct RemoteLaunchArgs {
  std::string scenario_file, ssh_config, out, dds, qos_file;
  std::vector<std::string> sets, vendors, externals;
  std::vector<std::string> clock_injections;  ///< --inject-clock-offset HOST=SECONDS (tests)
  int domain = 0;
  double timeout = 10.0;
  bool allow_clock_offset = false;
};

/// Preflight of one command over many hosts: this host's address on an interface, then every
/// host of `hosts` (RemoteShares::preflight) and their clock offsets (check_offsets). Throws
/// InputError (exit 2) naming the host; nothing has started anywhere then.
std::unique_ptr<RemoteShares> preflight_hosts(const scenario::Scenario& sc, const std::string& local_host,
                                              const std::string& local_address, const std::vector<std::string>& hosts,
                                              const RemoteLaunchArgs& args, const std::string& version,
                                              const std::string& digest);

}  // namespace plexus::cli
