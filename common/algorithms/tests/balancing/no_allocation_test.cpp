// The balancing hot paths (plant step, IMU sample, the three filters, controller) must not
// allocate: a counting global operator new checks it around one closed-loop run.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "plexus/algorithms/balancing/attitude_filter.hpp"
#include "plexus/algorithms/balancing/balancing_controller.hpp"
#include "plexus/algorithms/balancing/imu_sensor.hpp"
#include "closed_loop.hpp"

namespace {
std::atomic<long> g_allocations{0};
}  // namespace

void* operator new(std::size_t n) {
  ++g_allocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace plexus::algorithms {
namespace {

TEST(NoAllocation, BalancingHotPathsDoNotAllocate) {
  WheeledInvertedPendulum plant({});
  GyroParams gyro;
  ImuSensor imu(gyro, {}, 9.81, 1);
  BalancingController ctl({}, plant);
  MotionProfile profile({});
  AttitudeFilter f1(testing::filter_params(plant, AttitudeFilterKind::kUkfAugmented, AttitudeMeasurementForm::kObservable, gyro));
  AttitudeFilter f2(testing::filter_params(plant, AttitudeFilterKind::kUkfAdditive, AttitudeMeasurementForm::kPaper, gyro));
  AttitudeFilter f3(testing::filter_params(plant, AttitudeFilterKind::kEkf, AttitudeMeasurementForm::kObservable, gyro));
  AttitudeFilter f4(testing::filter_params(plant, AttitudeFilterKind::kUkfAugmented, AttitudeMeasurementForm::kPaper, gyro));
  WheeledPendulumState s;
  double T = 0;
  const long before = g_allocations.load();
  for (int k = 0; k < 300; ++k) {
    const auto a = plant.step(s, T, 0.01);
    const ImuSample m = imu.measure(s, a, 0.01);
    f1.step(T, m.acc_tilt, m.gyro);
    f2.step(T, m.acc_tilt, m.gyro);
    f3.step(T, m.acc_tilt, m.gyro);
    f4.step(T, m.acc_tilt, m.gyro);
    T = ctl.torque(s.x, s.v, f1.state()(0), f1.state()(1), profile.sample(0.01 * k));
  }
  EXPECT_EQ(g_allocations.load() - before, 0);
  EXPECT_LT(std::abs(s.theta), 0.3);
}

}  // namespace
}  // namespace plexus::algorithms
