// Discrete extended Kalman filter, fixed-size, allocation-free.
//
// Model (the user supplies f, F, h, H; noise is additive):
//   x_{k+1} = f(x_k) + w_k,   w_k ~ N(0, Q),   F = df/dx at x_k
//   z_k     = h(x_k) + v_k,   v_k ~ N(0, R),   H = dh/dx at x_{k|k-1}
// Predict:  x- = f(x),  P- = F P F^T + Q
// Update:   r = z - h(x-)  (angular components wrapped),  S = H P- H^T + R,
//           K = P- H^T S^-1,  x+ = x- + K r,
//           P+ = (I - K H) P- (I - K H)^T + K R K^T      (Joseph form, default)
//             or (I - K H) P-                           (Options::joseph_form = false)
// After each step P is symmetrised and guarded (keep_symmetric_pd in covariance.hpp):
// eigenvalues are clamped to >= Options::min_eigenvalue if round-off lost definiteness;
// guard_repairs() counts how often that fired.
//
// Inputs and time step are bound by the caller into the model callables, e.g.
//   ekf.predict([&](const auto& x, auto& F) { F = jacobian(x, u, dt); return f(x, u, dt); }, Q);
//   ekf.update(z, [&](const auto& x, auto& H) { H = dhdx(x); return h(x); }, R);
// or the pre-evaluated forms predict(x_pred, F, Q) / update(z, z_pred, H, R).
// The callables must return a plain Eigen object (declare the return type; an `auto`
// lambda returning `A * x + b` hands back an expression over dead temporaries).
//
// Angles: Options::angular_states flags state components that are angles; they are
// wrapped to (-pi, pi] after every step. An update's `angular_measurements` mask
// flags measurement components whose residual z - h is wrapped.
//
// Used by: balancing attitude filter (paper 002), skid-steer ICR filter (paper 001).
#pragma once

#include <cmath>
#include <stdexcept>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "plexus/algorithms/core/covariance.hpp"
#include "plexus/algorithms/core/validation.hpp"

namespace plexus::algorithms {

struct EkfOptions {
  AngularMask angular_states = 0;  ///< bit i: state i is an angle, wrapped to (-pi, pi]
  double min_eigenvalue = 1e-12;   ///< covariance guard floor, finite > 0 (see covariance.hpp)
  bool joseph_form = true;         ///< Joseph-form covariance update (SPD-preserving)
};

template <int N>
class ExtendedKalmanFilter {
  static_assert(N > 0 && N <= 32, "state dimension must be in 1..32 (AngularMask bits)");

 public:
  using State = Eigen::Matrix<double, N, 1>;
  using Covariance = Eigen::Matrix<double, N, N>;
  using Jacobian = Eigen::Matrix<double, N, N>;
  template <int M>
  using Measurement = Eigen::Matrix<double, M, 1>;
  template <int M>
  using MeasurementJacobian = Eigen::Matrix<double, M, N>;

  /// Validates min_eigenvalue (finite, > 0); throws std::invalid_argument. State 0, P = I.
  explicit ExtendedKalmanFilter(const EkfOptions& options = {}) : options_(options) {
    validation::require_positive("ekf", "min_eigenvalue", options.min_eigenvalue);
  }

  /// Sets the estimate. Throws std::invalid_argument if x0 is not finite or P0 is not
  /// symmetric positive definite.
  void reset(const State& x0, const Covariance& P0) {
    if (!x0.allFinite()) throw std::invalid_argument("ekf: x0 must be finite");
    reset_covariance(P0);
    x_ = x0;
    wrap_masked(x_, options_.angular_states);
  }

  /// Replaces the covariance only (e.g. an adaptive reset). Throws std::invalid_argument
  /// if P is not symmetric positive definite.
  void reset_covariance(const Covariance& P) {
    if (!is_symmetric_positive_definite<N>(P)) {
      throw std::invalid_argument("ekf: covariance must be finite, symmetric and positive definite");
    }
    P_ = 0.5 * (P + P.transpose());
  }

  /// Predict with a model callable: `f(const State& x, Jacobian& F) -> State` returns
  /// f(x) and writes F = df/dx(x). Returns false (estimate unchanged) if the result or
  /// Q is not finite.
  template <class Model>
  bool predict(Model&& f, const Covariance& Q) {
    Jacobian F;
    const State x_pred = f(static_cast<const State&>(x_), F);
    return predict(x_pred, F, Q);
  }

  /// Predict with a pre-evaluated model: x- = x_pred, P- = F P F^T + Q.
  bool predict(const State& x_pred, const Jacobian& F, const Covariance& Q) {
    if (!x_pred.allFinite() || !F.allFinite() || !Q.allFinite()) return false;
    x_ = x_pred;
    wrap_masked(x_, options_.angular_states);
    P_ = F * P_ * F.transpose() + Q;
    guard();
    return true;
  }

  /// Predict with a Jacobian that is the identity below its first K rows (states K..N-1 are
  /// random walks, f_i(x) = x_i): F = [F_top; 0 I]. Same covariance as predict(x_pred, F, Q)
  /// up to rounding, with about a third of the products:
  ///   T = F_top P (K x N);  P-[0:K, 0:K] = T F_top^T,  P-[0:K, K:] = T[:, K:],
  ///   P-[K:, 0:K] = T[:, K:]^T,  P-[K:, K:] = P[K:, K:];  then + Q.
  template <int K>
  bool predict_partial(const State& x_pred, const Eigen::Matrix<double, K, N>& F_top, const Covariance& Q) {
    if (!Q.allFinite()) return false;
    if (!propagate_partial<K>(x_pred, F_top)) return false;
    P_ += Q;
    guard();
    return true;
  }
  /// The same with a diagonal Q = diag(q).
  template <int K>
  bool predict_partial(const State& x_pred, const Eigen::Matrix<double, K, N>& F_top, const State& q) {
    if (!q.allFinite()) return false;
    if (!propagate_partial<K>(x_pred, F_top)) return false;
    P_.diagonal() += q;
    guard();
    return true;
  }

  /// Update with a direct measurement of M consecutive states: h(x) = x[first .. first+M-1],
  /// H = [0 I 0]. The same update as update(z, z_pred, H, R) (Joseph form or not, as the
  /// options say) up to rounding, with H's structure used instead of multiplied by:
  ///   P H^T = P[:, first..],  S = P[first.., first..] + R,  K = P H^T S^-1,
  ///   Joseph: A P = P - K P[first.., :],  A P A^T + K R K^T = A P + (K R - (A P)[:, first..]) K^T.
  template <int M>
  bool update_segment(const Measurement<M>& z, int first, const Eigen::Matrix<double, M, M>& R,
                      AngularMask angular_measurements = 0) {
    static_assert(M > 0 && M <= N, "1..N measured states");
    if (first < 0 || first + M > N) throw std::invalid_argument("ekf: measured states outside the state");
    const Measurement<M> z_pred = x_.template segment<M>(first);
    if (!z.allFinite() || !R.allFinite()) return false;
    const Measurement<M> r = masked_difference(z, z_pred, angular_measurements);
    const Eigen::Matrix<double, N, M> PHt = P_.template middleCols<M>(first);
    Eigen::Matrix<double, M, M> S = P_.template block<M, M>(first, first) + R;
    S = 0.5 * (S + S.transpose()).eval();
    const SmallLdlt<M> ldlt(S);
    if (!ldlt.ok) return false;
    const Eigen::Matrix<double, M, M> S_inv = ldlt.inverse();
    const Eigen::Matrix<double, N, M> K = PHt * S_inv;
    x_ += K * r;
    wrap_masked(x_, options_.angular_states);
    if (options_.joseph_form) {
      // A P A^T + K R K^T = A P - (A P) H^T K^T + K R K^T = A P + (K R - (A P) H^T) K^T
      const Covariance AP = P_ - K * P_.template middleRows<M>(first);
      const Eigen::Matrix<double, N, M> B = K * R - AP.template middleCols<M>(first);
      P_ = AP + B * K.transpose();
    } else {
      P_ = P_ - K * PHt.transpose();
    }
    guard();
    last_nis_ = r.dot(S_inv * r);
    last_log_det_s_ = ldlt.log_det();
    return true;
  }

  /// Update with a measurement callable: `h(const State& x, MeasurementJacobian<M>& H)
  /// -> Measurement<M>` returns h(x) and writes H = dh/dx(x). Returns false (estimate
  /// unchanged) if anything is not finite or S = H P H^T + R is not positive definite.
  template <int M, class Model>
  bool update(const Measurement<M>& z, Model&& h, const Eigen::Matrix<double, M, M>& R,
              AngularMask angular_measurements = 0) {
    MeasurementJacobian<M> H;
    const Measurement<M> z_pred = h(static_cast<const State&>(x_), H);
    return update<M>(z, z_pred, H, R, angular_measurements);
  }

  /// Update with a pre-evaluated measurement model (z_pred = h(x-), H = dh/dx(x-)).
  template <int M>
  bool update(const Measurement<M>& z, const Measurement<M>& z_pred, const MeasurementJacobian<M>& H,
              const Eigen::Matrix<double, M, M>& R, AngularMask angular_measurements = 0) {
    if (!z.allFinite() || !z_pred.allFinite() || !H.allFinite() || !R.allFinite()) return false;
    const Measurement<M> r = masked_difference(z, z_pred, angular_measurements);
    const Eigen::Matrix<double, N, M> PHt = P_ * H.transpose();
    Eigen::Matrix<double, M, M> S = H * PHt + R;
    S = 0.5 * (S + S.transpose()).eval();
    Eigen::LLT<Eigen::Matrix<double, M, M>> llt(S);
    if (llt.info() != Eigen::Success) return false;
    // K = P H^T S^-1  <=>  S K^T = H P  (S, P symmetric)
    const Eigen::Matrix<double, N, M> K = llt.solve(PHt.transpose()).transpose();
    x_ += K * r;
    wrap_masked(x_, options_.angular_states);
    if (options_.joseph_form) {
      const Jacobian A = Jacobian::Identity() - K * H;
      P_ = A * P_ * A.transpose() + K * R * K.transpose();
    } else {
      P_ = P_ - K * PHt.transpose();
    }
    guard();
    last_nis_ = r.dot(llt.solve(r));
    last_log_det_s_ = 2.0 * llt.matrixL().toDenseMatrix().diagonal().array().log().sum();
    return true;
  }

  const State& state() const { return x_; }
  const Covariance& covariance() const { return P_; }
  const EkfOptions& options() const { return options_; }
  /// Normalised innovation squared r^T S^-1 r of the last successful update (0 before).
  double last_nis() const { return last_nis_; }
  /// log det S of the last successful update: with the NIS, -2 log of the innovation's
  /// Gaussian likelihood up to a constant (NIS + log det S), to compare two filters' fits.
  double last_log_det_s() const { return last_log_det_s_; }
  /// How many times the covariance guard had to repair P.
  long guard_repairs() const { return guard_repairs_; }

 private:
  void guard() {
    if (keep_symmetric_pd<N>(P_, options_.min_eigenvalue)) ++guard_repairs_;
  }

  /// x = x_pred, P = F P F^T for F = [F_top; 0 I] (predict_partial), without Q or the guard.
  template <int K>
  bool propagate_partial(const State& x_pred, const Eigen::Matrix<double, K, N>& F_top) {
    static_assert(K > 0 && K <= N, "F_top has 1..N rows");
    if (!x_pred.allFinite() || !F_top.allFinite()) return false;
    x_ = x_pred;
    wrap_masked(x_, options_.angular_states);
    const Eigen::Matrix<double, K, N> T = (F_top * P_).eval();
    Covariance P;
    P.template topLeftCorner<K, K>().noalias() = T * F_top.transpose();
    if constexpr (K < N) {
      P.template topRightCorner<K, N - K>() = T.template rightCols<N - K>();
      P.template bottomLeftCorner<N - K, K>() = T.template rightCols<N - K>().transpose();
      P.template bottomRightCorner<N - K, N - K>() = P_.template bottomRightCorner<N - K, N - K>();
    }
    P_ = P;
    return true;
  }

  EkfOptions options_;
  State x_ = State::Zero();
  Covariance P_ = Covariance::Identity();
  double last_nis_ = 0.0;
  double last_log_det_s_ = 0.0;
  long guard_repairs_ = 0;
};

}  // namespace plexus::algorithms
