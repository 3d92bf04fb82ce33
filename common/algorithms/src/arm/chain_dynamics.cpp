#include "plexus/algorithms/arm/chain_dynamics.hpp"

#include <cmath>

namespace plexus::algorithms {
namespace {

constexpr int kAngular = 5;  // Z = [0 0 0 0 0 1]^T: the joint axis is z of {B_i}

/// crm(Z) x = [z x x_v; z x x_w] and crf(Z) f (the same for Z = [0; z]).
spatial::Vector6 cross_z(const spatial::Vector6& x) {
  spatial::Vector6 out;
  out << -x(1), x(0), 0.0, -x(4), x(3), 0.0;
  return out;
}

}  // namespace

ArmChainDynamics::ArmChainDynamics(const ArmModel& model) : n_(model.dof()) {
  model.validate();
  links_.resize(static_cast<std::size_t>(n_));
  for (int i = 0; i < n_; ++i) {
    const ArmLink& l = model.links[static_cast<std::size_t>(i)];
    Link& k = links_[static_cast<std::size_t>(i)];
    spatial::Vector13 theta =
        spatial::link_parameters(l.mass, Eigen::Vector3d(l.com, 0.0, 0.0),
                                 Eigen::Vector3d(l.inertia_xx_com(), l.inertia_yy_com(), l.inertia_zz_com()));
    if (i + 1 == n_ && model.payload_mass > 0.0) {
      theta +=
          spatial::link_parameters(model.payload_mass, Eigen::Vector3d(l.length, 0.0, 0.0), Eigen::Vector3d::Zero());
    }
    k.inertia = spatial::spatial_inertia(theta);
    k.from_parent = model.fixed_link_frame(i);
    k.fixed_rotation = k.from_parent.rotation;
    k.composite.setZero();
    k.v.setZero(), k.a.setZero(), k.f.setZero(), k.xv.setZero(), k.xa.setZero(), k.iv.setZero();
    k.dv.setZero(), k.da.setZero(), k.df.setZero();
  }
  const ArmLink& last = model.links.back();
  last_inertia_ = links_.back().inertia;
  unit_point_ = spatial::spatial_inertia(
      spatial::link_parameters(1.0, Eigen::Vector3d(last.length, 0.0, 0.0), Eigen::Vector3d::Zero()));
  base_acceleration_.setZero();
  base_acceleration_.head<3>() = -model.gravity;
  qd_ = qdd_ = h_ = zero_ = unit_ = dtau_ = Eigen::VectorXd::Zero(n_);
  mass_ = Eigen::MatrixXd::Zero(n_, n_);
  llt_ = Eigen::LLT<Eigen::MatrixXd>(n_);
}

void ArmChainDynamics::frames(const Eigen::VectorXd& q) {
  for (int i = 0; i < n_; ++i) {
    Link& k = links_[static_cast<std::size_t>(i)];
    const double c = std::cos(q(i)), s = std::sin(q(i));
    // R = RotX(twist) RotZ(q): columns c x + s y', -s x + c y', z' of RotX.
    const Eigen::Matrix3d& r = k.fixed_rotation;
    k.from_parent.rotation.col(0) = c * r.col(0) + s * r.col(1);
    k.from_parent.rotation.col(1) = -s * r.col(0) + c * r.col(1);
    k.from_parent.rotation.col(2) = r.col(2);
  }
}

void ArmChainDynamics::rnea(const Eigen::VectorXd& qd, const Eigen::VectorXd& qdd, Eigen::VectorXd& tau) {
  // Base -> tip: V_i = U^T V_{i-1} + Z q'_i, A_i = U^T A_{i-1} + crm(V_i) Z q'_i + Z q''_i,
  // F_i = M_i A_i + crf(V_i) M_i V_i; tip -> base: F_{i-1} += U F_i, tau_i = Z^T F_i.
  const spatial::Vector6 zero = spatial::Vector6::Zero();
  for (int i = 0; i < n_; ++i) {
    Link& k = links_[static_cast<std::size_t>(i)];
    const spatial::Vector6& v_parent = i == 0 ? zero : links_[static_cast<std::size_t>(i - 1)].v;
    const spatial::Vector6& a_parent = i == 0 ? base_acceleration_ : links_[static_cast<std::size_t>(i - 1)].a;
    k.xv = spatial::velocity_to_child(k.from_parent, v_parent);
    k.xa = spatial::velocity_to_child(k.from_parent, a_parent);
    k.v = k.xv;
    k.v(kAngular) += qd(i);
    // crm(V) Z q' = q' [v x z; w x z].
    k.a = k.xa;
    k.a(0) += qd(i) * k.v(1), k.a(1) -= qd(i) * k.v(0);
    k.a(3) += qd(i) * k.v(4), k.a(4) -= qd(i) * k.v(3);
    k.a(kAngular) += qdd(i);
    k.iv.noalias() = k.inertia * k.v;
    k.f.noalias() = k.inertia * k.a;
    k.f += spatial::cross_force(k.v, k.iv);
  }
  for (int i = n_ - 1; i >= 0; --i) {
    Link& k = links_[static_cast<std::size_t>(i)];
    tau(i) = k.f(kAngular);
    if (i > 0) links_[static_cast<std::size_t>(i - 1)].f += spatial::force_to_parent(k.from_parent, k.f);
  }
}

void ArmChainDynamics::inverse_dynamics(const Eigen::VectorXd& q, const Eigen::VectorXd& qd, const Eigen::VectorXd& qdd,
                                        Eigen::VectorXd& tau) {
  frames(q);
  qd_ = qd, qdd_ = qdd;
  rnea(qd, qdd, tau);
  pass_has_qdd_ = true;
}

void ArmChainDynamics::mass_matrix(const Eigen::VectorXd& q, Eigen::MatrixXd& m) {
  frames(q);
  for (Link& k : links_) k.composite = k.inertia;
  for (int i = n_ - 1; i >= 0; --i) {
    Link& k = links_[static_cast<std::size_t>(i)];
    spatial::Vector6 f = k.composite.col(kAngular);  // M_c Z
    m(i, i) = f(kAngular);
    for (int j = i; j > 0; --j) {
      f = spatial::force_to_parent(links_[static_cast<std::size_t>(j)].from_parent, f);
      m(i, j - 1) = m(j - 1, i) = f(kAngular);
    }
    if (i == 1) {
      // The base link's composite inertia enters M only through its (Z, Z) entry (m(0, 0) in
      // the next iteration): that entry of U M_c U^T alone, computed as the full product below
      // computes it (the same operations on the same numbers).
      spatial::Vector6 row;  // row Z of U M_c
      for (int c = 0; c < 6; ++c) row(c) = spatial::force_to_parent(k.from_parent, k.composite.col(c))(kAngular);
      links_[0].composite(kAngular, kAngular) += spatial::force_to_parent(k.from_parent, row)(kAngular);
    } else if (i > 1) {
      // M_c,parent += U M_c U^T: U applied to the columns, then to the rows.
      spatial::Matrix6 half;
      for (int c = 0; c < 6; ++c) half.col(c) = spatial::force_to_parent(k.from_parent, k.composite.col(c));
      spatial::Matrix6 full;
      for (int r = 0; r < 6; ++r)
        full.row(r) = spatial::force_to_parent(k.from_parent, half.row(r).transpose()).transpose();
      links_[static_cast<std::size_t>(i - 1)].composite += full;
    }
  }
}

void ArmChainDynamics::forward_dynamics(const Eigen::VectorXd& q, const Eigen::VectorXd& qd, const Eigen::VectorXd& tau,
                                        Eigen::VectorXd& qdd) {
  mass_matrix(q, mass_);  // also sets the frames
  rnea(qd, zero_, h_);    // C q' + G
  llt_.compute(mass_);
  h_ = tau - h_;
  qdd = llt_.solve(h_);
  qd_ = qd, qdd_ = qdd;
  pass_has_qdd_ = false;  // the stored pass is at q'' = 0; tangent() redoes it at q''
}

void ArmChainDynamics::set_extra_payload(double mass) {
  if (mass == extra_payload_) return;
  extra_payload_ = mass;
  links_.back().inertia = last_inertia_ + mass * unit_point_;
}

void ArmChainDynamics::ensure_pass_with_qdd() {
  if (!pass_has_qdd_) {
    rnea(qd_, qdd_, h_);
    pass_has_qdd_ = true;
  }
}

void ArmChainDynamics::payload_regressor(Eigen::VectorXd& y) {
  ensure_pass_with_qdd();
  // F = M_p A_n + crf(V_n) M_p V_n for a unit point mass, carried to the base.
  const Link& tip = links_.back();
  spatial::Vector6 f = unit_point_ * tip.a + spatial::cross_force(tip.v, unit_point_ * tip.v);
  for (int i = n_ - 1; i >= 0; --i) {
    y(i) = f(kAngular);
    if (i > 0) f = spatial::force_to_parent(links_[static_cast<std::size_t>(i)].from_parent, f);
  }
}

void ArmChainDynamics::tangent(const Eigen::VectorXd& dq, const Eigen::VectorXd& dqd, Eigen::VectorXd& dtau) {
  ensure_pass_with_qdd();
  const spatial::Vector6 zero = spatial::Vector6::Zero();
  for (int i = 0; i < n_; ++i) {
    Link& k = links_[static_cast<std::size_t>(i)];
    const spatial::Vector6& dv_parent = i == 0 ? zero : links_[static_cast<std::size_t>(i - 1)].dv;
    const spatial::Vector6& da_parent = i == 0 ? zero : links_[static_cast<std::size_t>(i - 1)].da;
    k.dv = spatial::velocity_to_child(k.from_parent, dv_parent) - dq(i) * cross_z(k.xv);
    k.dv(kAngular) += dqd(i);
    k.da = spatial::velocity_to_child(k.from_parent, da_parent) - dq(i) * cross_z(k.xa);
    // crm(dV) Z q' + crm(V) Z dq'.
    k.da(0) += qd_(i) * k.dv(1) + dqd(i) * k.v(1), k.da(1) -= qd_(i) * k.dv(0) + dqd(i) * k.v(0);
    k.da(3) += qd_(i) * k.dv(4) + dqd(i) * k.v(4), k.da(4) -= qd_(i) * k.dv(3) + dqd(i) * k.v(3);
    const spatial::Vector6 idv = k.inertia * k.dv;
    k.df.noalias() = k.inertia * k.da;
    k.df += spatial::cross_force(k.dv, k.iv) + spatial::cross_force(k.v, idv);
  }
  for (int i = n_ - 1; i >= 0; --i) {
    Link& k = links_[static_cast<std::size_t>(i)];
    dtau(i) = k.df(kAngular);
    if (i > 0) {
      links_[static_cast<std::size_t>(i - 1)].df +=
          spatial::force_to_parent(k.from_parent, k.df + dq(i) * cross_z(k.f));
    }
  }
}

void ArmChainDynamics::derivatives(Eigen::MatrixXd& dtau_dq, Eigen::MatrixXd& dtau_dqd) {
  for (int c = 0; c < n_; ++c) {
    unit_.setZero();
    unit_(c) = 1.0;
    tangent(unit_, zero_, dtau_);
    dtau_dq.col(c) = dtau_;
    tangent(zero_, unit_, dtau_);
    dtau_dqd.col(c) = dtau_;
  }
}

}  // namespace plexus::algorithms
