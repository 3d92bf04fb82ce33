// The part of a service executable's --help that says what it runs: each component type it
// hosts, with its one-line summary and the typed topics it reads and writes, so that a user
// learns a service's contract from the program itself (docs/topics.md has the full one).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace plexus::scenario {

/// `types`: the component types the executable hosts (service_catalog.hpp); empty for
/// component_host (any type). `robot_section`: plant_simulator (plants and sensors, listed
/// from the example robots in deploy/params/*_robot.yaml). Topics are listed as built from the
/// type's example parameters (deploy/params/<type>.yaml, else none) for robot r1.
std::string hosted_help(std::string_view program, const std::vector<std::string_view>& types, bool robot_section);

}  // namespace plexus::scenario
