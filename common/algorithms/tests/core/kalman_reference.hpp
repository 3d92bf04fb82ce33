// Test helpers: error_of(), and the linear Kalman filter, written out plainly, as the reference that the
// EKF and both UKF forms must equal on a linear-Gaussian problem.
#pragma once

#include <stdexcept>
#include <string>

#include <Eigen/Core>
#include <Eigen/LU>

#include "plexus/algorithms/core/random.hpp"

namespace plexus::algorithms::testing {

template <int N>
struct LinearKalman {
  Eigen::Matrix<double, N, 1> x;
  Eigen::Matrix<double, N, N> P;

  void predict(const Eigen::Matrix<double, N, N>& A, const Eigen::Matrix<double, N, 1>& b,
               const Eigen::Matrix<double, N, N>& Q) {
    x = A * x + b;
    P = A * P * A.transpose() + Q;
  }
  template <int M>
  void update(const Eigen::Matrix<double, M, 1>& z, const Eigen::Matrix<double, M, N>& H,
              const Eigen::Matrix<double, M, M>& R) {
    const Eigen::Matrix<double, M, M> S = H * P * H.transpose() + R;
    const Eigen::Matrix<double, N, M> K = P * H.transpose() * S.inverse();
    x = x + K * (z - H * x);
    P = P - K * S * K.transpose();
  }
};

template <int R, int C>
Eigen::Matrix<double, R, C> random_matrix(Rng& rng, double scale = 1.0) {
  Eigen::Matrix<double, R, C> m;
  for (int i = 0; i < R; ++i)
    for (int j = 0; j < C; ++j) m(i, j) = rng.normal(0.0, scale);
  return m;
}

template <int N>
Eigen::Matrix<double, N, N> random_spd(Rng& rng, double scale = 1.0) {
  const Eigen::Matrix<double, N, N> A = random_matrix<N, N>(rng, scale);
  return A * A.transpose() + 0.05 * scale * scale * Eigen::Matrix<double, N, N>::Identity();
}

/// |a - b| relative to 1 + |b|: a difference that means the same at every scale.
double rel(const auto& a, const auto& b) { return (a - b).norm() / (1.0 + b.norm()); }

/// The std::invalid_argument message thrown by f(), "" if none.
template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

}  // namespace plexus::algorithms::testing
