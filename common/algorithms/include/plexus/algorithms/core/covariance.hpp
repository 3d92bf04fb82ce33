// Covariance hygiene shared by the Kalman filters (ekf.hpp, ukf.hpp).
//
// Every filter step ends with keep_symmetric_pd(): the matrix is symmetrised
// (P = (P + P^T) / 2) and, if its Cholesky factorisation fails or a squared
// Cholesky pivot lies below `min_eigenvalue`, it is eigen-decomposed and the
// eigenvalues below `min_eigenvalue` are clamped to it (P = V max(D, eps) V^T). That repair
// is the documented guard: it only fires on round-off loss of definiteness (e.g.
// a UKF with a negative zeroth covariance weight, or a near-perfect measurement),
// it keeps the eigenvectors, and the caller can count how often it fired.
//
// Also here: the angle-aware difference used for residuals. Components whose bit
// is set in an "angular mask" (bit i <-> component i) are differences of angles
// and are wrapped to (-pi, pi].
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include "plexus/algorithms/core/angles.hpp"

namespace plexus::algorithms {

/// Bit i set <-> component i is an angle (residuals wrapped to (-pi, pi]). 0: none.
using AngularMask = std::uint32_t;

/// a - b, with the components flagged in `mask` wrapped to (-pi, pi].
template <class Derived1, class Derived2>
typename Derived1::PlainObject masked_difference(const Eigen::MatrixBase<Derived1>& a,
                                                 const Eigen::MatrixBase<Derived2>& b, AngularMask mask) {
  typename Derived1::PlainObject d = a - b;
  if (mask != 0) {
    for (Eigen::Index i = 0; i < d.size(); ++i) {
      if ((mask >> i) & 1u) d(i) = wrap_angle(d(i));
    }
  }
  return d;
}

/// Wraps the components flagged in `mask` to (-pi, pi] in place.
template <class Derived>
void wrap_masked(Eigen::MatrixBase<Derived>& v, AngularMask mask) {
  if (mask == 0) return;
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    if ((mask >> i) & 1u) v(i) = wrap_angle(v(i));
  }
}

/// True if `m` is finite, symmetric to a relative 1e-9 and Cholesky (LLT) succeeds.
template <int N>
bool is_symmetric_positive_definite(const Eigen::Matrix<double, N, N>& m) {
  if (!m.allFinite()) return false;
  const double scale = m.cwiseAbs().maxCoeff();
  if (!((m - m.transpose()).cwiseAbs().maxCoeff() <= 1e-9 * (scale > 0 ? scale : 1.0))) return false;
  Eigen::LLT<Eigen::Matrix<double, N, N>> llt(m);
  return llt.info() == Eigen::Success;
}

/// True if `m` is finite, symmetric (relative 1e-9) and positive semi-definite
/// (smallest eigenvalue >= -1e-12 times the largest magnitude). For noise covariances.
template <int N>
bool is_symmetric_positive_semidefinite(const Eigen::Matrix<double, N, N>& m) {
  if (!m.allFinite()) return false;
  const double scale = m.cwiseAbs().maxCoeff();
  if (scale == 0.0) return true;
  if (!((m - m.transpose()).cwiseAbs().maxCoeff() <= 1e-9 * scale)) return false;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, N, N>> es(m, Eigen::EigenvaluesOnly);
  return es.eigenvalues().minCoeff() >= -1e-12 * scale;
}

/// The Cholesky factor L (A = L L^T, lower) of a small fixed-size matrix, from its lower
/// triangle, with plain loops the compiler unrolls (Eigen's LLT takes a general blocked
/// path that costs several times more at these sizes). `ok` is false when a squared pivot
/// is not > 0, the same test as Eigen's LLT. Allocation-free.
template <int N>
struct SmallCholesky {
  Eigen::Matrix<double, N, N> L = Eigen::Matrix<double, N, N>::Zero();
  bool ok = false;

  explicit SmallCholesky(const Eigen::Matrix<double, N, N>& A) {
#pragma GCC unroll 16
    for (int j = 0; j < N; ++j) {
      double d = A(j, j);
#pragma GCC unroll 16
      for (int k = 0; k < j; ++k) d -= L(j, k) * L(j, k);
      if (!(d > 0.0)) return;
      const double ljj = std::sqrt(d);
      L(j, j) = ljj;
#pragma GCC unroll 16
      for (int i = j + 1; i < N; ++i) {
        double s = A(i, j);
#pragma GCC unroll 16
        for (int k = 0; k < j; ++k) s -= L(i, k) * L(j, k);
        L(i, j) = s / ljj;
      }
    }
    ok = true;
  }
};

/// The LDL^T factorisation (L unit lower triangular, D diagonal) of a small fixed-size
/// symmetric matrix, from its lower triangle, with plain loops the compiler unrolls
/// (Eigen's LLT takes a general blocked path that costs several times more at these sizes)
/// and no square root. The pivots D_jj are the squared pivots of the Cholesky factor; `ok`
/// is false when one is not > 0 (the matrix is not positive definite, the same test as
/// Eigen's LLT). Allocation-free.
template <int N>
struct SmallLdlt {
  Eigen::Matrix<double, N, N> L = Eigen::Matrix<double, N, N>::Identity();
  Eigen::Matrix<double, N, 1> D = Eigen::Matrix<double, N, 1>::Zero();
  bool ok = false;

  explicit SmallLdlt(const Eigen::Matrix<double, N, N>& A) {
    double inv_d[N];
#pragma GCC unroll 16
    for (int j = 0; j < N; ++j) {
      double d = A(j, j);
#pragma GCC unroll 16
      for (int k = 0; k < j; ++k) d -= L(j, k) * L(j, k) * D(k);
      if (!(d > 0.0)) return;
      D(j) = d;
      inv_d[j] = 1.0 / d;
#pragma GCC unroll 16
      for (int i = j + 1; i < N; ++i) {
        double w = A(i, j);
#pragma GCC unroll 16
        for (int k = 0; k < j; ++k) w -= L(i, k) * L(j, k) * D(k);
        L(i, j) = w * inv_d[j];
      }
    }
    ok = true;
  }

  /// A^-1 = L^-T D^-1 L^-1 (requires ok).
  Eigen::Matrix<double, N, N> inverse() const {
    Eigen::Matrix<double, N, N> Li = Eigen::Matrix<double, N, N>::Identity();  // L^-1, unit lower
#pragma GCC unroll 16
    for (int j = 0; j < N; ++j) {
#pragma GCC unroll 16
      for (int i = j + 1; i < N; ++i) {
        double s = 0.0;
#pragma GCC unroll 16
        for (int k = j; k < i; ++k) s -= L(i, k) * Li(k, j);
        Li(i, j) = s;
      }
    }
    return Li.transpose() * D.cwiseInverse().asDiagonal() * Li;
  }

  /// log det A = log prod D_jj (requires ok).
  double log_det() const { return std::log(D.prod()); }
};

/// The smallest squared Cholesky pivot of a symmetric matrix (its lower triangle): the
/// pivots D_jj of its LDL^T factorisation, computed without storing L (W = L D) and with one
/// division per column, the cheapest form for the guard below; 0 when the matrix is not
/// positive definite or not finite. Allocation-free.
template <int N>
double min_squared_pivot(const Eigen::Matrix<double, N, N>& A) {
  Eigen::Matrix<double, N, N> W;  // W(i, j) = L(i, j) D(j, j) for i > j
  double inv_d[N];
  double smallest = std::numeric_limits<double>::infinity();
#pragma GCC unroll 16
  for (int j = 0; j < N; ++j) {
    double d = A(j, j);
#pragma GCC unroll 16
    for (int k = 0; k < j; ++k) d -= W(j, k) * W(j, k) * inv_d[k];
    if (!(d > 0.0)) return 0.0;  // not positive definite (or not finite)
    inv_d[j] = 1.0 / d;
    smallest = std::min(smallest, d);
#pragma GCC unroll 16
    for (int i = j + 1; i < N; ++i) {
      double w = A(i, j);
#pragma GCC unroll 16
      for (int k = 0; k < j; ++k) w -= W(i, k) * W(j, k) * inv_d[k];
      W(i, j) = w;
    }
  }
  return smallest;
}

/// Symmetrises `P`; if Cholesky fails or a squared pivot is < `min_eigenvalue` (> 0),
/// clamps its eigenvalues to >= `min_eigenvalue`. Returns true if the repair changed P.
/// Fixed-size, no allocation.
template <int N>
bool keep_symmetric_pd(Eigen::Matrix<double, N, N>& P, double min_eigenvalue) {
  for (int j = 0; j < N; ++j)
    for (int i = j + 1; i < N; ++i) P(i, j) = P(j, i) = 0.5 * (P(i, j) + P(j, i));  // (P + P^T) / 2
  // P is PD when every squared Cholesky pivot is > 0. A squared pivot is >= the smallest
  // eigenvalue, so pivots above the floor are the cheap common case; decompose only otherwise.
  if (min_squared_pivot<N>(P) >= min_eigenvalue) return false;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, N, N>> es(P);
  if (es.info() != Eigen::Success) return false;
  if (es.eigenvalues().minCoeff() >= min_eigenvalue) return false;
  const Eigen::Matrix<double, N, 1> clamped = es.eigenvalues().cwiseMax(min_eigenvalue);
  P = es.eigenvectors() * clamped.asDiagonal() * es.eigenvectors().transpose();
  P = 0.5 * (P + P.transpose()).eval();
  return true;
}

}  // namespace plexus::algorithms
