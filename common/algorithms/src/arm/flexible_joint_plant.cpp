#include "plexus/algorithms/arm/flexible_joint_plant.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/Geometry>

#include "plexus/algorithms/core/validation.hpp"

namespace plexus::algorithms {

FlexibleJointArmPlant::FlexibleJointArmPlant(const FlexibleJointArmParams& params)
    : params_(params), n_(params.model.dof()), dyn_(params.model) {
  validation::require_positive("flexible_joint_arm", "max_substep", params.max_substep);
  if (params.torque_limit.size() != 0) {
    if (params.torque_limit.size() != n_) {
      validation::fail("flexible_joint_arm", "torque_limit size", "the joint count " + std::to_string(n_),
                       static_cast<double>(params.torque_limit.size()));
    }
    for (int i = 0; i < n_; ++i) {
      validation::require_positive("flexible_joint_arm", "torque_limit[" + std::to_string(i) + "]",
                                   params.torque_limit(i));
    }
  }
  k_.resize(n_), j_.resize(n_), f_.resize(n_);
  for (int i = 0; i < n_; ++i) {
    const ArmJoint& jt = params_.model.joints[static_cast<std::size_t>(i)];
    k_(i) = jt.stiffness, j_(i) = jt.motor_inertia, f_(i) = jt.friction;
  }
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n_);
  state_ = {zero, zero, zero, zero};
  for (Eigen::VectorXd* v : {&x_, &k1_, &k2_, &k3_, &k4_, &tmp_}) *v = Eigen::VectorXd::Zero(4 * n_);
  u_total_ = u_applied_ = q_ = qd_ = tau_ = qdd_ = zero;
  mass_ = Eigen::MatrixXd::Zero(n_, n_);
}

void FlexibleJointArmPlant::reset(const FlexibleJointArmState& s) {
  if (s.q.size() != n_ || s.qd.size() != n_ || s.phi.size() != n_ || s.phid.size() != n_) {
    validation::fail("flexible_joint_arm", "state size", "the number of joints " + std::to_string(n_),
                     static_cast<double>(s.q.size()));
  }
  state_ = s;
}

void FlexibleJointArmPlant::reset_at_rest(const Eigen::VectorXd& q) { reset_in_motion(q, Eigen::VectorXd::Zero(n_)); }

void FlexibleJointArmPlant::reset_in_motion(const Eigen::VectorXd& q, const Eigen::VectorXd& qd) {
  if (q.size() != n_ || qd.size() != n_) {
    validation::fail("flexible_joint_arm", "state size", "the number of joints " + std::to_string(n_),
                     static_cast<double>(q.size() != n_ ? q.size() : qd.size()));
  }
  FlexibleJointArmState s{q, qd, q, qd};
  Eigen::VectorXd bias(n_);
  dyn_.bias(q, qd, bias);  // C(q, q') q' + G(q): the spring torque that gives q'' = 0
  s.phi = q + bias.cwiseQuotient(k_);
  reset(s);
}

void FlexibleJointArmPlant::derivative(const Eigen::VectorXd& x, const Eigen::VectorXd& u, Eigen::VectorXd& dx) {
  // x = [q, q', phi, phi'];  tau = K (phi - q)                          (paper 004, eq. (17))
  q_ = x.segment(0, n_);
  qd_ = x.segment(n_, n_);
  tau_ = k_.cwiseProduct(x.segment(2 * n_, n_) - q_);
  dyn_.forward_dynamics(q_, qd_, tau_, qdd_);  // M q'' + C q' + G = tau  (eq. (24))
  dx.segment(0, n_) = qd_;
  dx.segment(n_, n_) = qdd_;
  dx.segment(2 * n_, n_) = x.segment(3 * n_, n_);
  // J phi'' = u + u_d - F phi' - tau                                    (eq. (16))
  dx.segment(3 * n_, n_) = (u - f_.cwiseProduct(x.segment(3 * n_, n_)) - tau_).cwiseQuotient(j_);
}

void FlexibleJointArmPlant::step(const Eigen::VectorXd& u, double dt) { step(u, no_disturbance_, dt); }

void FlexibleJointArmPlant::step(const Eigen::VectorXd& u, const Eigen::VectorXd& u_d, double dt) {
  if (!(dt > 0.0) || !u.allFinite()) return;
  u_applied_ = u;
  if (params_.torque_limit.size() == n_)
    u_applied_ = u_applied_.cwiseMax(-params_.torque_limit).cwiseMin(params_.torque_limit);
  u_total_ = u_applied_;
  if (u_d.size() == n_) u_total_ += u_d;
  const int substeps = std::max(1, static_cast<int>(std::ceil(dt / params_.max_substep - 1e-9)));
  const double h = dt / substeps;
  x_ << state_.q, state_.qd, state_.phi, state_.phid;
  for (int s = 0; s < substeps; ++s) {
    derivative(x_, u_total_, k1_);
    tmp_ = x_ + 0.5 * h * k1_;
    derivative(tmp_, u_total_, k2_);
    tmp_ = x_ + 0.5 * h * k2_;
    derivative(tmp_, u_total_, k3_);
    tmp_ = x_ + h * k3_;
    derivative(tmp_, u_total_, k4_);
    x_ += (h / 6.0) * (k1_ + 2.0 * k2_ + 2.0 * k3_ + k4_);
  }
  state_.q = x_.segment(0, n_);
  state_.qd = x_.segment(n_, n_);
  state_.phi = x_.segment(2 * n_, n_);
  state_.phid = x_.segment(3 * n_, n_);
}

void FlexibleJointArmPlant::spring_torque(Eigen::VectorXd& tau) const { tau = k_.cwiseProduct(state_.phi - state_.q); }

double FlexibleJointArmPlant::energy() {
  dyn_.mass_matrix(state_.q, mass_);
  const double kinetic = 0.5 * state_.qd.dot(mass_ * state_.qd) + 0.5 * state_.phid.dot(j_.cwiseProduct(state_.phid));
  const Eigen::VectorXd stretch = state_.phi - state_.q;
  const double spring = 0.5 * stretch.dot(k_.cwiseProduct(stretch));
  // Gravity potential: -sum m_i g . p_com_i, with the centres of mass from the chain's forward kinematics.
  Eigen::Matrix3d r = Eigen::Matrix3d::Identity();
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  double potential = 0.0;
  const ArmModel& m = params_.model;
  for (int i = 0; i < n_; ++i) {
    const ArmLink& l = m.links[static_cast<std::size_t>(i)];
    if (i > 0) {
      const ArmLink& prev = m.links[static_cast<std::size_t>(i - 1)];
      p += r * Eigen::Vector3d(prev.length, 0.0, 0.0);
      r = r * Eigen::AngleAxisd(prev.twist, Eigen::Vector3d::UnitX()).toRotationMatrix();
    }
    r = r * Eigen::AngleAxisd(state_.q(i), Eigen::Vector3d::UnitZ()).toRotationMatrix();
    potential -= l.mass * m.gravity.dot(p + r * Eigen::Vector3d(l.com, 0.0, 0.0));
    if (i + 1 == n_) potential -= m.payload_mass * m.gravity.dot(p + r * Eigen::Vector3d(l.length, 0.0, 0.0));
  }
  return kinetic + spring + potential;
}

}  // namespace plexus::algorithms
