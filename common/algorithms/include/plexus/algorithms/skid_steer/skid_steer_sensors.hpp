// Sensor models of the skid-steer family (paper 001 section 4, docs/papers.md).
//
//   PoseSensor       differential GPS position + dual-antenna heading: X, Y with
//                    N(0, position_std^2) each, theta with N(0, heading_std^2), heading
//                    wrapped to (-pi, pi] like a real compass (wrap_heading). Paper: 20 Hz,
//                    sigma 0.01 m and 1 deg.
//   TrackSpeedSensor encoder track speeds v_l, v_r with N(0, noise_std^2) each.
//   ImuZSensor       z accelerometer: a_z + bias + N(0, noise_std^2). Paper: 100 Hz.
// Rates are the scenario's business (the component's `rate`); the models are pure and draw
// from the caller's Rng in a fixed order (x, y, theta / v_l, v_r / a_z). No allocation.
#pragma once

#include <numbers>

#include "plexus/algorithms/core/angles.hpp"
#include "plexus/algorithms/core/random.hpp"
#include "plexus/algorithms/core/validation.hpp"
#include "plexus/algorithms/skid_steer/icr_kinematics.hpp"

namespace plexus::algorithms {

struct PoseSensorParams {
  double position_std = 0.01;                     ///< m, >= 0 (paper: 0.01)
  double heading_std = std::numbers::pi / 180.0;  ///< rad, >= 0 (paper: 1 deg)
  bool wrap_heading = true;                       ///< report theta in (-pi, pi]
};

class PoseSensor {
 public:
  explicit PoseSensor(const PoseSensorParams& p) : p_(p) {
    validation::require_non_negative("pose_sensor", "position_std", p.position_std);
    validation::require_non_negative("pose_sensor", "heading_std", p.heading_std);
  }
  Pose2 measure(const Pose2& truth, Rng& rng) const {
    Pose2 m{truth.x + p_.position_std * rng.normal(), truth.y + p_.position_std * rng.normal(),
            truth.theta + p_.heading_std * rng.normal()};
    if (p_.wrap_heading) m.theta = wrap_angle(m.theta);
    return m;
  }
  const PoseSensorParams& params() const { return p_; }

 private:
  PoseSensorParams p_;
};

class TrackSpeedSensor {
 public:
  explicit TrackSpeedSensor(double noise_std) : std_(noise_std) {
    validation::require_non_negative("track_speed_sensor", "noise_std", noise_std);
  }
  TrackSpeeds measure(const TrackSpeeds& truth, Rng& rng) const {
    return {truth.v_l + std_ * rng.normal(), truth.v_r + std_ * rng.normal()};
  }

 private:
  double std_;
};

class ImuZSensor {
 public:
  ImuZSensor(double noise_std, double bias) : std_(noise_std), bias_(bias) {
    validation::require_non_negative("imu_z_sensor", "noise_std", noise_std);
    validation::require_finite("imu_z_sensor", "bias", bias);
  }
  double measure(double a_z, Rng& rng) const { return a_z + bias_ + std_ * rng.normal(); }

 private:
  double std_;
  double bias_;
};

}  // namespace plexus::algorithms
