// Dead-reckoning odometry with an ICR kinematic model (paper 001 section 4: the "ICR",
// "GA" and "NS" odometries compared against the true trajectory).
//
// The pose is integrated from track speeds only, with the ICRs given at each step: the
// filter's current estimate (the estimated-ICR model), fixed values (e.g. an offline fit),
// or the no-slip model no_slip_icr(B) = (B/2, -B/2, 0). Integration is exact for speeds
// held over the step (icr_pose_step). No allocation.
#pragma once

#include "plexus/algorithms/skid_steer/icr_kinematics.hpp"

namespace plexus::algorithms {

class IcrOdometry {
 public:
  /// Starts (or restarts) dead reckoning at `pose`.
  void reset(const Pose2& pose) { pose_ = pose; }

  /// Integrates h seconds (> 0) with track speeds u and model `icr` (y_l > y_r). A model
  /// with y_l <= y_r is singular: the step is skipped and false returned.
  bool step(const TrackSpeeds& u, const IcrParams& icr, double h) {
    if (!(icr.y_l > icr.y_r) || !(h > 0.0)) return false;
    pose_ = icr_pose_step(pose_, icr_body_velocity(icr, u), h);
    return true;
  }

  const Pose2& pose() const { return pose_; }

 private:
  Pose2 pose_{};
};

}  // namespace plexus::algorithms
