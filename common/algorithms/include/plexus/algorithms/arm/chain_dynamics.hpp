// Joint-space rigid-body dynamics of the arm's links for the observer's model, with exact
// derivatives (issue 15 section 6: the EKF's Jacobian by central differences of KDL's forward
// dynamics cost ~20 us a step; docs/algorithms/arm.md "Cost").
//
//   M(q) q'' + C(q, q') q' + G(q) = tau                              (paper 004, eq. (24))
//
// Featherstone's recursive Newton-Euler algorithm (RNEA) and composite-rigid-body algorithm
// (CRBA) (Featherstone, Rigid Body Dynamics Algorithms, 2008, tables 5.1 and 6.2) in the
// link frames {B_i} of the VDC (spatial.hpp: V = [v; w], U transforms, crm / crf), so the
// geometry is the one of arm_model.hpp and the VDC: joint i turns {B_i} about z, {B_i} is
// {T_i} = Frame(RotX(twist_{i-1}), (l_{i-1}, 0, 0)) of link i-1 turned by q_i, gravity
// enters as the base acceleration [-g; 0], the payload is a point mass at (l_n, 0, 0) of the
// last link.
//
// Derivatives: the RNEA's tangent along a direction (dq, dq') at fixed q'' (forward-mode
// differentiation of the recursion, written out):
//   dV_i  = U^T dV_{i-1} - dq_i crm(Z) U^T V_{i-1} + Z dq'_i
//   dA_i  = U^T dA_{i-1} - dq_i crm(Z) U^T A_{i-1} + crm(dV_i) Z q'_i + crm(V_i) Z dq'_i
//   dF_i  = M_i dA_i + crf(dV_i) M_i V_i + crf(V_i) M_i dV_i + sum over the child c of
//           U_c dF_c + dq_c U_c crf(Z) F_c,         dtau_i = Z^T dF_i
// (d/dq of U^T x is -crm(Z) U^T x and of U f is U crf(Z) f, U depending on q_i through
// RotZ(q_i)). With it: dq''/dq = -M^{-1} dID/dq, dq''/dq' = -M^{-1} dID/dq' at q'' = FD,
// and the link jerk q''' = M^{-1} (tau' - dID(q', q'')) exactly.
//
// Checked against KDL (rigid_body_dynamics.hpp) and against finite differences in
// common/algorithms/tests/arm/chain_dynamics_test.cpp. Buffers are sized in the
// constructor; no call allocates.
#pragma once

#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "plexus/algorithms/arm/arm_model.hpp"
#include "plexus/algorithms/arm/spatial.hpp"

namespace plexus::algorithms {

class ArmChainDynamics {
 public:
  /// Validates the model (ArmModel::validate).
  explicit ArmChainDynamics(const ArmModel& model);

  int dof() const { return n_; }

  /// tau = M q'' + C q' + G (RNEA). Keeps the pass for tangent().
  void inverse_dynamics(const Eigen::VectorXd& q, const Eigen::VectorXd& qd, const Eigen::VectorXd& qdd,
                        Eigen::VectorXd& tau);
  /// M(q) (CRBA).
  void mass_matrix(const Eigen::VectorXd& q, Eigen::MatrixXd& m);
  /// q'' = M^{-1} (tau - C q' - G); keeps the RNEA pass at (q, q', q'') for tangent() and
  /// the Cholesky factor of M for mass_factor().
  void forward_dynamics(const Eigen::VectorXd& q, const Eigen::VectorXd& qd, const Eigen::VectorXd& tau,
                        Eigen::VectorXd& qdd);
  /// Directional derivative of the inverse dynamics of the last pass along (dq, dq') at fixed
  /// q'' (header). Call after inverse_dynamics() or forward_dynamics().
  void tangent(const Eigen::VectorXd& dq, const Eigen::VectorXd& dqd, Eigen::VectorXd& dtau);
  /// dID/dq and dID/dq' of the last pass (n x n each: 2n tangents).
  void derivatives(Eigen::MatrixXd& dtau_dq, Eigen::MatrixXd& dtau_dqd);
  /// Changes the tip point mass (kg, any sign: an estimate of the model's error) on top of
  /// the model's payload_mass; cheap (one 6x6 update).
  void set_extra_payload(double mass);
  /// dID/dm of the last pass: the joint torques a unit point mass at the tip needs for the
  /// motion (q, q', q'') (gravity included).
  void payload_regressor(Eigen::VectorXd& y);
  /// Cholesky factor of the M(q) of the last forward_dynamics().
  const Eigen::LLT<Eigen::MatrixXd>& mass_factor() const { return llt_; }

 private:
  struct Link {
    Eigen::Matrix3d fixed_rotation;        ///< RotX(twist of the parent link)
    spatial::Transform from_parent;        ///< {B_{i-1}} -> {B_i} at the current q_i
    spatial::Matrix6 inertia;              ///< M_i about the origin of {B_i} (payload included)
    spatial::Matrix6 composite;            ///< CRBA work
    spatial::Vector6 v, a, f, xv, xa, iv;  ///< V_i, A_i, F_i (with the children), U^T V_{i-1}, U^T A_{i-1}, M_i V_i
    spatial::Vector6 dv, da, df;           ///< tangent work
  };

  void frames(const Eigen::VectorXd& q);
  void rnea(const Eigen::VectorXd& qd, const Eigen::VectorXd& qdd, Eigen::VectorXd& tau);

  void ensure_pass_with_qdd();

  int n_;
  double extra_payload_ = 0.0;
  spatial::Matrix6 last_inertia_, unit_point_;  ///< the last link's model inertia; a unit mass at its tip
  bool pass_has_qdd_ = false;                   ///< the stored pass is at (q, q', q''), not at q'' = 0
  spatial::Vector6 base_acceleration_;          ///< [-g; 0]
  std::vector<Link> links_;
  Eigen::VectorXd qd_, qdd_, h_, zero_, unit_, dtau_;
  Eigen::MatrixXd mass_;
  Eigen::LLT<Eigen::MatrixXd> llt_;
};

}  // namespace plexus::algorithms
