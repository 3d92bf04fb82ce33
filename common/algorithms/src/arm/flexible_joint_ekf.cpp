#include "plexus/algorithms/arm/flexible_joint_ekf.hpp"

#include <string>

#include "plexus/algorithms/core/validation.hpp"

namespace plexus::algorithms {
namespace {
constexpr const char* kWhereFlexibleJointEkf = "flexible_joint_ekf";
}

FlexibleJointEkfParams FlexibleJointEkfParams::paper() { return {}; }

FlexibleJointEkfParams FlexibleJointEkfParams::robust() {
  // docs/algorithms/arm.md "Model error": the tip mass absorbs a payload (and most of a mass
  // error) as a constant, the disturbance torque the rest; values from the sweep there.
  FlexibleJointEkfParams p;
  p.disturbance = true;
  p.q_disturbance = 3e6;
  p.payload = true;
  p.q_payload = 1e4;
  p.p0_payload = 1e3;
  return p;
}

FlexibleJointEkf::FlexibleJointEkf(const FlexibleJointEkfParams& p)
    : params_(p),
      n_(p.model.dof()),
      m_((p.disturbance ? 5 : 4) * n_ + (p.payload ? 1 : 0)),
      ipay_((p.disturbance ? 3 : 2) * n_),
      iphi_(m_ - 2 * n_),
      dyn_(p.model) {
  validation::require_positive(kWhereFlexibleJointEkf, "q", p.q);
  validation::require_positive(kWhereFlexibleJointEkf, "r", p.r);
  validation::require_positive(kWhereFlexibleJointEkf, "p0", p.p0);
  if (p.substeps < 1) validation::fail(kWhereFlexibleJointEkf, "substeps", ">= 1", p.substeps);
  validation::require_positive(kWhereFlexibleJointEkf, "step", p.step);
  validation::require_positive(kWhereFlexibleJointEkf, "accel_filter_hz", p.accel_filter_hz);
  validation::require_positive(kWhereFlexibleJointEkf, "fd_step", p.fd_step);
  if (p.disturbance) validation::require_positive(kWhereFlexibleJointEkf, "q_disturbance", p.q_disturbance);
  if (p.q_tau_rate != 0.0) validation::require_positive(kWhereFlexibleJointEkf, "q_tau_rate", p.q_tau_rate);
  if (p.payload) validation::require_positive(kWhereFlexibleJointEkf, "q_payload", p.q_payload);
  if (p.payload) validation::require_positive(kWhereFlexibleJointEkf, "p0_payload", p.p0_payload);
  k_.resize(n_), j_.resize(n_), f_.resize(n_);
  for (int i = 0; i < n_; ++i) {
    const ArmJoint& jt = p.model.joints[static_cast<std::size_t>(i)];
    k_(i) = jt.stiffness, j_(i) = jt.motor_inertia, f_(i) = jt.friction;
  }
  const int m = m_;
  qdiag_ = Vector::Constant(m, p.q);
  if (p.q_tau_rate > 0.0) qdiag_.segment(n_, n_).setConstant(p.q_tau_rate);
  if (p.disturbance) qdiag_.segment(2 * n_, n_).setConstant(p.q_disturbance);
  if (p.payload) qdiag_(ipay_) = p.q_payload;
  yp_ = Vector::Zero(n_);
  d_ = Vector::Zero(n_);
  for (Vector* v : {&x_, &k1_, &k2_, &k3_, &k4_, &xt_, &pass_x_}) *v = Vector::Zero(m);
  for (Matrix* a : {&p_, &fjac_, &p1_, &p2_, &p3_, &p4_, &pt_, &tmp_}) *a = Matrix::Zero(m, m);
  for (Vector* v : {&q_, &qd_, &qdd_, &qdd_plus_, &qdd_minus_, &tau_, &qp_, &jq_, &jqd_, &jtau_}) *v = Vector::Zero(n_);
  innovation_ = y_prev_ = Vector::Zero(2 * n_);
  minv_ = a_ = b_ = did_q_ = did_qd_ = Matrix::Zero(n_, n_);
  fb_ = ArmFeedback::zero(n_);
  accel_.configure(n_, p.accel_filter_hz, p.step);
  reset(Vector::Zero(m));
}

void FlexibleJointEkf::reset(const Vector& x0) {
  if (x0.size() != 4 * n_ && x0.size() != m_) {
    validation::fail(kWhereFlexibleJointEkf, "x0 size",
                     "4 n = " + std::to_string(4 * n_) + (m_ != 4 * n_ ? " or " + std::to_string(m_) : ""),
                     static_cast<double>(x0.size()));
  }
  if (x0.size() == m_) {
    x_ = x0;
  } else {
    x_.setZero();
    x_.head(2 * n_) = x0.head(2 * n_);
    x_.tail(2 * n_) = x0.tail(2 * n_);
  }
  p_ = params_.p0 * Matrix::Identity(m_, m_);
  if (params_.payload) p_(ipay_, ipay_) = params_.p0_payload;
  accel_.reset();
  has_y_prev_ = false;
  link_state(x_);
  fb_.q = q_, fb_.qd = qd_, fb_.qdd.setZero(), fb_.qddd.setZero();
  fb_.tau = x_.segment(0, n_), fb_.taud = x_.segment(n_, n_);
  fb_.phi = x_.segment(iphi_, n_), fb_.phid = x_.segment(iphi_ + n_, n_);
  if (params_.disturbance) d_ = x_.segment(2 * n_, n_);
}

void FlexibleJointEkf::link_state(const Vector& x) {
  // Eq. (17): q = phi - K^{-1} tau, q' = phi' - K^{-1} tau'; tau_ = tau + d drives the links.
  q_ = x.segment(iphi_, n_) - x.segment(0, n_).cwiseQuotient(k_);
  qd_ = x.segment(iphi_ + n_, n_) - x.segment(n_, n_).cwiseQuotient(k_);
  tau_ = x.segment(0, n_);
  if (params_.disturbance) tau_ += x.segment(2 * n_, n_);
  if (params_.payload) dyn_.set_extra_payload(x(ipay_));
}

void FlexibleJointEkf::model_pass(const Vector& x) {
  // The forward dynamics at x, unless the last pass of dyn_ was at this very x (the Jacobian
  // and the first RK4 stage of an update, and the feedback of the previous update, share it).
  link_state(x);
  if (pass_valid_ && x == pass_x_) return;
  dyn_.forward_dynamics(q_, qd_, tau_, qdd_);
  pass_x_ = x;
  pass_valid_ = true;
}

void FlexibleJointEkf::dynamics(const Vector& x, const Vector& u, Vector& dx) {
  model_pass(x);
  // phi'' = J^{-1} (u - tau - F phi'), stored in the phi' rows, then tau'' = K (phi'' - q'') (eq. (35)).
  const int ip = iphi_, iv = iphi_ + n_;
  dx.segment(iv, n_) = (u - x.segment(0, n_) - f_.cwiseProduct(x.segment(iv, n_))).cwiseQuotient(j_);
  dx.segment(n_, n_) = k_.cwiseProduct(dx.segment(iv, n_) - qdd_);
  dx.segment(0, n_) = x.segment(n_, n_);
  dx.segment(ip, n_) = x.segment(iv, n_);
  if (params_.disturbance) dx.segment(2 * n_, n_).setZero();  // d' = 0 (a random walk)
  if (params_.payload) dx(ipay_) = 0.0;                       // m_p' = 0
}

void FlexibleJointEkf::link_jerk(const Vector& x) {
  // Header comment: q''' = M^{-1} (tau' - dID(q', q'')), at the forward-dynamics pass of
  // dynamics(x) (q_, qd_, qdd_ hold the link state of x; d' = 0).
  dyn_.tangent(qd_, qdd_, qdd_plus_);
  qdd_minus_ = x.segment(n_, n_) - qdd_plus_;
  fb_.qddd = dyn_.mass_factor().solve(qdd_minus_);
}

void FlexibleJointEkf::jacobian(const Vector& x, const Vector& /*u*/, Matrix& f) {
  const int n = n_;
  f.setZero();
  model_pass(x);
  minv_ = dyn_.mass_factor().solve(Matrix::Identity(n, n));
  a_.setZero();
  b_.setZero();
  if (params_.jacobian == EkfJacobian::kFull) {
    // A = dq''/dq = -M^{-1} dID/dq, B = dq''/dq' = -M^{-1} dID/dq' (exact tangents).
    dyn_.derivatives(did_q_, did_qd_);
    a_.noalias() = -minv_ * did_q_;
    b_.noalias() = -minv_ * did_qd_;
  }
  if (params_.payload) {
    dyn_.payload_regressor(yp_);
    qp_.noalias() = minv_ * yp_;  // -dq''/dm_p
    for (int i = 0; i < n; ++i) f(n + i, ipay_) = k_(i) * qp_(i);
  }
  const int ip = iphi_, iv = iphi_ + n;
  for (int i = 0; i < n; ++i) {
    f(i, n + i) = 1.0;                          // d tau / d tau'
    f(ip + i, iv + i) = 1.0;                    // d phi / d phi'
    f(iv + i, i) = -1.0 / j_(i);                // d phi'' / d tau
    f(iv + i, iv + i) = -f_(i) / j_(i);         // d phi'' / d phi'
    f(n + i, iv + i) = -k_(i) * f_(i) / j_(i);  // K d phi'' / d phi'
    f(n + i, i) = -k_(i) / j_(i);               // K d phi'' / d tau
    for (int c = 0; c < n; ++c) {
      // -K dq''/d(.) through tau directly (M^{-1}) and through q = phi - tau/K, q' = phi' - tau'/K.
      f(n + i, c) += -k_(i) * minv_(i, c) + k_(i) * a_(i, c) / k_(c);
      f(n + i, n + c) += k_(i) * b_(i, c) / k_(c);
      f(n + i, ip + c) += -k_(i) * a_(i, c);
      f(n + i, iv + c) += -k_(i) * b_(i, c);
      if (params_.disturbance) f(n + i, 2 * n + c) = -k_(i) * minv_(i, c);  // -K dq''/dd
    }
  }
}

namespace {

/// The Riccati right-hand side of riccati() below at compile-time sizes: N joints, M states
/// (the measured phi, phi' last). The same operations in the same order on fixed-size Eigen
/// maps of the same storage, so Eigen unrolls the small products instead of looping over
/// runtime sizes.
template <int N, int M>
void riccati_fixed(const Eigen::MatrixXd& p_in, const Eigen::MatrixXd& f_in, const Eigen::VectorXd& qdiag, double gain,
                   Eigen::MatrixXd& tmp_out, Eigen::MatrixXd& dp_out) {
  using Mat = Eigen::Matrix<double, M, M>;
  constexpr int kPhi = M - 2 * N, kPhiRate = M - N;
  const Eigen::Map<const Mat> p(p_in.data());
  const Eigen::Map<const Mat> f(f_in.data());
  Eigen::Map<Mat> tmp(tmp_out.data());
  Eigen::Map<Mat> dp(dp_out.data());
  tmp.setZero();
  tmp.template topRows<N>() = p.template middleRows<N>(N);
  tmp.template middleRows<N>(N).noalias() = f.template middleRows<N>(N).lazyProduct(p);
  tmp.template middleRows<N>(kPhi) = p.template middleRows<N>(kPhiRate);
  for (int i = 0; i < N; ++i)
    tmp.row(kPhiRate + i) = f(kPhiRate + i, i) * p.row(i) + f(kPhiRate + i, kPhiRate + i) * p.row(kPhiRate + i);
  dp = tmp + tmp.transpose();
  dp.diagonal() += qdiag;
  dp.noalias() -= gain * p.template rightCols<2 * N>().lazyProduct(p.template bottomRows<2 * N>());
}

}  // namespace

void FlexibleJointEkf::riccati(const Matrix& p, double gain, Matrix& dp) {
  // P' = F P + P F^T + Q - P H^T R^{-1} H P   (eq. (32)-(33)), H = [0 I] selects phi, phi'.
  // F P by rows, from the structure of F (jacobian()): the tau and phi rows of F select the
  // tau' and phi' rows of P, the d and m_p rows are zero, only the tau' rows are dense and
  // the phi' rows have two diagonal blocks. Small products are coefficient-based (Eigen's
  // blocked product costs more than it saves below ~16 x 16). The 2-DoF arm's sizes (the
  // paper's 8 states, the robust tuning's 11) run at compile-time sizes (issue 15 section 6).
  if (n_ == 2 && m_ == 8) return riccati_fixed<2, 8>(p, fjac_, qdiag_, gain, tmp_, dp);
  if (n_ == 2 && m_ == 11) return riccati_fixed<2, 11>(p, fjac_, qdiag_, gain, tmp_, dp);
  const int n = n_, m2 = 2 * n_, ip = iphi_, iv = iphi_ + n_;
  const bool small = m_ <= 24;
  tmp_.setZero();
  tmp_.topRows(n) = p.middleRows(n, n);
  if (small) {
    tmp_.middleRows(n, n).noalias() = fjac_.middleRows(n, n).lazyProduct(p);
  } else {
    tmp_.middleRows(n, n).noalias() = fjac_.middleRows(n, n) * p;
  }
  tmp_.middleRows(ip, n) = p.middleRows(iv, n);
  for (int i = 0; i < n; ++i) {
    tmp_.row(iv + i) = fjac_(iv + i, i) * p.row(i) + fjac_(iv + i, iv + i) * p.row(iv + i);
  }
  dp = tmp_ + tmp_.transpose();
  dp.diagonal() += qdiag_;
  if (small) {
    dp.noalias() -= gain * p.rightCols(m2).lazyProduct(p.bottomRows(m2));
  } else {
    dp.noalias() -= gain * (p.rightCols(m2) * p.bottomRows(m2));
  }
}

void FlexibleJointEkf::update(const Vector& u, const Vector& y, double dt) {
  if (!(dt > 0.0) || u.size() != n_ || y.size() != 2 * n_ || !u.allFinite() || !y.allFinite()) return;
  // First-order hold of the measurement between the previous sample and this one (the
  // continuous y(t) of eq. (31)); the first update holds y.
  if (!has_y_prev_) y_prev_ = y;
  integrate(u, y, dt, 1.0 / params_.r);
  y_prev_ = y;
  has_y_prev_ = true;
  finish(u);
}

void FlexibleJointEkf::predict(const Vector& u, double dt) {
  if (!(dt > 0.0) || u.size() != n_ || !u.allFinite()) return;
  // No measurement over dt: L = 0 in eq. (31), P' = F P + P F^T + Q (R^{-1} = 0 in eq. (32)).
  integrate(u, y_prev_, dt, 0.0);
  // The next update holds y from the prediction's h(x^) (H = [0 I]), not from a sample a
  // period older than its interval.
  y_prev_ = x_.tail(2 * n_);
  has_y_prev_ = true;
  finish(u);
}

void FlexibleJointEkf::integrate(const Vector& u, const Vector& y, double dt, double gain) {
  const int m = 2 * n_;
  const double h = dt / params_.substeps;
  auto observer = [&](const Vector& x, double t, Vector& dx) {
    dynamics(x, u, dx);
    const double a = t / dt;
    innovation_ = (1.0 - a) * y_prev_ + a * y - x.tail(m);
    dx.noalias() += gain * (p_.rightCols(m) * innovation_);  // L (y - h(x)), eq. (31)
  };
  for (int s = 0; s < params_.substeps; ++s) {
    const double t0 = s * h;
    jacobian(x_, u, fjac_);
    observer(x_, t0, k1_);
    xt_ = x_ + 0.5 * h * k1_;
    observer(xt_, t0 + 0.5 * h, k2_);
    xt_ = x_ + 0.5 * h * k2_;
    observer(xt_, t0 + 0.5 * h, k3_);
    xt_ = x_ + h * k3_;
    observer(xt_, t0 + h, k4_);
    riccati(p_, gain, p1_);
    pt_ = p_ + 0.5 * h * p1_;
    riccati(pt_, gain, p2_);
    pt_ = p_ + 0.5 * h * p2_;
    riccati(pt_, gain, p3_);
    pt_ = p_ + h * p3_;
    riccati(pt_, gain, p4_);
    x_ += (h / 6.0) * (k1_ + 2.0 * k2_ + 2.0 * k3_ + k4_);
    p_ += (h / 6.0) * (p1_ + 2.0 * p2_ + 2.0 * p3_ + p4_);
    tmp_ = 0.5 * (p_ + p_.transpose());
    p_ = tmp_;
  }
}

void FlexibleJointEkf::finish(const Vector& u) {
  dynamics(x_, u, k1_);  // also sets q_, qd_ (eq. (17)) and the model's q'' in qdd_
  fb_.q = q_, fb_.qd = qd_;
  const Vector& differentiated = accel_.update(qd_);  // section 4: q'' by a filtered differentiator of q'
  fb_.qdd = params_.acceleration == LinkAcceleration::kModel ? qdd_ : differentiated;
  link_jerk(x_);
  fb_.tau = x_.segment(0, n_), fb_.taud = x_.segment(n_, n_);
  fb_.phi = x_.segment(iphi_, n_), fb_.phid = x_.segment(iphi_ + n_, n_);
  if (params_.disturbance) d_ = x_.segment(2 * n_, n_);
}

}  // namespace plexus::algorithms
