#include "ssh_command.hpp"

namespace plexus::cli {

std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::string remote_launch_command(const scenario::Scenario::HostAccess& access, const std::string& local_plexus) {
  std::string cmd;
  if (!access.workdir.empty()) cmd = "cd " + shell_quote(access.workdir) + " && ";
  if (access.plexus.empty()) return cmd + "exec " + shell_quote(local_plexus) + " launch --remote";
  // The host's `plexus:` is its plexus executable, or the prefix it is installed in (bin/plexus
  // there): the remote shell tells which.
  return cmd + "P=" + shell_quote(access.plexus) +
         "; if [ -d \"$P\" ]; then P=\"$P/bin/plexus\"; fi; exec \"$P\" launch --remote";
}

std::vector<std::string> ssh_arguments(const SshOptions& o, const std::string& destination,
                                       const std::string& remote_command) {
  std::vector<std::string> a;
  if (!o.config_file.empty()) a.insert(a.end(), {"-F", o.config_file});
  a.insert(a.end(), {"-T", "-o", "BatchMode=yes", "-o", "ConnectTimeout=" + std::to_string(o.connect_timeout_s), "-o",
                     "ServerAliveInterval=" + std::to_string(o.alive_interval_s), "-o",
                     "ServerAliveCountMax=" + std::to_string(o.alive_count_max), "--", destination, remote_command});
  return a;
}

}  // namespace plexus::cli
