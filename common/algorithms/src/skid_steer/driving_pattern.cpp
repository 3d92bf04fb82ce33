// Driving patterns for the skid-steer plant (docs/algorithms/skid_steer.md).
#include "plexus/algorithms/skid_steer/driving_pattern.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "plexus/algorithms/core/validation.hpp"

namespace plexus::algorithms {

namespace {
constexpr const char* kWhereDrivingPattern = "driving_pattern";
}  // namespace

DrivingPatternKind driving_pattern_kind_from_string(const std::string& name) {
  if (name == "straight") return DrivingPatternKind::kStraight;
  if (name == "circle") return DrivingPatternKind::kCircle;
  // A sinusoidal turn rate at a constant speed: a slalom (docs/algorithms/skid_steer.md,
  // finding 3); "figure_eight" is the name the paper-case scenarios use for it.
  if (name == "figure_eight" || name == "slalom") return DrivingPatternKind::kFigureEight;
  if (name == "segments") return DrivingPatternKind::kSegments;
  throw std::invalid_argument(
      "driving_pattern: kind must be straight, circle, slalom (figure_eight) or segments (got '" + name + "')");
}

DrivingPattern::DrivingPattern(const DrivingPatternParams& params) : params_(params) {
  using namespace validation;
  require_positive(kWhereDrivingPattern, "track_width", params.track_width);
  switch (params.kind) {
    case DrivingPatternKind::kFigureEight:
      require_positive(kWhereDrivingPattern, "period", params.period);
      require_finite(kWhereDrivingPattern, "phase", params.phase);
      [[fallthrough]];
    case DrivingPatternKind::kCircle:
      require_finite(kWhereDrivingPattern, "turn_rate", params.turn_rate);
      [[fallthrough]];
    case DrivingPatternKind::kStraight: require_finite(kWhereDrivingPattern, "speed", params.speed); break;
    case DrivingPatternKind::kSegments:
      if (params.segments.empty()) throw std::invalid_argument("driving_pattern: segments must not be empty");
      for (std::size_t i = 0; i < params.segments.size(); ++i) {
        const std::string s = "segments[" + std::to_string(i) + "]";
        require_positive(kWhereDrivingPattern, s + ".duration_s", params.segments[i].duration_s);
        require_finite(kWhereDrivingPattern, s + ".v_l", params.segments[i].v_l);
        require_finite(kWhereDrivingPattern, s + ".v_r", params.segments[i].v_r);
        total_ += params.segments[i].duration_s;
      }
      break;
  }
}

TrackSpeeds DrivingPattern::from_body(double v, double w) const {
  const double d = 0.5 * w * params_.track_width;
  return {v - d, v + d};
}

TrackSpeeds DrivingPattern::at(double t) const {
  switch (params_.kind) {
    case DrivingPatternKind::kStraight: return from_body(params_.speed, 0.0);
    case DrivingPatternKind::kCircle: return from_body(params_.speed, params_.turn_rate);
    case DrivingPatternKind::kFigureEight:
      return from_body(params_.speed,
                       params_.turn_rate * std::sin(2.0 * std::numbers::pi * t / params_.period + params_.phase));
    case DrivingPatternKind::kSegments: {
      double local = t;
      if (params_.repeat) local = std::fmod(std::max(t, 0.0), total_);
      for (const DriveSegment& s : params_.segments) {
        if (local < s.duration_s) return {s.v_l, s.v_r};
        local -= s.duration_s;
      }
      return {params_.segments.back().v_l, params_.segments.back().v_r};
    }
  }
  return {};
}

}  // namespace plexus::algorithms
