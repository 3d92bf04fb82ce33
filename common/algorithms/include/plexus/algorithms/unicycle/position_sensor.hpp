// Position sensor models for the unicycle family: exact, Gaussian, RFID grid.
//
// Paper 000 (section 6.3.2) localises the robot with RFID tags glued to the floor on
// a 10 cm grid; the measured position is the coordinate of the nearest tag, i.e.
// each coordinate rounded to the grid. This is a large, deterministic,
// position-correlated quantisation error (up to 5 cm per axis, 7 cm radially).
//
// The model is pure: `measure(true_position, rng)` returns the measurement and only
// touches the caller's Rng (which it uses in Gaussian mode only). Rate and seed are
// parameters the caller uses to schedule samples (`period()`) and to construct the
// Rng (`make_rng()`); the model itself holds no time and no random state.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>

#include <Eigen/Core>

#include "plexus/algorithms/core/random.hpp"

namespace plexus::algorithms {

enum class PositionSensorKind {
  kExact,     ///< measurement = true position
  kGaussian,  ///< true position + independent N(0, sigma^2) per axis (Box-Muller, core/random.hpp)
  kRfidGrid,  ///< nearest tag: origin + spacing * round((p - origin) / spacing), per axis
};

struct PositionSensorParams {
  PositionSensorKind kind = PositionSensorKind::kExact;
  double sigma = 0.0;         ///< m, Gaussian standard deviation per axis (kGaussian), >= 0
  double grid_spacing = 0.1;  ///< m, tag spacing (kRfidGrid), > 0; paper 000 section 6.3.2: 0.1 m
  Eigen::Vector2d grid_origin = Eigen::Vector2d::Zero();  ///< m, position of one tag
  double rate_hz = 100.0;                                 ///< samples per second, > 0
  std::uint64_t seed = 0;                                 ///< seed for make_rng()
};

class PositionSensor {
 public:
  /// Validates `params`; throws std::invalid_argument naming the offending field.
  explicit PositionSensor(const PositionSensorParams& params);

  /// The measurement of `true_position`. Draws two normals from `rng` in kGaussian mode
  /// (x first, then y), nothing otherwise. Halfway points round away from the origin
  /// (std::round), so a robot exactly between two tags reads the outer one.
  Eigen::Vector2d measure(const Eigen::Vector2d& true_position, Rng& rng) const {
    switch (params_.kind) {
      case PositionSensorKind::kExact: return true_position;
      case PositionSensorKind::kGaussian:
        return {true_position.x() + params_.sigma * rng.normal(), true_position.y() + params_.sigma * rng.normal()};
      case PositionSensorKind::kRfidGrid:
        return {round_to_grid(true_position.x(), params_.grid_origin.x()),
                round_to_grid(true_position.y(), params_.grid_origin.y())};
    }
    return true_position;
  }

  /// Sampling period, 1 / rate_hz, s.
  double period() const { return 1.0 / params_.rate_hz; }

  /// A fresh Rng seeded with params().seed.
  Rng make_rng() const { return Rng(params_.seed); }

  const PositionSensorParams& params() const { return params_; }

 private:
  double round_to_grid(double v, double origin) const {
    return origin + params_.grid_spacing * std::round((v - origin) / params_.grid_spacing);
  }

  PositionSensorParams params_;
};

/// Parses "exact" | "gaussian" | "rfid_grid"; throws std::invalid_argument otherwise.
PositionSensorKind position_sensor_kind_from_string(const std::string& name);

}  // namespace plexus::algorithms
