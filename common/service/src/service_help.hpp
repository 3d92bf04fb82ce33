// The part of a service executable's --help that says what it runs: each component type it
// hosts, with its one-line summary and the typed topics it reads and writes, so that a user
// learns a service's contract from the program itself (docs/topics.md has the full one).
#pragma once

#include <string>

#include "plexus/scenario/registry.hpp"

namespace plexus::scenario {

/// From the service's declaration: a plant-side service lists the example robots of
/// deploy/params/*_robot.yaml, a host says it hosts any type, any other service lists its
/// component types. Topics are listed as built from the type's example parameters
/// (deploy/params/<type>.yaml, else none) for robot r1.
std::string hosted_help(const ServiceDeclaration& service);

}  // namespace plexus::scenario
