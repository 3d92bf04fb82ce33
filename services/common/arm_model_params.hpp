// The arm model keys (paper 004; docs/algorithms/arm.md), read by the plant (true arm) and
// by every model-based service (their nominal model), all optional:
//   model: paper_2dof | uniform        preset (default paper_2dof: Tables 1-2)
//   dof: n                             for `uniform` (n identical links, 1..4 in scenarios)
//   length, com, mass, inertia_o, twist, motor_inertia, friction, stiffness: lists of n
//                                      numbers overriding the preset, per link / joint
//   gravity: [gx, gy, gz]              m/s^2 in the base frame (default [9.81, 0, 0]: q = 0 hangs)
//   payload_mass                       kg at the tip of the last link (default 0)
#pragma once

#include <string>

#include <Eigen/Core>

#include "plexus/algorithms/arm/arm_model.hpp"
#include "plexus/base/yaml_reader.hpp"

namespace plexus::scenario {

/// Optional list of `n` numbers; `fallback` when absent.
Eigen::VectorXd number_list(const YamlMap& p, const std::string& key, int n, const Eigen::VectorXd& fallback);

/// Overwrites `v` with the optional list `key` of v.size() numbers.
void read_into(const YamlMap& p, const std::string& key, Eigen::VectorXd& v);

/// The arm model from the keys above.
algorithms::ArmModel read_model(const YamlMap& p);

}  // namespace plexus::scenario
