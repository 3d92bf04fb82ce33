// The command line of `plexus launch` (cmd_launch.cpp registers it with CLI11).
#pragma once

#include <string>
#include <vector>

namespace plexus::cli {

struct LaunchOptions {
  std::string scenario;
  std::vector<std::string> sets;
  std::vector<std::string> vendors;    // PROCESS=VENDOR
  std::vector<std::string> kills;      // PROCESS@SECONDS (fault injection, realtime)
  std::vector<std::string> externals;  // processes provided from outside (replay, hardware bridge)
  std::string dds, out, qos_file, host, record;
  std::string transport;  // --transport: dds.transport of the scenario, overridden (travels as a --set)
  std::string naming;     // --naming: dds.naming of the scenario, overridden (travels as a --set)
  int domain = -1;
  int foxglove = 0;  // --foxglove PORT: foxglove_bridge beside the run on 127.0.0.1:PORT (0: none)
  int monitor = 0;   // --monitor PORT: the run's live page on http://127.0.0.1:PORT/ (0: none)
  double timeout = 10.0;
  bool json = false, quiet = false, report = false;
  bool strict = false;  // --strict: a loop that cannot fit its timing budget ends the run (exit 2)
  // Hosts over ssh (remote_share.hpp): --ssh-config, --allow-clock-offset; --remote is the
  // share a launcher started over ssh; --inject-clock-offset HOST=SECONDS fakes an offset (tests).
  std::string ssh_config;
  bool allow_clock_offset = false, remote = false;
  std::vector<std::string> clock_injections;
};

/// `plexus launch`: plan, preflight, start, run, summarise (stages.hpp). Returns the exit
/// code; bad input throws InputError (exit 2).
int run_launch(LaunchOptions o);

}  // namespace plexus::cli
