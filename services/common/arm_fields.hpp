// Field names of the arm's signals (paper 004; docs/algorithms/arm.md): joint i of a
// field `q` is `q<i>`, i = 1..n. Shared by the arm plant and encoders (plant_simulator),
// the sine reference (component_host) and the joint EKF and controllers (joint_controller).
#pragma once

#include <initializer_list>
#include <string>
#include <vector>

#include "plexus/scenario/signal.hpp"

namespace plexus::scenario {

// The joint messages hold 16 joints (idl/plexus/msg/joint.idl, MAX_JOINTS), and the estimate
// (8 fields per joint) fills a signal of kMaxSignalFields; the algorithms take any n.
constexpr int kMaxScenarioDof = 16;
static_assert(8 * kMaxScenarioDof <= static_cast<int>(kMaxSignalFields));

/// prefix1 .. prefixn.
std::vector<std::string> names(const std::string& prefix, int n);

/// The parts one after the other.
std::vector<std::string> concat(std::initializer_list<std::vector<std::string>> parts);

/// The estimate's fields (LinkJointState): link motion to the jerk, joint torque and rate,
/// motor side.
std::vector<std::string> estimate_fields(int n);

}  // namespace plexus::scenario
