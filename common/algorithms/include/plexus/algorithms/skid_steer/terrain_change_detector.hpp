// Terrain-change detection for the adaptive reset (paper 001 section 3.2, last paragraph):
// "if the terrain type differs from the previous one and the classification stays on the
// new terrain for 2 consecutive samples, the terrain has changed; set P to P_B".
//
// observe() takes one classifier decision per window. The first decision sets the current
// terrain without a change (the filter starts with its own P_0). A class different from
// the current one becomes a candidate; `consecutive` decisions in a row for the same
// candidate confirm the change (observe() returns true once, the candidate becomes the
// current terrain). Any decision for the current terrain, or for another class, restarts
// the count.
#pragma once

#include "plexus/algorithms/core/validation.hpp"

namespace plexus::algorithms {

class TerrainChangeDetector {
 public:
  /// consecutive >= 1 (paper: 2); throws std::invalid_argument.
  explicit TerrainChangeDetector(int consecutive = 2) : consecutive_(consecutive) {
    if (consecutive < 1) validation::fail("terrain_change_detector", "consecutive", ">= 1", consecutive);
  }

  /// One window's class; true when it confirms a change of terrain.
  bool observe(int terrain_class) {
    if (current_ < 0) {
      current_ = terrain_class;
      return false;
    }
    if (terrain_class == current_) {
      count_ = 0;
      return false;
    }
    count_ = terrain_class == candidate_ ? count_ + 1 : 1;
    candidate_ = terrain_class;
    if (count_ < consecutive_) return false;
    current_ = terrain_class;
    count_ = 0;
    ++changes_;
    return true;
  }

  /// The confirmed terrain, -1 before the first decision.
  int current() const { return current_; }
  long changes() const { return changes_; }

 private:
  int consecutive_;
  int current_ = -1;
  int candidate_ = -1;
  int count_ = 0;
  long changes_ = 0;
};

}  // namespace plexus::algorithms
