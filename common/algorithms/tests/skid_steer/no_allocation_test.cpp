// The hot paths of the skid-steer family (plant step, sensors, vibration, ICR EKF
// predict/update, PSD features, kNN classification, odometry, window buffering) must not
// allocate. This binary replaces the global operator new with a counting one.
#include <gtest/gtest.h>

#include "../support/count_allocations.hpp"

#include <atomic>
#include <cstdlib>
#include <new>
#include <vector>

#include "plexus/algorithms/skid_steer/driving_pattern.hpp"
#include "plexus/algorithms/skid_steer/icr_ekf.hpp"
#include "plexus/algorithms/skid_steer/icr_odometry.hpp"
#include "plexus/algorithms/skid_steer/icr_terrain_reset.hpp"
#include "plexus/algorithms/skid_steer/knn_classifier.hpp"
#include "plexus/algorithms/skid_steer/skid_steer_plant.hpp"
#include "plexus/algorithms/skid_steer/skid_steer_sensors.hpp"
#include "plexus/algorithms/skid_steer/terrain_change_detector.hpp"
#include "plexus/algorithms/skid_steer/terrain_features.hpp"

namespace plexus::algorithms {
namespace {

TEST(NoAllocation, HotPathsDoNotAllocate) {
  SkidSteerPlantParams pp;
  pp.schedule = {{0.0, 0}, {1.0, 1}};
  SkidSteerPlant plant(pp);
  const DrivingPattern drive({});
  const PoseSensor gps({});
  const TrackSpeedSensor wheels(0.01);
  const ImuZSensor imu(0.05, 0.0);
  IcrEkf ekf({});
  IcrOdometry odo;
  PsdFeatureExtractor features({});
  SampleWindow window(100, 100);
  TrainingSet set;
  set.layout.features = features.size();
  for (int i = 0; i < 45; ++i) {
    set.labels.push_back(i % 3);
    for (std::size_t j = 0; j < features.size(); ++j)
      set.features.push_back(0.01 * (i % 3) + 0.001 * static_cast<double>(j));
  }
  const KnnClassifier knn(set, {});
  TerrainChangeDetector detector;
  std::vector<double> f(features.size());
  Rng rng(1);
  ekf.reset(plant.state().pose);
  odo.reset(plant.state().pose);

  const long before = plexus::test::allocations();
  double sink = 0;
  for (int k = 0; k < 300; ++k) {
    const double t = 0.01 * k;
    const TrackSpeeds u = drive.at(t);
    const SkidSteerState& s = plant.step(t, u, rng);
    const TrackSpeeds m = wheels.measure(u, rng);
    ekf.predict(m, 0.01);
    if (k % 5 == 0) ekf.update(gps.measure(s.pose, rng));
    odo.step(m, ekf.icr(), 0.01);
    if (window.push(imu.measure(s.a_z, rng))) {
      features.compute(window.window(), f);
      const KnnResult r = knn.classify(f);
      if (detector.observe(r.label)) ekf.reset_covariance_to_p_b();
      sink += r.confidence;
    }
  }
  const long after = plexus::test::allocations();
  EXPECT_EQ(after - before, 0);
  EXPECT_TRUE(std::isfinite(sink + odo.pose().x));
}

TEST(NoAllocation, TerrainResetWithRewindAndRevisedOdometryDoNotAllocate) {
  SkidSteerPlantParams pp;
  pp.schedule = {{0.0, 0}, {1.0, 1}};
  SkidSteerPlant plant(pp);
  const DrivingPattern drive({});
  const PoseSensor gps({});
  IcrTerrainResetOptions rewind;
  rewind.rewind_steps = 300;
  IcrTerrainResetFilter f({}, rewind);  // its history is allocated here
  RevisableIcrOdometry odo(300);        // and this one's
  TerrainIcrPrior prior;
  prior.mean = {0.5, -0.7, -0.3};
  prior.sd = Eigen::Vector3d::Constant(0.01);
  Rng rng(1);
  f.start(plant.state().pose);
  const long before = plexus::test::allocations();
  for (int k = 0; k < 400; ++k) {
    const double t = 0.01 * k;
    const TrackSpeeds u = drive.at(t);
    const Pose2 z = gps.measure(plant.step(t, u, rng).pose, rng);
    f.step(&u, 0.01, k % 5 == 0 ? &z : nullptr);
    odo.step(u, f.published().icr(), 0.01, t);
    odo.revise(t - 0.01 * static_cast<double>(f.published_model_steps()), f.published().icr());
    if (k == 150) f.terrain_changed(&prior);   // rewind over the kept steps, check begins
    if (k == 300) f.terrain_changed(nullptr);  // the paper's reset, rewound
  }
  EXPECT_EQ(plexus::test::allocations() - before, 0);
  EXPECT_TRUE(std::isfinite(f.published().icr().y_l) && std::isfinite(odo.pose().x));
}

}  // namespace
}  // namespace plexus::algorithms
