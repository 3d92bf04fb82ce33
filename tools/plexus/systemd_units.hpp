// `plexus deploy units`: systemd unit files that start one host's share of a scenario at
// boot, without plexus launch. One service unit per process of the host (the process plexus
// launch would start there, in realtime, running until stopped) and a target that groups them.
// Installing them on a robot: docs/deployment.md.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "plexus/scenario/scenario.hpp"

namespace plexus::cli {

struct UnitOptions {
  std::string host;        ///< the scenario's host (empty: a scenario without hosts)
  std::string bin_dir;     ///< where the plexus executables are on the robot (absolute)
  std::string config_dir;  ///< where the processes' part files and qos.yaml go on the robot (absolute)
  std::string dds;         ///< vendor of processes without a `dds` key (empty: dds.vendor, else fast)
  std::map<std::string, std::string> vendor_of;  ///< --vendor PROCESS=V
  int domain = -1;                               ///< -1: the scenario's
};

/// A file to write: its name in the output folder and its text.
struct UnitFile {
  std::string name;
  std::string text;
};

struct UnitSet {
  std::string target;            ///< plexus-<scenario>-<host>.target
  std::vector<UnitFile> units;   ///< the services, then the target
  std::vector<UnitFile> config;  ///< <process>.yaml: each process's part, run until stopped
};

/// Throws InputError for an unknown host or process, or a scenario with no process there.
UnitSet make_units(const scenario::Scenario& sc, const UnitOptions& o);

/// A unit-name-safe form of `s`: letters, digits, '_', '.' and '-' kept, anything else '-'.
std::string unit_word(const std::string& s);

/// One ExecStart= argument, quoted for systemd when needed (spaces, quotes, '%', '$').
std::string exec_argument(const std::string& s);

}  // namespace plexus::cli
