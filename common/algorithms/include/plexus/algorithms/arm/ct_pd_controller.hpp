// Computed-torque + PD comparator (paper 004, eq. (60); Khosravi & Taghirad 2014):
//
//   u = M(q) q_d'' + C(q, q') q' + G(q) + K_p (q_d - q) + K_v (q_d' - q') + K_d (q' - phi')
//
// The printed (60) writes M q'' (the OCR lost the subscript): computed torque uses the
// desired acceleration q_d''. The rigid-body terms are one KDL recursive Newton-Euler call
// on the nominal model. Paper gains: K_p = diag(1900, 500), K_v = diag(500, 150),
// K_d = diag(110, 110). Note that (60) has no motor-inertia term J q_d''.
//
// Two readings of (60) the text allows (issue 29, docs/algorithms/arm.md "Table 4: the
// set-up"), both off by default:
// - `inertia`: T_m^T M_1 T_m is the links' inertia (kLinks, as we read it), or the rigid
//   equivalent of the flexible arm, links and rotors (kWithMotors: + J q_d'' + F q_d', the
//   motor side of eq. (16) at phi = q);
// - `acceleration`: q_d'' (kDesired, computed torque) or the observer's q'' (kEstimated,
//   (60) exactly as printed).
#pragma once

#include <Eigen/Core>

#include "plexus/algorithms/arm/arm_feedback.hpp"
#include "plexus/algorithms/arm/arm_model.hpp"
#include "plexus/algorithms/arm/rigid_body_dynamics.hpp"
#include "plexus/algorithms/arm/sine_reference.hpp"

namespace plexus::algorithms {

/// Which velocity the K_v term of eq. (60) compares with q_d'.
enum class CtPdVelocity {
  kLink,   ///< eq. (60) as printed: K_v (q_d' - q'). With the paper's gains this loop is
           ///< unstable on the Table 1-2 arm (linearised joint 1: eigenvalue +11.5 1/s).
  kMotor,  ///< K_v (q_d' - phi'): collocated velocity feedback, stable with the same gains.
};

/// What the computed-torque inertia of eq. (60) covers.
enum class CtPdInertia {
  kLinks,       ///< M(q) of the links alone (no J q_d'' term)
  kWithMotors,  ///< the rigid equivalent: + J q_d'' + F q_d' (rotor inertia and friction)
};

/// Which acceleration the computed torque of eq. (60) multiplies by M.
enum class CtPdAcceleration {
  kDesired,    ///< q_d'' (computed torque)
  kEstimated,  ///< the observer's q'' (eq. (60) as printed)
};

struct CtPdParams {
  ArmModel model = ArmModel::paper_2dof();  ///< nominal model
  Eigen::VectorXd k_p, k_v, k_d;            ///< diagonal gains, one per joint, >= 0
  CtPdVelocity velocity = CtPdVelocity::kLink;
  CtPdInertia inertia = CtPdInertia::kLinks;
  CtPdAcceleration acceleration = CtPdAcceleration::kDesired;
  static CtPdParams paper_2dof();
};

class CtPdController {
 public:
  /// Validates the model and the gain sizes and signs.
  explicit CtPdController(const CtPdParams& params);
  int dof() const { return n_; }
  /// u of eq. (60). No allocation.
  const Eigen::VectorXd& step(const ArmReferenceSample& ref, const ArmFeedback& fb);

 private:
  CtPdParams params_;
  int n_;
  ArmRigidBodyDynamics dyn_;
  Eigen::VectorXd u_;
};

}  // namespace plexus::algorithms
