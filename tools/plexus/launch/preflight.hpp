// What `plexus launch` checks on every host before anything starts (docs/distributed.md,
// "One command, many hosts"): the hosts are complete, each host's address is on one of its
// interfaces, and every host resolves the scenario to the same digest.
#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

#include "plexus/scenario/scenario.hpp"

namespace plexus::cli {

/// The hosts one command starts over ssh: every host but the first (where the command
/// runs, with the clock). Throws InputError when a host lacks an `address` or, past the
/// first, an `ssh` destination.
std::vector<std::string> ssh_hosts(const scenario::Scenario& sc);

/// True when some host names an ssh destination: `plexus launch SCENARIO` without --host
/// then starts the whole system from the first host.
bool uses_ssh(const scenario::Scenario& sc);

/// FNV-1a 64 (16 hex digits) of the scenario as resolved here (after --set, with derived
/// seeds written in) and of the QoS profiles file this host uses: two hosts with the same
/// digest build the same components with the same parameters and QoS.
std::string scenario_digest(const scenario::Scenario& sc, const std::string& qos_file);

/// True when `address` (IPv4 or IPv6) is assigned to an interface of this machine.
bool address_on_interface(const std::string& address);

/// Processes of this machine whose parent is this process, not counting `except` (the
/// launcher's ssh sessions): the per-host health count.
int running_children(const std::vector<pid_t>& except = {});

}  // namespace plexus::cli
