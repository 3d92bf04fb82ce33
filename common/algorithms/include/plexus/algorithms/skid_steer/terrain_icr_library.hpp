// Terrain ICR library: for each terrain class, the ICRs (y_l, y_r, x_G) the ICR EKF
// converged to on that terrain, with their uncertainty. The prior reset of the ICR EKF
// (docs/algorithms/skid_steer.md, "Prior reset") starts the filter from these values when
// the classifier confirms a change to a known terrain, instead of paper 001's covariance
// reset (eq. (22)) from the old terrain's values.
//
// File format (text, one record per line, '#' comments):
//   plexus-terrain-icr-library 1
//   class <id> <name> <y_l> <y_r> <x_G> <sd_y_l> <sd_y_r> <sd_x_G> <samples>
// Learned from recorded runs by the icr_library_recorder service (TerrainIcrAccumulator):
// the mean of the converged estimate, and sd^2 = the estimate's variance about that mean
// plus the filter's own mean variance (how well one run pins the value).
#pragma once

#include <Eigen/Core>
#include <map>
#include <string>

#include "plexus/algorithms/skid_steer/icr_kinematics.hpp"
#include "plexus/algorithms/skid_steer/training_set.hpp"  // TrainingFileError

namespace plexus::algorithms {

struct TerrainIcrPrior {
  IcrParams mean;
  Eigen::Vector3d sd = Eigen::Vector3d::Zero();  ///< of y_l, y_r, x_G; > 0
  long samples = 0;
};

struct TerrainIcrLibrary {
  std::map<int, TerrainIcrPrior> classes;
  std::map<int, std::string> names;
  /// The prior of class `id`, or nullptr.
  const TerrainIcrPrior* find(int id) const {
    const auto it = classes.find(id);
    return it == classes.end() ? nullptr : &it->second;
  }
};

/// Loads and validates a library file; throws TrainingFileError ("file:line: ...").
TerrainIcrLibrary load_terrain_icr_library(const std::string& path);
/// Writes `library` to `path` (replaced atomically: a temporary file renamed over it).
/// Throws TrainingFileError if it cannot be written.
void save_terrain_icr_library(const std::string& path, const TerrainIcrLibrary& library,
                              const std::string& comment = {});

/// Per-class running mean and variance (Welford) of converged ICR estimates.
class TerrainIcrAccumulator {
 public:
  /// One converged estimate of class `id` and the filter's standard deviations then.
  void add(int id, const IcrParams& icr, const Eigen::Vector3d& filter_sd);
  TerrainIcrLibrary library(const std::map<int, std::string>& names = {}) const;
  long samples(int id) const;

 private:
  struct Moments {
    long n = 0;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    Eigen::Vector3d m2 = Eigen::Vector3d::Zero();
    Eigen::Vector3d filter_var = Eigen::Vector3d::Zero();  ///< sum of the filter's variances
  };
  std::map<int, Moments> moments_;
};

}  // namespace plexus::algorithms
