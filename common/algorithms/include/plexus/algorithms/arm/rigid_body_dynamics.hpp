// Joint-space rigid-body dynamics of the arm's links, computed by Orocos KDL:
//   M(q) q'' + C(q, q') q' + G(q) = tau          (paper 004, eq. (24) left side)
//
// The KDL chain has one segment per link: a RotZ joint, the tip frame
// Frame(RotX(twist), (length, 0, 0)) and the link inertia at (com, 0, 0) with central
// inertia diag(Ixx_c, Iyy_c, Izz_c); the payload is a point mass added at the tip of
// the last segment. KDL's solvers keep references to the chain, so this object is
// neither copyable nor movable (hold it by value or unique_ptr).
//
// All work buffers are allocated in the constructor; the calls below reuse them.
#pragma once

#include <memory>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "plexus/algorithms/arm/arm_model.hpp"

namespace KDL {
class Chain;
}  // namespace KDL

namespace plexus::algorithms {

class ArmRigidBodyDynamics {
 public:
  /// Validates the model (ArmModel::validate) and builds the KDL chain.
  explicit ArmRigidBodyDynamics(const ArmModel& model);
  ~ArmRigidBodyDynamics();
  ArmRigidBodyDynamics(const ArmRigidBodyDynamics&) = delete;
  ArmRigidBodyDynamics& operator=(const ArmRigidBodyDynamics&) = delete;

  int dof() const { return n_; }
  const ArmModel& model() const { return model_; }
  const KDL::Chain& chain() const;

  /// M(q), n x n (KDL ChainDynParam::JntToMass).
  void mass_matrix(const Eigen::VectorXd& q, Eigen::MatrixXd& m);
  /// h = C(q, q') q' + G(q) (KDL recursive Newton-Euler with q'' = 0).
  void bias(const Eigen::VectorXd& q, const Eigen::VectorXd& qd, Eigen::VectorXd& h);
  /// tau = M q'' + C q' + G (KDL recursive Newton-Euler).
  void inverse_dynamics(const Eigen::VectorXd& q, const Eigen::VectorXd& qd, const Eigen::VectorXd& qdd,
                        Eigen::VectorXd& tau);
  /// q'' = M^{-1} (tau - C q' - G) (Cholesky of M).
  void forward_dynamics(const Eigen::VectorXd& q, const Eigen::VectorXd& qd, const Eigen::VectorXd& tau,
                        Eigen::VectorXd& qdd);
  /// After forward_dynamics: the Cholesky factor of the M(q) it used (for M^{-1} products).
  const Eigen::LLT<Eigen::MatrixXd>& last_mass_factor() const { return llt_; }

 private:
  struct Kdl;  // the chain, its solvers and their joint arrays

  ArmModel model_;
  int n_;
  std::unique_ptr<Kdl> kdl_;
  Eigen::MatrixXd mass_;
  Eigen::VectorXd h_;
  Eigen::LLT<Eigen::MatrixXd> llt_;
};

}  // namespace plexus::algorithms
