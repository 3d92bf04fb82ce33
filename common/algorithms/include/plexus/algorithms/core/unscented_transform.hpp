// Scaled unscented transform (Julier 2002, "The scaled unscented transformation";
// paper 002, eqs. (3)-(5) with its OCR-damaged symbols restored; docs/papers.md).
//
// For an L-dimensional random variable with mean x and covariance P:
//   lambda = alpha^2 (L + kappa) - L,  gamma = sqrt(L + lambda)
//   X_0 = x,  X_i = x + gamma S_i,  X_{L+i} = x - gamma S_i   (i = 1..L)
//   W_0^m = lambda / (L + lambda)
//   W_0^c = lambda / (L + lambda) + (1 - alpha^2 + beta)
//   W_i^m = W_i^c = 1 / (2 (L + lambda))                      (i = 1..2L)
// where S_i is column i of a square root S S^T = P (lower Cholesky factor; an
// eigen-decomposition square root when P is only semi-definite). Then for
// y_i = f(X_i):  y = sum W^m y_i,  P_yy = sum W^c (y_i - y)(y_i - y)^T,
// P_xy = sum W^c (X_i - x)(y_i - y)^T  (eqs. (4)-(5)).
//
// Angles: the weighted mean is taken as y_0 + sum_i W_i^m (y_i - y_0) with the
// differences of components flagged in an AngularMask wrapped, so sigma points
// that straddle +-pi average correctly; it equals sum W^m y_i otherwise.
//
// Everything is fixed-size (L, output dimension R are template parameters): no allocation.
#pragma once

#include <cmath>
#include <string_view>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include "plexus/algorithms/core/covariance.hpp"
#include "plexus/algorithms/core/validation.hpp"

namespace plexus::algorithms {

/// Scaling of the sigma points (paper 002, eq. (3); Julier 2002).
struct UnscentedParams {
  double alpha = 1.0;  ///< spread of the points around the mean, > 0 (paper: 1e-4 < alpha <= 1)
  double beta = 2.0;   ///< prior-distribution term, finite; 2 is optimal for Gaussians
  double kappa = 0.0;  ///< secondary scaling, finite, with L + kappa > 0 (common: 0 or 3 - L)
};

/// Weights and scale of the (2L+1)-point scaled symmetric set for dimension L.
template <int L>
struct UnscentedWeights {
  static_assert(L > 0, "dimension must be positive");
  static constexpr int kPoints = 2 * L + 1;

  double lambda = 0.0;  ///< alpha^2 (L + kappa) - L
  double gamma = 0.0;   ///< sqrt(L + lambda): distance scale of the points
  double wm0 = 0.0;     ///< W_0^m
  double wc0 = 0.0;     ///< W_0^c
  double wi = 0.0;      ///< W_i^m = W_i^c, i >= 1

  /// Validates `p` (alpha finite > 0, beta finite, kappa finite with L + kappa > 0) and
  /// computes the weights; throws std::invalid_argument naming `where` and the parameter.
  static UnscentedWeights make(const UnscentedParams& p, std::string_view where) {
    validation::require_positive(where, "alpha", p.alpha);
    validation::require_finite(where, "beta", p.beta);
    validation::require_finite(where, "kappa", p.kappa);
    if (!(L + p.kappa > 0.0)) {
      validation::fail(where, "kappa", "> -L = " + validation::format_value(-L) + " (L + kappa > 0)", p.kappa);
    }
    UnscentedWeights w;
    w.lambda = p.alpha * p.alpha * (L + p.kappa) - L;
    const double c = L + w.lambda;  // alpha^2 (L + kappa) > 0
    w.gamma = std::sqrt(c);
    w.wm0 = w.lambda / c;
    w.wc0 = w.wm0 + (1.0 - p.alpha * p.alpha + p.beta);
    w.wi = 0.5 / c;
    return w;
  }

  double mean_weight(int i) const { return i == 0 ? wm0 : wi; }
  double cov_weight(int i) const { return i == 0 ? wc0 : wi; }
};

/// A square root S (S S^T = P) of a symmetric positive semi-definite P: the lower
/// Cholesky factor, or V sqrt(max(D, 0)) when Cholesky fails (singular P, e.g. a zero
/// noise block). Returns false only if P is not finite.
template <int L>
bool covariance_square_root(const Eigen::Matrix<double, L, L>& P, Eigen::Matrix<double, L, L>& S) {
  if (!P.allFinite()) return false;
  const SmallCholesky<L> chol(P);  // covariance.hpp
  if (chol.ok) {
    S = chol.L;
    return true;
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, L, L>> es(P);
  if (es.info() != Eigen::Success) return false;
  S = es.eigenvectors() * es.eigenvalues().cwiseMax(0.0).cwiseSqrt().asDiagonal();
  return true;
}

/// Fills `points` (column i = X_i) with the 2L+1 scaled sigma points of (mean, P).
/// Returns false if P has no square root (non-finite). No allocation.
template <int L>
bool make_sigma_points(const Eigen::Matrix<double, L, 1>& mean, const Eigen::Matrix<double, L, L>& P,
                       const UnscentedWeights<L>& w, Eigen::Matrix<double, L, 2 * L + 1>& points) {
  Eigen::Matrix<double, L, L> S;
  if (!covariance_square_root<L>(P, S)) return false;
  points.col(0) = mean;
  for (int i = 0; i < L; ++i) {
    points.col(1 + i) = mean + w.gamma * S.col(i);
    points.col(1 + L + i) = mean - w.gamma * S.col(i);
  }
  return true;
}

/// Weighted mean of the columns of `Y` (2L+1 points of dimension R) with the mean
/// weights of `w`; components flagged in `mask` are averaged as angles (see header).
template <int L, int R>
Eigen::Matrix<double, R, 1> sigma_mean(const Eigen::Matrix<double, R, 2 * L + 1>& Y, const UnscentedWeights<L>& w,
                                       AngularMask mask = 0) {
  Eigen::Matrix<double, R, 1> acc = Eigen::Matrix<double, R, 1>::Zero();
  for (int i = 1; i < 2 * L + 1; ++i) acc += w.wi * masked_difference(Y.col(i), Y.col(0), mask);
  Eigen::Matrix<double, R, 1> mean = Y.col(0) + acc;
  wrap_masked(mean, mask);
  return mean;
}

/// Result of propagating (x, P) through y = f(x).
template <int L, int R>
struct UnscentedTransformResult {
  Eigen::Matrix<double, R, 1> mean;       ///< y
  Eigen::Matrix<double, R, R> cov;        ///< P_yy
  Eigen::Matrix<double, L, R> cross_cov;  ///< P_xy
};

/// Scaled unscented transform of (x, P) through f: R^L -> R^R (paper 002, eqs. (3)-(5)).
/// `f` is called as f(const Eigen::Matrix<double, L, 1>&) -> Eigen::Matrix<double, R, 1>.
/// Exact (up to round-off) for affine f. Returns false if P is not finite.
template <int L, int R, class F>
bool unscented_transform(const Eigen::Matrix<double, L, 1>& x, const Eigen::Matrix<double, L, L>& P,
                         const UnscentedWeights<L>& w, F&& f, UnscentedTransformResult<L, R>& out,
                         AngularMask input_mask = 0, AngularMask output_mask = 0) {
  Eigen::Matrix<double, L, 2 * L + 1> X;
  if (!make_sigma_points<L>(x, P, w, X)) return false;
  Eigen::Matrix<double, R, 2 * L + 1> Y;
  for (int i = 0; i < 2 * L + 1; ++i) Y.col(i) = f(Eigen::Matrix<double, L, 1>(X.col(i)));
  out.mean = sigma_mean<L, R>(Y, w, output_mask);
  out.cov.setZero();
  out.cross_cov.setZero();
  for (int i = 0; i < 2 * L + 1; ++i) {
    const Eigen::Matrix<double, R, 1> dy = masked_difference(Y.col(i), out.mean, output_mask);
    const Eigen::Matrix<double, L, 1> dx = masked_difference(X.col(i), x, input_mask);
    out.cov.noalias() += w.cov_weight(i) * dy * dy.transpose();
    out.cross_cov.noalias() += w.cov_weight(i) * dx * dy.transpose();
  }
  out.cov = 0.5 * (out.cov + out.cov.transpose()).eval();
  return true;
}

}  // namespace plexus::algorithms
