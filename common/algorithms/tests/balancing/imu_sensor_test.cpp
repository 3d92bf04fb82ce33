#include "plexus/algorithms/balancing/imu_sensor.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "../support/validation_message.hpp"

namespace plexus::algorithms {
namespace {

TEST(ImuSensor, AtRestReadsTiltAndRatePlusDrift) {
  GyroParams g;
  g.noise_std = 0;
  g.drift_noise_psd = 0;
  g.gamma1 = 0;
  AccelerometerParams a;
  a.noise_std = 0;
  ImuSensor imu(g, a, 9.81, 1);
  ImuSample m = imu.measure({0, 0, 0.2, 0.0}, {0, 0}, 0.01);
  EXPECT_NEAR(m.acc_tilt, 0.2, 1e-12);  // no linear acceleration of the mounting point
  m = imu.measure({0, 0, 0.2, 0.1}, {0, 0}, 0.01);
  EXPECT_NEAR(m.gyro, 0.1 + g.initial_drift, 1e-15);
}

TEST(ImuSensor, GyroSaturatesAndAccelerometerSeesLinearAcceleration) {
  GyroParams g;
  g.noise_std = 0;
  AccelerometerParams a;
  a.noise_std = 0;
  a.height = 0.0;  // at the axle: f = (x'', g)
  ImuSensor imu(g, a, 9.81, 1);
  const ImuSample m = imu.measure({0, 0, 0.0, 10.0}, {0.981, 0}, 0.01);
  EXPECT_EQ(m.gyro, g.range);
  EXPECT_NEAR(m.acc_tilt, -std::atan(0.1), 1e-12);  // forward acceleration reads as leaning back
}

// Drift: with gamma1 < 0 the mean decays as exp(gamma1 t) towards -gamma2 / gamma1 and the
// stationary variance is psd / (2 |gamma1|) (Ornstein-Uhlenbeck, integrated exactly).
TEST(ImuSensor, DriftFollowsTheGaussMarkovModel) {
  GyroParams g;
  g.gamma1 = -2.0;
  g.gamma2 = 0.02;
  g.drift_noise_psd = 4e-4;
  g.initial_drift = 0.0;
  ImuSensor imu(g, {}, 9.81, 3);
  double sum = 0, sq = 0;
  int n = 0;
  for (int k = 0; k < 200000; ++k) {
    imu.measure({}, {}, 0.01);
    if (k > 1000) {
      sum += imu.drift();
      sq += imu.drift() * imu.drift();
      ++n;
    }
  }
  const double mean = sum / n, var = sq / n - mean * mean;
  EXPECT_NEAR(mean, 0.01, 0.001);
  EXPECT_NEAR(var, 1e-4, 1e-5);
}

TEST(ImuSensor, EveryValidationError) {
  auto msg = [](auto mutate) {
    GyroParams g;
    AccelerometerParams a;
    double gravity = 9.81;
    mutate(g, a, gravity);
    return testing::invalid_argument_message<ImuSensor>(g, a, gravity, std::uint64_t{1});
  };
  EXPECT_EQ(msg([](auto& g, auto&, auto&) { g.noise_std = -1; }),
            "imu_sensor: gyro.noise_std must be finite and >= 0 (got -1)");
  EXPECT_EQ(msg([](auto& g, auto&, auto&) { g.gamma1 = NAN; }), "imu_sensor: gyro.gamma1 must be finite (got nan)");
  EXPECT_EQ(msg([](auto& g, auto&, auto&) { g.gamma2 = NAN; }), "imu_sensor: gyro.gamma2 must be finite (got nan)");
  EXPECT_EQ(msg([](auto& g, auto&, auto&) { g.drift_noise_psd = -1; }),
            "imu_sensor: gyro.drift_noise_psd must be finite and >= 0 (got -1)");
  EXPECT_EQ(msg([](auto& g, auto&, auto&) { g.initial_drift = INFINITY; }),
            "imu_sensor: gyro.initial_drift must be finite (got inf)");
  EXPECT_EQ(msg([](auto& g, auto&, auto&) { g.range = 0; }),
            "imu_sensor: gyro.range must be > 0 (infinity allowed) (got 0)");
  EXPECT_EQ(msg([](auto&, auto& a, auto&) { a.noise_std = -1; }),
            "imu_sensor: accelerometer.noise_std must be finite and >= 0 (got -1)");
  EXPECT_EQ(msg([](auto&, auto& a, auto&) { a.height = NAN; }),
            "imu_sensor: accelerometer.height must be finite (got nan)");
  EXPECT_EQ(msg([](auto&, auto& a, auto&) { a.range = -3; }),
            "imu_sensor: accelerometer.range must be > 0 (infinity allowed) (got -3)");
  EXPECT_EQ(msg([](auto&, auto&, auto& gr) { gr = 0; }), "imu_sensor: gravity must be finite and > 0 (got 0)");
}

}  // namespace
}  // namespace plexus::algorithms
