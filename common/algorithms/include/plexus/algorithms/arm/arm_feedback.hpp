// What a joint-space controller of the flexible-joint arm receives each step.
#pragma once

#include <Eigen/Core>

namespace plexus::algorithms {

/// Link- and motor-side feedback (estimated by FlexibleJointEkf, or truth in tests).
struct ArmFeedback {
  Eigen::VectorXd q, qd, qdd;  ///< link side: rad, rad/s, rad/s^2
  Eigen::VectorXd tau, taud;   ///< transmitted torque and its rate: N m, N m/s
  Eigen::VectorXd phi, phid;   ///< motor side: rad, rad/s
  Eigen::VectorXd qddd;        ///< link jerk q''' (rad/s^3): d/dt of M^{-1} (tau - C q' - G)

  static ArmFeedback zero(int n) {
    const Eigen::VectorXd z = Eigen::VectorXd::Zero(n);
    return {z, z, z, z, z, z, z, z};
  }
};

}  // namespace plexus::algorithms
