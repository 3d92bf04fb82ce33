// The body of every service executable (service_main.cpp), compiled once; each executable's
// main() (service_entry.cpp) passes its own name, which decides what it may host.
#pragma once

#include <string>

namespace plexus::service {

/// Parses the command line of the service executable `self` (plant_simulator,
/// localisation_observer, ..., component_host), builds the components it hosts and runs them;
/// returns the process's exit code (0, 1 for a failed run, 2 for bad input).
int run_service(int argc, char** argv, const std::string& self);

}  // namespace plexus::service
