// Benchmarks of the generic filters on the balancing robot's attitude model (paper 002;
// docs/algorithms/balancing.md has the figures). One iteration = one predict + update
// cycle of a 3-state filter with the paper's accelerometer-tilt measurement:
//
//   BM_UkfAugmentedStep  augmented UKF, [x; w; v] = 3 + 3 + 1 -> 15 sigma points
//   BM_UkfAdditiveStep   additive-noise UKF, 7 sigma points
//   BM_EkfAttitudeStep   EKF with the analytic Jacobian
//   BM_AttitudeFilterObservable/kind  the attitude_filter service's full step (observable
//                        measurement with the accelerometer model and the gyro), kind 0/1/2 =
//                        augmented UKF / additive UKF / EKF
#include <benchmark/benchmark.h>

#include <cmath>

#include "plexus/algorithms/balancing/attitude_filter.hpp"
#include "plexus/algorithms/balancing/attitude_model.hpp"
#include "plexus/algorithms/core/ekf.hpp"
#include "plexus/algorithms/core/ukf.hpp"

namespace {

using namespace plexus::algorithms;
using V1 = Eigen::Matrix<double, 1, 1>;

AttitudeModel make_model() {
  AttitudeModelParams p;
  p.coefficients = WheeledInvertedPendulum({}).coefficients();
  return AttitudeModel(p);
}

const Eigen::Matrix3d kQ =
    Eigen::Vector3d(std::pow(0.2 * M_PI / 180, 2), std::pow(0.05 * M_PI / 180, 2), std::pow(0.3 * M_PI / 180, 2))
        .asDiagonal();
const V1 kR(std::pow(0.2 * M_PI / 180, 2));

/// A deterministic measurement sequence (a slow tilt oscillation), no RNG in the loop.
double measurement(int k) { return 0.02 * std::sin(0.05 * k); }

void BM_UkfAugmentedStep(benchmark::State& state) {
  const AttitudeModel m = make_model();
  AugmentedUkf<3, 3, 1> ukf;
  ukf.reset(Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity() * 1e-4);
  int k = 0;
  for (auto _ : state) {
    const double T = 0.1 * std::sin(0.01 * k);
    ukf.predict(
        [&](const Eigen::Vector3d& x, const Eigen::Vector3d& w) -> Eigen::Vector3d { return m.predict(x, T) + w; }, kQ,
        kR);
    ukf.update<1>(V1(measurement(k++)), [](const Eigen::Vector3d& x, const V1& v) -> V1 { return V1(x(0) + v(0)); });
    benchmark::DoNotOptimize(ukf.state());
  }
}
BENCHMARK(BM_UkfAugmentedStep);

void BM_UkfAdditiveStep(benchmark::State& state) {
  const AttitudeModel m = make_model();
  AdditiveUkf<3> ukf;
  ukf.reset(Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity() * 1e-4);
  int k = 0;
  for (auto _ : state) {
    const double T = 0.1 * std::sin(0.01 * k);
    ukf.predict([&](const Eigen::Vector3d& x) -> Eigen::Vector3d { return m.predict(x, T); }, kQ);
    ukf.update<1>(
        V1(measurement(k++)), [](const Eigen::Vector3d& x) -> V1 { return V1(x(0)); }, kR);
    benchmark::DoNotOptimize(ukf.state());
  }
}
BENCHMARK(BM_UkfAdditiveStep);

void BM_EkfAttitudeStep(benchmark::State& state) {
  const AttitudeModel m = make_model();
  ExtendedKalmanFilter<3> ekf;
  ekf.reset(Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity() * 1e-4);
  const Eigen::RowVector3d H(1.0, 0.0, 0.0);
  int k = 0;
  for (auto _ : state) {
    const double T = 0.1 * std::sin(0.01 * k);
    ekf.predict(
        [&](const Eigen::Vector3d& x, Eigen::Matrix3d& F) -> Eigen::Vector3d {
          F = m.jacobian(x, T);
          return m.predict(x, T);
        },
        kQ);
    ekf.update<1>(V1(measurement(k++)), V1(ekf.state()(0)), H, kR);
    benchmark::DoNotOptimize(ekf.state());
  }
}
BENCHMARK(BM_EkfAttitudeStep);

void BM_AttitudeFilterObservable(benchmark::State& state) {
  AttitudeFilterParams p;
  p.model.coefficients = WheeledInvertedPendulum({}).coefficients();
  p.kind = static_cast<AttitudeFilterKind>(state.range(0));
  AttitudeFilter f(p);
  int k = 0;
  for (auto _ : state) {
    f.step(0.1 * std::sin(0.01 * k), measurement(k), 0.01 * std::cos(0.05 * k));
    ++k;
    benchmark::DoNotOptimize(f.state());
  }
}
BENCHMARK(BM_AttitudeFilterObservable)->Arg(0)->Arg(1)->Arg(2);

}  // namespace
