// Which terrain the robot drives on, as data: a time schedule of terrain ids.
//
// Paper 001 section 4.2: terrain A (concrete) for 0-50 s, B (tile) from 50 s, C (grass)
// from 150 s (the text also says 200 s for the second switch; the schedule is data, so
// either is one line of the scenario). Each segment starts at `start_s` and lasts until
// the next one starts; the first starts at 0.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "plexus/algorithms/core/validation.hpp"

namespace plexus::algorithms {

struct TerrainSegment {
  double start_s = 0.0;  ///< s, start of the segment
  int terrain = 0;       ///< terrain id, in [0, terrain count)
};

class TerrainSchedule {
 public:
  /// Validates: at least one segment, the first at 0 s, start times finite and strictly
  /// increasing, ids in [0, terrain_count). Throws std::invalid_argument naming the segment.
  TerrainSchedule(std::vector<TerrainSegment> segments, std::size_t terrain_count) : segments_(std::move(segments)) {
    if (segments_.empty()) throw std::invalid_argument("terrain_schedule: must have at least one segment");
    for (std::size_t i = 0; i < segments_.size(); ++i) {
      const std::string name = "segments[" + std::to_string(i) + "]";
      validation::require_finite("terrain_schedule", name + ".start_s", segments_[i].start_s);
      if (i == 0 && segments_[i].start_s != 0.0) {
        validation::fail("terrain_schedule", name + ".start_s", "0 (the schedule starts at 0 s)", segments_[i].start_s);
      }
      if (i > 0 && !(segments_[i].start_s > segments_[i - 1].start_s)) {
        validation::fail("terrain_schedule", name + ".start_s", "> the previous segment's start", segments_[i].start_s);
      }
      if (segments_[i].terrain < 0 || static_cast<std::size_t>(segments_[i].terrain) >= terrain_count) {
        validation::fail("terrain_schedule", name + ".terrain",
                         "a terrain id in [0, " + std::to_string(terrain_count) + ")", segments_[i].terrain);
      }
    }
  }

  /// The terrain at time t (s): the last segment with start_s <= t (the first before 0).
  int terrain_at(double t) const {
    int id = segments_.front().terrain;
    for (const TerrainSegment& s : segments_) {
      if (s.start_s <= t) id = s.terrain;
    }
    return id;
  }

  const std::vector<TerrainSegment>& segments() const { return segments_; }

 private:
  std::vector<TerrainSegment> segments_;
};

}  // namespace plexus::algorithms
