// Unscented Kalman filters, fixed-size, allocation-free, in the two forms of
// paper 002 section 2.2 (Wan & van der Merwe 2000; Wu et al. 2005, the paper's ref. [9]):
//
// AugmentedUkf<N, NW, NV>: non-additive noise,  x_{k+1} = f(x_k, w_k),  z_k = h(x_k, v_k).
//   The sigma points are drawn once per cycle over the augmented variable
//   x^a = [x; w; v] ~ N([x; 0; 0], blkdiag(P, Q, R)) of dimension L = N + NW + NV
//   (2L + 1 points; the paper's 3 + 3 + 1 = 7 -> 15). predict(f, Q, R) propagates the
//   state part through f with the w part; update(z, h) passes the SAME propagated points
//   with their v part through h (paper 002, eqs. (7)-(9)):
//     x- = sum W^m X_i,  P- = sum W^c dX_i dX_i^T
//     z^ = sum W^m Z_i,  P_zz = sum W^c dZ_i dZ_i^T,  P_xz = sum W^c dX_i dZ_i^T
//   R is already inside P_zz through the v points. (Printing error in the paper: eq. (8)
//   adds R to P_vv in the augmented form as well, which would count it twice.)
//
// AdditiveUkf<N>: additive noise,  x_{k+1} = f(x_k) + w_k,  z_k = h(x_k) + v_k.
//   2N + 1 points (the paper's 7 for N = 3). predict(f, Q): points of (x, P) through f,
//   P- = sum W^c dX dX^T + Q. update(z, h, R): points redrawn from (x-, P-) through h,
//   P_zz = sum W^c dZ dZ^T + R.
//
// Both then correct (eq. (9)):  K = P_xz P_zz^-1,  x+ = x- + K (z - z^),
//   P+ = P- - K P_zz K^T, symmetrised and guarded by keep_symmetric_pd (covariance.hpp).
//
// Model callables must return a plain Eigen object: declare the lambda's return type
// (`-> Eigen::Vector3d`), since `return A * x + w;` with `auto` would return an Eigen
// expression that refers to the lambda's dead temporaries.
//
// For linear models both forms are exactly the Kalman filter. Inputs and time step are
// bound by the caller into the model callables. Angles: Options::angular_states flags
// state components that are angles (wrapped, sigma means and differences taken on the
// circle, see unscented_transform.hpp); an update's mask does the same for measurements.
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "plexus/algorithms/core/covariance.hpp"
#include "plexus/algorithms/core/unscented_transform.hpp"
#include "plexus/algorithms/core/validation.hpp"

namespace plexus::algorithms {

struct UkfOptions {
  UnscentedParams sigma;           ///< alpha, beta, kappa (validated for the filter's dimension L)
  AngularMask angular_states = 0;  ///< bit i: state i is an angle, wrapped to (-pi, pi]
  double min_eigenvalue = 1e-12;   ///< covariance guard floor, finite > 0 (see covariance.hpp)
};

namespace detail {

/// Shared estimate storage, reset and the Kalman correction of eq. (9).
template <int N>
class UkfEstimate {
  static_assert(N > 0 && N <= 32, "state dimension must be in 1..32 (AngularMask bits)");

 public:
  using State = Eigen::Matrix<double, N, 1>;
  using Covariance = Eigen::Matrix<double, N, N>;

  /// Sets the estimate. Throws std::invalid_argument if x0 is not finite or P0 is not SPD.
  void reset(const State& x0, const Covariance& P0) {
    if (!x0.allFinite()) throw std::invalid_argument(std::string(where_) + ": x0 must be finite");
    reset_covariance(P0);
    x_ = x0;
    wrap_masked(x_, options_.angular_states);
  }

  /// Replaces the covariance only. Throws std::invalid_argument if P is not SPD.
  void reset_covariance(const Covariance& P) {
    if (!is_symmetric_positive_definite<N>(P)) {
      throw std::invalid_argument(std::string(where_) + ": covariance must be finite, symmetric and positive definite");
    }
    P_ = 0.5 * (P + P.transpose());
  }

  const State& state() const { return x_; }
  const Covariance& covariance() const { return P_; }
  const UkfOptions& options() const { return options_; }
  /// Normalised innovation squared r^T P_zz^-1 r of the last successful update (0 before).
  double last_nis() const { return last_nis_; }
  /// How many times the covariance guard had to repair P.
  long guard_repairs() const { return guard_repairs_; }

 protected:
  UkfEstimate(const UkfOptions& options, const char* where) : options_(options), where_(where) {
    validation::require_positive(where, "min_eigenvalue", options.min_eigenvalue);
  }

  void guard() {
    if (keep_symmetric_pd<N>(P_, options_.min_eigenvalue)) ++guard_repairs_;
  }

  /// x+ = x- + K r, P+ = P- - K P_zz K^T with K = P_xz P_zz^-1 (paper 002, eq. (9)).
  template <int M>
  bool correct(const Eigen::Matrix<double, M, 1>& r, const Eigen::Matrix<double, N, M>& Pxz,
               Eigen::Matrix<double, M, M> Pzz) {
    Pzz = 0.5 * (Pzz + Pzz.transpose()).eval();
    if (!r.allFinite() || !Pxz.allFinite() || !Pzz.allFinite()) return false;
    const SmallLdlt<M> ldlt(Pzz);  // covariance.hpp
    if (!ldlt.ok) return false;
    const Eigen::Matrix<double, M, M> Pzz_inv = ldlt.inverse();
    const Eigen::Matrix<double, N, M> K = Pxz * Pzz_inv;
    x_ += K * r;
    wrap_masked(x_, options_.angular_states);
    P_ -= K * Pzz * K.transpose();
    guard();
    last_nis_ = r.dot(Pzz_inv * r);
    return true;
  }

  UkfOptions options_;
  const char* where_;
  State x_ = State::Zero();
  Covariance P_ = Covariance::Identity();
  double last_nis_ = 0.0;
  long guard_repairs_ = 0;
};

}  // namespace detail

/// Additive-noise UKF (2N + 1 sigma points). See the file header.
template <int N>
class AdditiveUkf : public detail::UkfEstimate<N> {
  using Base = detail::UkfEstimate<N>;

 public:
  using typename Base::Covariance;
  using typename Base::State;
  static constexpr int kSigmaPoints = 2 * N + 1;

  /// Validates sigma (for L = N) and min_eigenvalue; throws std::invalid_argument.
  explicit AdditiveUkf(const UkfOptions& options = {})
      : Base(options, "additive_ukf"), w_(UnscentedWeights<N>::make(options.sigma, "additive_ukf")) {}

  /// Predict: `f(const State&) -> State`. Returns false (estimate unchanged) if P, Q or
  /// the propagated points are not finite.
  template <class Model>
  bool predict(Model&& f, const Covariance& Q) {
    if (!Q.allFinite()) return false;
    Eigen::Matrix<double, N, kSigmaPoints> X;
    if (!make_sigma_points<N>(this->x_, this->P_, w_, X)) return false;
    for (int i = 0; i < kSigmaPoints; ++i) {
      const State xi = X.col(i);
      X.col(i) = f(xi);
    }
    if (!X.allFinite()) return false;
    const AngularMask mask = this->options_.angular_states;
    const State mean = sigma_mean<N, N>(X, w_, mask);
    Covariance P = Q;
    for (int i = 0; i < kSigmaPoints; ++i) {
      const State d = masked_difference(X.col(i), mean, mask);
      P.noalias() += w_.cov_weight(i) * d * d.transpose();
    }
    this->x_ = mean;
    this->P_ = P;
    this->guard();
    return true;
  }

  /// Update: `h(const State&) -> Eigen::Matrix<double, M, 1>`, additive R. Returns false
  /// (estimate unchanged) if anything is not finite or P_zz is not positive definite.
  template <int M, class Model>
  bool update(const Eigen::Matrix<double, M, 1>& z, Model&& h, const Eigen::Matrix<double, M, M>& R,
              AngularMask angular_measurements = 0) {
    if (!z.allFinite() || !R.allFinite()) return false;
    Eigen::Matrix<double, N, kSigmaPoints> X;
    if (!make_sigma_points<N>(this->x_, this->P_, w_, X)) return false;
    Eigen::Matrix<double, M, kSigmaPoints> Z;
    for (int i = 0; i < kSigmaPoints; ++i) {
      const State xi = X.col(i);
      Z.col(i) = h(xi);
    }
    const Eigen::Matrix<double, M, 1> z_hat = sigma_mean<N, M>(Z, w_, angular_measurements);
    Eigen::Matrix<double, M, M> Pzz = R;
    Eigen::Matrix<double, N, M> Pxz = Eigen::Matrix<double, N, M>::Zero();
    for (int i = 0; i < kSigmaPoints; ++i) {
      const Eigen::Matrix<double, M, 1> dz = masked_difference(Z.col(i), z_hat, angular_measurements);
      const State dx = masked_difference(X.col(i), this->x_, this->options_.angular_states);
      Pzz.noalias() += w_.cov_weight(i) * dz * dz.transpose();
      Pxz.noalias() += w_.cov_weight(i) * dx * dz.transpose();
    }
    return this->template correct<M>(masked_difference(z, z_hat, angular_measurements), Pxz, Pzz);
  }

  const UnscentedWeights<N>& weights() const { return w_; }

 private:
  UnscentedWeights<N> w_;
};

/// Augmented UKF over [x; w; v] (2(N + NW + NV) + 1 sigma points). See the file header.
template <int N, int NW, int NV>
class AugmentedUkf : public detail::UkfEstimate<N> {
  using Base = detail::UkfEstimate<N>;

 public:
  using typename Base::Covariance;
  using typename Base::State;
  static constexpr int kAugmented = N + NW + NV;
  static constexpr int kSigmaPoints = 2 * kAugmented + 1;
  using ProcessNoise = Eigen::Matrix<double, NW, 1>;
  using MeasurementNoise = Eigen::Matrix<double, NV, 1>;

  /// Validates sigma (for L = N + NW + NV) and min_eigenvalue; throws std::invalid_argument.
  explicit AugmentedUkf(const UkfOptions& options = {})
      : Base(options, "augmented_ukf"), w_(UnscentedWeights<kAugmented>::make(options.sigma, "augmented_ukf")) {}

  /// Predict: draws the 2L+1 points of [x; w; v] ~ N([x; 0; 0], blkdiag(P, Q, R)) and
  /// propagates `f(const State&, const ProcessNoise&) -> State`. Keeps the propagated
  /// points (and their v parts) for the next update(). Returns false (estimate unchanged)
  /// if P, Q, R or the propagated points are not finite.
  template <class Model>
  bool predict(Model&& f, const Eigen::Matrix<double, NW, NW>& Q, const Eigen::Matrix<double, NV, NV>& R) {
    if (!Q.allFinite() || !R.allFinite()) return false;
    using AugVec = Eigen::Matrix<double, kAugmented, 1>;
    using AugMat = Eigen::Matrix<double, kAugmented, kAugmented>;
    AugVec xa = AugVec::Zero();
    xa.template head<N>() = this->x_;
    AugMat Pa = AugMat::Zero();
    Pa.template topLeftCorner<N, N>() = this->P_;
    Pa.template block<NW, NW>(N, N) = Q;
    Pa.template bottomRightCorner<NV, NV>() = R;
    Eigen::Matrix<double, kAugmented, kSigmaPoints> Xa;
    if (!make_sigma_points<kAugmented>(xa, Pa, w_, Xa)) return false;
    Eigen::Matrix<double, N, kSigmaPoints> X;
    for (int i = 0; i < kSigmaPoints; ++i) {
      const State xi = Xa.col(i).template head<N>();
      const ProcessNoise wi = Xa.col(i).template segment<NW>(N);
      X.col(i) = f(xi, wi);
    }
    if (!X.allFinite()) return false;
    const AngularMask mask = this->options_.angular_states;
    const State mean = sigma_mean<kAugmented, N>(X, w_, mask);
    Covariance P = Covariance::Zero();
    for (int i = 0; i < kSigmaPoints; ++i) {
      const State d = masked_difference(X.col(i), mean, mask);
      P.noalias() += w_.cov_weight(i) * d * d.transpose();
    }
    X_ = X;
    V_ = Xa.template bottomRows<NV>();
    this->x_ = mean;
    this->P_ = P;
    this->guard();
    points_pending_ = true;
    return true;
  }

  /// Update with the points of the preceding predict(): `h(const State&, const
  /// MeasurementNoise&) -> Eigen::Matrix<double, M, 1>`. Returns false (estimate unchanged)
  /// if no predict() preceded it since the last update, or anything is not finite, or
  /// P_zz is not positive definite.
  template <int M, class Model>
  bool update(const Eigen::Matrix<double, M, 1>& z, Model&& h, AngularMask angular_measurements = 0) {
    if (!points_pending_ || !z.allFinite()) return false;
    Eigen::Matrix<double, M, kSigmaPoints> Z;
    for (int i = 0; i < kSigmaPoints; ++i) {
      const State xi = X_.col(i);
      const MeasurementNoise vi = V_.col(i);
      Z.col(i) = h(xi, vi);
    }
    const Eigen::Matrix<double, M, 1> z_hat = sigma_mean<kAugmented, M>(Z, w_, angular_measurements);
    Eigen::Matrix<double, M, M> Pzz = Eigen::Matrix<double, M, M>::Zero();
    Eigen::Matrix<double, N, M> Pxz = Eigen::Matrix<double, N, M>::Zero();
    for (int i = 0; i < kSigmaPoints; ++i) {
      const Eigen::Matrix<double, M, 1> dz = masked_difference(Z.col(i), z_hat, angular_measurements);
      const State dx = masked_difference(X_.col(i), this->x_, this->options_.angular_states);
      Pzz.noalias() += w_.cov_weight(i) * dz * dz.transpose();
      Pxz.noalias() += w_.cov_weight(i) * dx * dz.transpose();
    }
    if (!this->template correct<M>(masked_difference(z, z_hat, angular_measurements), Pxz, Pzz)) return false;
    points_pending_ = false;
    return true;
  }

  /// Sets the estimate (and drops points of an unfinished predict/update cycle).
  void reset(const State& x0, const Covariance& P0) {
    Base::reset(x0, P0);
    points_pending_ = false;
  }

  /// Replaces the covariance (and drops points of an unfinished predict/update cycle).
  void reset_covariance(const Covariance& P) {
    Base::reset_covariance(P);
    points_pending_ = false;
  }

  const UnscentedWeights<kAugmented>& weights() const { return w_; }

 private:
  UnscentedWeights<kAugmented> w_;
  Eigen::Matrix<double, N, kSigmaPoints> X_ = Eigen::Matrix<double, N, kSigmaPoints>::Zero();
  Eigen::Matrix<double, NV, kSigmaPoints> V_ = Eigen::Matrix<double, NV, kSigmaPoints>::Zero();
  bool points_pending_ = false;
};

}  // namespace plexus::algorithms
