// The balancing robot's keys (paper 002; docs/algorithms/balancing.md), read by the plant
// (the true robot) and, as their model, by the attitude filter and the balancing
// controller: body_mass, com_height, body_inertia, wheel_mass, wheel_radius,
// wheel_inertia, gravity, max_torque (WheeledPendulumParams defaults).
#pragma once

#include "plexus/algorithms/balancing/wheeled_inverted_pendulum.hpp"
#include "plexus/base/yaml_reader.hpp"

namespace plexus::scenario {

/// The robot's parameters from the keys above.
algorithms::WheeledPendulumParams pendulum_params(const YamlMap& p);

}  // namespace plexus::scenario
