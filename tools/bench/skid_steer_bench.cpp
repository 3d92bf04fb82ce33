// Benchmarks of the skid-steer family's hot paths (paper 001), on the paper's settings
// (docs/algorithms/skid_steer.md):
//   BM_IcrEkfStep       one ICR EKF period: predict (dt 0.01 s) + update with a GPS pose
//   BM_TerrainFeatures  PSD features of one 100-sample window (FFTW3 r2c, 50 bins)
//   BM_TerrainClassify  kNN (k 5, standardised) of one window against 45 training samples
//   BM_IcrPriorResetRewind  one prior reset with the default 3 s rewind (300 steps, GPS 20 Hz:
//                       24 change times tried for the prior and for the paper's hypothesis)
#include <benchmark/benchmark.h>

#include <vector>

#include "plexus/algorithms/core/random.hpp"
#include "plexus/algorithms/skid_steer/driving_pattern.hpp"
#include "plexus/algorithms/skid_steer/icr_ekf.hpp"
#include "plexus/algorithms/skid_steer/icr_terrain_reset.hpp"
#include "plexus/algorithms/skid_steer/knn_classifier.hpp"
#include "plexus/algorithms/skid_steer/skid_steer_plant.hpp"
#include "plexus/algorithms/skid_steer/skid_steer_sensors.hpp"
#include "plexus/algorithms/skid_steer/terrain_features.hpp"

namespace {

using namespace plexus::algorithms;

/// 100-sample windows of the paper terrains' vibration (terrain i % 3).
std::vector<std::vector<double>> windows(int count) {
  SkidSteerPlantParams p;
  std::vector<std::vector<double>> out;
  Rng rng(3);
  TerrainVibrationParams v;
  for (const auto& t : p.terrains) v.spectra.push_back(t.vibration);
  TerrainVibration vib(v);
  for (int i = 0; i < count; ++i) {
    std::vector<double> w(100);
    for (double& s : w) s = vib.sample(i % 3, 0.4, rng);
    out.push_back(w);
  }
  return out;
}

void BM_IcrEkfStep(benchmark::State& state) {
  IcrEkf ekf({});
  const PoseSensor gps({});
  Rng rng(1);
  const TrackSpeeds u{0.2, 0.6};
  Pose2 truth{};
  const BodyVelocity b = icr_body_velocity({0.3, -0.5, -0.1}, u);
  ekf.reset(truth);
  for (auto _ : state) {
    truth = icr_pose_step(truth, b, 0.01);
    ekf.predict(u, 0.01);
    ekf.update(gps.measure(truth, rng));
    benchmark::DoNotOptimize(ekf.state());
  }
}
BENCHMARK(BM_IcrEkfStep);

void BM_IcrPriorResetRewind(benchmark::State& state) {
  IcrTerrainResetOptions o;
  o.rewind_steps = 300;
  IcrTerrainResetFilter f({}, o);
  const PoseSensor gps({});
  Rng rng(1);
  Pose2 truth{};
  f.start(truth);
  for (int k = 1; k <= 400; ++k) {  // fill the history on a turn
    const TrackSpeeds u{0.2, 0.6};
    truth = icr_pose_step(truth, icr_body_velocity({0.3, -0.5, -0.1}, u), 0.01);
    const Pose2 z = gps.measure(truth, rng);
    f.step(&u, 0.01, k % 5 == 0 ? &z : nullptr);
  }
  TerrainIcrPrior prior;
  prior.mean = {0.5, -0.7, -0.3};
  prior.sd = Eigen::Vector3d::Constant(0.015);
  const IcrTerrainResetFilter filled = f;
  for (auto _ : state) {
    state.PauseTiming();
    f = filled;
    state.ResumeTiming();
    f.terrain_changed(&prior);
    benchmark::DoNotOptimize(f.published().state());
  }
}
BENCHMARK(BM_IcrPriorResetRewind)->Unit(benchmark::kMicrosecond);

void BM_TerrainFeatures(benchmark::State& state) {
  PsdFeatureExtractor e({});
  const auto w = windows(1);
  std::vector<double> f(e.size());
  for (auto _ : state) {
    e.compute(w[0], f);
    benchmark::DoNotOptimize(f.data());
  }
}
BENCHMARK(BM_TerrainFeatures);

void BM_TerrainClassify(benchmark::State& state) {
  PsdFeatureExtractor e({});
  TrainingSet set;
  set.layout = FeatureLayout::of(e);
  std::vector<double> f(e.size());
  const auto w = windows(46);
  for (int i = 0; i < 45; ++i) {
    e.compute(w[static_cast<std::size_t>(i)], f);
    set.labels.push_back(i % 3);
    set.features.insert(set.features.end(), f.begin(), f.end());
  }
  const KnnClassifier knn(set, {});
  e.compute(w[45], f);
  for (auto _ : state) benchmark::DoNotOptimize(knn.classify(f));
}
BENCHMARK(BM_TerrainClassify);

}  // namespace
