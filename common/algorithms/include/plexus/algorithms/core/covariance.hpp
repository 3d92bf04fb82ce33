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

#include <cmath>
#include <cstdint>

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

/// Symmetrises `P`; if Cholesky fails or a squared pivot is < `min_eigenvalue` (> 0),
/// clamps its eigenvalues to >= `min_eigenvalue`. Returns true if the repair changed P.
/// Fixed-size, no allocation.
template <int N>
bool keep_symmetric_pd(Eigen::Matrix<double, N, N>& P, double min_eigenvalue) {
  P = 0.5 * (P + P.transpose()).eval();
  Eigen::LLT<Eigen::Matrix<double, N, N>> llt(P);
  if (llt.info() == Eigen::Success) {
    // Cholesky succeeded: P is PD. A squared pivot is >= the smallest eigenvalue, so
    // pivots above the floor are the cheap common case; decompose only otherwise.
    const auto d = llt.matrixLLT().diagonal();
    if ((d.array() * d.array()).minCoeff() >= min_eigenvalue) return false;
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, N, N>> es(P);
  if (es.info() != Eigen::Success) return false;
  if (es.eigenvalues().minCoeff() >= min_eigenvalue) return false;
  const Eigen::Matrix<double, N, 1> clamped = es.eigenvalues().cwiseMax(min_eigenvalue);
  P = es.eigenvectors() * clamped.asDiagonal() * es.eigenvectors().transpose();
  P = 0.5 * (P + P.transpose()).eval();
  return true;
}

}  // namespace plexus::algorithms
