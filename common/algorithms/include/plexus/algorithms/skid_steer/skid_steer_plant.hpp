// Skid-steer plant: ICR kinematics whose ICRs are set by the terrain under the robot, and
// the terrain's body vibration (paper 001, docs/papers.md).
//
// Input: track speeds (v_l, v_r), held over each step. Each step of h seconds starting at
// time t looks up the terrain at t in the schedule, takes its ICRs (y_l, y_r, x_G),
// integrates the pose exactly for the held body velocities (icr_pose_step), and draws the
// body z-acceleration from the vibration model for that terrain and the mean track speed.
// The state therefore carries the true ICRs and terrain id the estimator and classifier
// are compared against.
#pragma once

#include <string>
#include <vector>

#include "plexus/algorithms/core/random.hpp"
#include "plexus/algorithms/skid_steer/icr_kinematics.hpp"
#include "plexus/algorithms/skid_steer/terrain_schedule.hpp"
#include "plexus/algorithms/skid_steer/terrain_vibration.hpp"

namespace plexus::algorithms {

/// One terrain class: its name, the ICRs it gives the robot and its vibration signature.
struct TerrainSpec {
  std::string name;
  IcrParams icr;
  VibrationSpectrum vibration;
};

/// Paper 001 section 4 terrains A concrete, B tile, C grass (the paper's ICR values,
/// docs/papers.md); the vibration spectra are this project's model (docs/algorithms/skid_steer.md).
std::vector<TerrainSpec> paper_terrains();

struct SkidSteerPlantParams {
  std::vector<TerrainSpec> terrains = paper_terrains();  ///< >= 1, each with valid ICRs
  std::vector<TerrainSegment> schedule{{0.0, 0}};        ///< validated by TerrainSchedule
  Pose2 initial_pose{};
  double step = 0.01;            ///< s, > 0: the integration and vibration sample period
  double reference_speed = 0.5;  ///< vibration gain 1 at this mean track speed, m/s
  double speed_exponent = 1.0;   ///< vibration gain exponent, >= 0
  double gravity = 9.81;         ///< m/s^2
};

struct SkidSteerState {
  Pose2 pose;
  BodyVelocity velocity;  ///< over the last step
  IcrParams icr;          ///< true ICRs of the current terrain
  int terrain = 0;        ///< current terrain id
  double a_z = 0.0;       ///< body z-acceleration (specific force) over the last step, m/s^2
};

class SkidSteerPlant {
 public:
  /// Validates params (terrains, ICRs, schedule, vibration); throws std::invalid_argument.
  explicit SkidSteerPlant(const SkidSteerPlantParams& params);

  /// The state at time 0: initial pose, the terrain at 0 s, at rest (a_z = g).
  const SkidSteerState& state() const { return state_; }

  /// Advances one step of params().step from time t with track speeds u held; draws the
  /// vibration from `rng`. No allocation.
  const SkidSteerState& step(double t, const TrackSpeeds& u, Rng& rng);

  const SkidSteerPlantParams& params() const { return params_; }
  const TerrainSchedule& schedule() const { return schedule_; }

 private:
  SkidSteerPlantParams params_;
  TerrainSchedule schedule_;
  TerrainVibration vibration_;
  SkidSteerState state_;
};

}  // namespace plexus::algorithms
