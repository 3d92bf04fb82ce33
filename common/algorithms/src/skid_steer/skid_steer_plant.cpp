// Skid-steer plant (paper 001; docs/algorithms/skid_steer.md).
#include "plexus/algorithms/skid_steer/skid_steer_plant.hpp"

#include <cmath>
#include <stdexcept>

namespace plexus::algorithms {

namespace {

const SkidSteerPlantParams& non_empty(const SkidSteerPlantParams& p) {
  if (p.terrains.empty()) throw std::invalid_argument("skid_steer_plant: terrains must not be empty");
  return p;
}

TerrainVibrationParams vibration_params(const SkidSteerPlantParams& p) {
  TerrainVibrationParams v;
  for (std::size_t i = 0; i < p.terrains.size(); ++i) {
    validate_icr("skid_steer_plant: terrains[" + std::to_string(i) + "] (" + p.terrains[i].name + ")",
                 p.terrains[i].icr);
    v.spectra.push_back(p.terrains[i].vibration);
  }
  validation::require_positive("skid_steer_plant", "step", p.step);
  validation::require_finite("skid_steer_plant", "initial_pose.x", p.initial_pose.x);
  validation::require_finite("skid_steer_plant", "initial_pose.y", p.initial_pose.y);
  validation::require_finite("skid_steer_plant", "initial_pose.theta", p.initial_pose.theta);
  v.sample_period = p.step;
  v.reference_speed = p.reference_speed;
  v.speed_exponent = p.speed_exponent;
  v.gravity = p.gravity;
  return v;
}

}  // namespace

std::vector<TerrainSpec> paper_terrains() {
  // ICRs: paper 001 section 4.2 (docs/papers.md). Spectra: this project's model —
  // concrete: stiff and rough, energy at 15-40 Hz; tile: smooth with lightly damped
  // low-mid resonances (joints excite the chassis); grass: soft, heavily damped, low.
  return {
      {"concrete", {0.3, -0.5, -0.1}, {{{18.0, 0.15, 0.6}, {33.0, 0.10, 0.4}}, 0.15}},
      {"tile", {0.5, -0.7, -0.3}, {{{8.0, 0.05, 0.5}, {24.0, 0.05, 0.3}}, 0.05}},
      {"grass", {0.4, -0.6, -0.2}, {{{4.0, 0.30, 0.8}, {12.0, 0.40, 0.3}}, 0.10}},
  };
}

SkidSteerPlant::SkidSteerPlant(const SkidSteerPlantParams& params)
    : params_(non_empty(params)),
      schedule_(params.schedule, params.terrains.size()),
      vibration_(vibration_params(params)) {
  state_.pose = params.initial_pose;
  state_.terrain = schedule_.terrain_at(0.0);
  state_.icr = params.terrains[static_cast<std::size_t>(state_.terrain)].icr;
  state_.a_z = params.gravity;
}

const SkidSteerState& SkidSteerPlant::step(double t, const TrackSpeeds& u, Rng& rng) {
  state_.terrain = schedule_.terrain_at(t);
  state_.icr = params_.terrains[static_cast<std::size_t>(state_.terrain)].icr;
  state_.velocity = icr_body_velocity(state_.icr, u);
  state_.pose = icr_pose_step(state_.pose, state_.velocity, params_.step);
  state_.a_z = vibration_.sample(state_.terrain, 0.5 * (std::abs(u.v_l) + std::abs(u.v_r)), rng);
  return state_;
}

}  // namespace plexus::algorithms
