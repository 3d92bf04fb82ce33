// n-DoF flexible-joint arm plant (Spong's model; paper 004, eqs. (16)-(17), (24)-(25)):
//
//   M(q) q'' + C(q, q') q' + G(q) = tau,        tau = K (phi - q)
//   J phi'' + F phi' + tau = u + u_d
//
// The rigid-body terms come from Orocos KDL (ArmRigidBodyDynamics, true model including
// the payload). Integration: classic RK4 on the 4n-state [q, q', phi, phi'] with the input
// held, sub-stepped so that no sub-step exceeds `max_substep` (default 1e-4 s). The
// stiffest mode of the paper's arm is the joint-2 spring, omega = sqrt(K (1/J + 1/m_eff))
// ~ 212 rad/s, so omega h ~ 0.02 per sub-step: RK4's local error ~ (omega h)^5 / 120 is
// ~ 3e-11 and its amplitude error over 10 s at 1 kHz below 1e-6 (the convergence test
// compares h with h/2). See docs/algorithms/arm.md.
//
// Link-side q, q' are truth (for metrics); a controller sees phi, phi' only (measured by
// a sensor with noise).
#pragma once

#include <Eigen/Core>

#include "plexus/algorithms/arm/arm_model.hpp"
#include "plexus/algorithms/arm/rigid_body_dynamics.hpp"

namespace plexus::algorithms {

struct FlexibleJointArmParams {
  ArmModel model = ArmModel::paper_2dof();  ///< the true arm (payload included)
  double max_substep = 1e-4;                ///< s, > 0: longest RK4 sub-step
  /// Actuator (drive) torque limit per joint, N m, > 0: the motor torque u is clamped to
  /// [-limit, limit] before it acts (u_d, a disturbance, is not). Empty: none (the paper).
  Eigen::VectorXd torque_limit = Eigen::VectorXd();
};

struct FlexibleJointArmState {
  Eigen::VectorXd q, qd;      ///< link side, rad, rad/s
  Eigen::VectorXd phi, phid;  ///< motor side (after the gear), rad, rad/s
};

class FlexibleJointArmPlant {
 public:
  /// Validates the model and max_substep; starts at rest at q = phi = 0.
  explicit FlexibleJointArmPlant(const FlexibleJointArmParams& params);

  int dof() const { return n_; }
  /// Sets the state; phi defaults to the static equilibrium q + K^{-1} tau_g when only q is given.
  void reset(const FlexibleJointArmState& state);
  /// At rest at q with phi = q + K^{-1} G(q) (the springs hold the arm against gravity).
  void reset_at_rest(const Eigen::VectorXd& q);
  /// In steady motion at (q, q'): motors at phi' = q', springs holding C(q, q') q' + G(q), so
  /// q'' = 0 and tau' = 0 at the start. reset_at_rest(q) is reset_in_motion(q, 0).
  void reset_in_motion(const Eigen::VectorXd& q, const Eigen::VectorXd& qd);

  /// Advances by dt seconds with motor torque u (clamped to the torque limit) and
  /// disturbance u_d held. No allocation.
  void step(const Eigen::VectorXd& u, double dt);
  void step(const Eigen::VectorXd& u, const Eigen::VectorXd& u_d, double dt);

  const FlexibleJointArmState& state() const { return state_; }
  /// The motor torque applied during the last step (u after the torque limit).
  const Eigen::VectorXd& applied_torque() const { return u_applied_; }
  /// Transmitted torque tau = K (phi - q).
  void spring_torque(Eigen::VectorXd& tau) const;
  /// Total energy: kinetic (links + motors) + spring + gravity potential (for tests).
  double energy();

  ArmRigidBodyDynamics& dynamics() { return dyn_; }

 private:
  void derivative(const Eigen::VectorXd& x, const Eigen::VectorXd& u, Eigen::VectorXd& dx);

  FlexibleJointArmParams params_;
  int n_;
  ArmRigidBodyDynamics dyn_;
  Eigen::VectorXd k_, j_, f_;
  FlexibleJointArmState state_;
  Eigen::VectorXd no_disturbance_;
  Eigen::VectorXd x_, k1_, k2_, k3_, k4_, tmp_, u_total_, u_applied_;
  Eigen::VectorXd q_, qd_, tau_, qdd_;
  Eigen::MatrixXd mass_;
};

}  // namespace plexus::algorithms
