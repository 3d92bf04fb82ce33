// An input port's fields as the algorithms' types, shared by the services that read
// positions and poses.
#pragma once

#include <Eigen/Core>

#include "plexus/algorithms/skid_steer/icr_kinematics.hpp"
#include "plexus/scenario/component.hpp"

namespace plexus::scenario {

/// Fields 0 and 1 ({x, y}) as a vector.
inline Eigen::Vector2d vec2(const InputPort& in) { return {in[0], in[1]}; }

/// Fields 0..2 ({x, y, theta}) as a pose.
inline algorithms::Pose2 pose_of(const InputPort& in) { return {in[0], in[1], in[2]}; }

}  // namespace plexus::scenario
