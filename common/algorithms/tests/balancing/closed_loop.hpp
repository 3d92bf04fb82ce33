// Test helper: the paper 002 experiment composed directly from the algorithms (no
// scenario layer): plant, IMU at 100 Hz, the designated filter in the loop and any
// number of filters fed the same sensor stream. Returns the tilt error statistics.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "plexus/algorithms/balancing/attitude_filter.hpp"
#include "plexus/algorithms/balancing/balancing_controller.hpp"
#include "plexus/algorithms/balancing/imu_sensor.hpp"
#include "plexus/algorithms/balancing/wheeled_inverted_pendulum.hpp"

namespace plexus::algorithms::testing {

struct ErrorStats {
  double mean = 0, std = 0, max = -1e9, min = 1e9;
  std::vector<double> samples;
  void add(double e) {
    samples.push_back(e);
    max = std::max(max, e);
    min = std::min(min, e);
  }
  void finish() {
    double s = 0, s2 = 0;
    for (double e : samples) s += e;
    mean = s / samples.size();
    for (double e : samples) s2 += (e - mean) * (e - mean);
    std = std::sqrt(s2 / samples.size());
  }
};

struct ClosedLoopResult {
  std::vector<ErrorStats> tilt_error_deg;  ///< per filter, estimate - truth
  ErrorStats acc_tilt_error_deg;           ///< the accelerometer's own tilt, atan2 of its axes, - truth
  std::vector<double> final_drift_error;   ///< per filter, rad/s
  double max_abs_tilt_deg = 0;
};

inline AttitudeFilterParams filter_params(const WheeledInvertedPendulum& plant, AttitudeFilterKind kind,
                                          AttitudeMeasurementForm form, const GyroParams& gyro) {
  AttitudeFilterParams p;
  p.kind = kind;
  p.measurement = form;
  p.model.coefficients = plant.coefficients();
  p.model.gamma1 = gyro.gamma1;
  p.model.gamma2 = gyro.gamma2;
  p.model.gyro_range = gyro.range;
  p.model.accelerometer_height = 0.12;
  p.model.gravity = plant.params().gravity;
  return p;
}

/// filters[0] closes the loop.
inline ClosedLoopResult run_closed_loop(const WheeledInvertedPendulum& plant, std::vector<AttitudeFilter>& filters,
                                        const GyroParams& gyro, const AccelerometerParams& acc, std::uint64_t seed,
                                        double duration = 5.0, double dt = 0.01) {
  ImuSensor imu(gyro, acc, plant.params().gravity, seed);
  BalancingController ctl({}, plant);
  MotionProfile profile({});
  WheeledPendulumState s;
  WheeledPendulumAccelerations a = plant.accelerations(s, 0.0);
  ClosedLoopResult r;
  r.tilt_error_deg.resize(filters.size());
  double torque = 0.0;
  const int n = static_cast<int>(std::lround(duration / dt));
  constexpr double kDeg = 180.0 / 3.14159265358979323846;
  for (int k = 0; k <= n; ++k) {
    if (k > 0) a = plant.step(s, torque, dt);
    const ImuSample m = imu.measure(s, a, dt);
    r.acc_tilt_error_deg.add((m.acc_tilt - s.theta) * kDeg);
    for (std::size_t i = 0; i < filters.size(); ++i) {
      filters[i].step(torque, m.acc_tilt, m.gyro);
      r.tilt_error_deg[i].add((filters[i].state()(0) - s.theta) * kDeg);
    }
    r.max_abs_tilt_deg = std::max(r.max_abs_tilt_deg, std::abs(s.theta) * kDeg);
    const auto& est = filters[0].state();
    torque = plant.saturate(ctl.torque(s.x, s.v, est(0), est(1), profile.sample(k * dt)));
    if (k == n) {
      for (auto& f : filters) r.final_drift_error.push_back(f.state()(2) - m.drift);
    }
  }
  for (auto& e : r.tilt_error_deg) e.finish();
  r.acc_tilt_error_deg.finish();
  return r;
}

}  // namespace plexus::algorithms::testing
