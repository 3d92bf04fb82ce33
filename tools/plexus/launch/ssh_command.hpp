// The ssh command line `plexus launch` uses to start a host's share: plain OpenSSH, the
// user's keys, ports and jump hosts from their ssh config (or --ssh-config FILE), no
// password prompt (BatchMode), keepalives so a dead link ends the session.
#pragma once

#include <string>
#include <vector>

#include "plexus/scenario/scenario.hpp"

namespace plexus::cli {

struct SshOptions {
  std::string config_file;     ///< ssh -F FILE (empty: the user's ~/.ssh/config)
  int connect_timeout_s = 10;  ///< ssh ConnectTimeout
  int alive_interval_s = 1;    ///< ServerAliveInterval: probes the link every second
  int alive_count_max = 3;     ///< ServerAliveCountMax: a link silent for 3 probes is dead
};

/// Single-quotes `s` for a POSIX shell (the remote login shell runs the command).
std::string shell_quote(const std::string& s);

/// The command the remote shell runs: `cd WORKDIR && exec PLEXUS launch --remote`.
/// `local_plexus` is the plexus used when the host names none (the same path as here).
std::string remote_launch_command(const scenario::Scenario::HostAccess& access, const std::string& local_plexus);

/// ssh's arguments (after the program name) to run `remote_command` on `destination`.
std::vector<std::string> ssh_arguments(const SshOptions& o, const std::string& destination,
                                       const std::string& remote_command);

}  // namespace plexus::cli
