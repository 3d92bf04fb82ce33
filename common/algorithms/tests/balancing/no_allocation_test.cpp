// The balancing hot paths (plant step, IMU sample, the three filters, controller) must not
// allocate: a counting global operator new checks it around one closed-loop run.
#include <gtest/gtest.h>

#include "../support/count_allocations.hpp"

#include <atomic>
#include <cstdlib>
#include <new>

#include "closed_loop.hpp"
#include "plexus/algorithms/balancing/attitude_filter.hpp"
#include "plexus/algorithms/balancing/balancing_controller.hpp"
#include "plexus/algorithms/balancing/imu_sensor.hpp"

namespace plexus::algorithms {
namespace {

TEST(NoAllocation, BalancingHotPathsDoNotAllocate) {
  WheeledInvertedPendulum plant({});
  GyroParams gyro;
  ImuSensor imu(gyro, {}, 9.81, 1);
  BalancingController ctl({}, plant);
  MotionProfile profile({});
  AttitudeFilter f1(
      testing::filter_params(plant, AttitudeFilterKind::kUkfAugmented, AttitudeMeasurementForm::kObservable, gyro));
  AttitudeFilter f2(
      testing::filter_params(plant, AttitudeFilterKind::kUkfAdditive, AttitudeMeasurementForm::kPaper, gyro));
  AttitudeFilter f3(
      testing::filter_params(plant, AttitudeFilterKind::kEkf, AttitudeMeasurementForm::kObservable, gyro));
  AttitudeFilter f4(
      testing::filter_params(plant, AttitudeFilterKind::kUkfAugmented, AttitudeMeasurementForm::kPaper, gyro));
  WheeledPendulumState s;
  double T = 0;
  const long before = plexus::test::allocations();
  for (int k = 0; k < 300; ++k) {
    const auto a = plant.step(s, T, 0.01);
    const ImuSample m = imu.measure(s, a, 0.01);
    f1.step(T, m.acc_tilt, m.gyro);
    f2.step(T, m.acc_tilt, m.gyro);
    f3.step(T, m.acc_tilt, m.gyro);
    f4.step(T, m.acc_tilt, m.gyro);
    T = ctl.torque(s.x, s.v, f1.state()(0), f1.state()(1), profile.sample(0.01 * k));
  }
  EXPECT_EQ(plexus::test::allocations() - before, 0);
  EXPECT_LT(std::abs(s.theta), 0.3);
}

}  // namespace
}  // namespace plexus::algorithms
