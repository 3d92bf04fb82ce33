// Driving patterns: open-loop track-speed commands that drive the skid-steer plant.
//
// A pattern gives a body speed v(t) and a nominal turn rate w(t), converted to track
// speeds with the no-slip model of the commanded track width B:
//   v_l = v - w B / 2,   v_r = v + w B / 2
// (the robot's actual turn rate differs: that slip is what the ICR filter estimates).
//   straight:      v, w = 0
//   circle:        v, w = turn_rate
//   figure_eight:  v, w = turn_rate sin(2 pi t / period + phase)  (a closed figure-eight; the
//                  turn changes sign every half period, so every ICR is excited)
//   segments:      a list of (duration, v_l, v_r) held in turn, repeated if `repeat`
//                  (else the last segment's speeds are held after the list ends)
// Paper 001 does not give its simulated path; section 4.3 drives "at a given speed and
// radius". ICRs are only observable while turning (v_l != v_r): the paper scenarios use
// figure_eight (docs/algorithms/skid_steer.md).
#pragma once

#include <string>
#include <vector>

#include "plexus/algorithms/skid_steer/icr_kinematics.hpp"

namespace plexus::algorithms {

enum class DrivingPatternKind { kStraight, kCircle, kFigureEight, kSegments };

/// "straight" | "circle" | "figure_eight" | "segments"; throws std::invalid_argument otherwise.
DrivingPatternKind driving_pattern_kind_from_string(const std::string& name);

struct DriveSegment {
  double duration_s = 1.0;  ///< > 0
  double v_l = 0.0;         ///< m/s, finite
  double v_r = 0.0;         ///< m/s, finite
};

struct DrivingPatternParams {
  DrivingPatternKind kind = DrivingPatternKind::kFigureEight;
  double speed = 0.5;                  ///< body speed v, m/s, finite (straight, circle, figure_eight)
  double turn_rate = 0.5;              ///< w (circle) or its amplitude (figure_eight), rad/s, finite
  double period = 20.0;                ///< figure-eight period, s, > 0
  double phase = 0.0;                  ///< figure-eight phase, rad, finite (pi/2: start turning at full rate)
  double track_width = 0.4;            ///< commanded no-slip track width B, m, > 0 (Pioneer 3-AT: 0.40)
  std::vector<DriveSegment> segments;  ///< kSegments: >= 1
  bool repeat = true;                  ///< kSegments: loop the list
};

class DrivingPattern {
 public:
  /// Validates the fields the kind uses; throws std::invalid_argument naming the field.
  explicit DrivingPattern(const DrivingPatternParams& params);

  /// Track speeds at time t (s). No allocation.
  TrackSpeeds at(double t) const;

  const DrivingPatternParams& params() const { return params_; }

 private:
  TrackSpeeds from_body(double v, double w) const;

  DrivingPatternParams params_;
  double total_ = 0.0;  // sum of segment durations
};

}  // namespace plexus::algorithms
