// skid_steer_driver (controller; motion_controller): an open-loop driving pattern for the
// skid-steer robot (paper 001; docs/algorithms/skid_steer.md). The output binds to
// `<robot>/cmd` unless remapped and names its IDL type (docs/topics.md).
//
//   out cmd {v_l, v_r} (TrackCommand)
//   pattern: straight | circle | slalom (also named figure_eight) | segments; speed (0.5), turn_rate (0.5),
//   period (20), phase (0), track_width (0.4), segments: [[duration_s, v_l, v_r], ...], repeat (true)
#include <memory>
#include <stdexcept>
#include <string>

#include "plexus/algorithms/skid_steer/driving_pattern.hpp"
#include "plexus/scenario/params.hpp"
#include "plexus/scenario/registry.hpp"

namespace plexus::scenario {
namespace {

namespace alg = plexus::algorithms;

alg::DrivingPatternParams driver_params(const YamlMap& p) {
  alg::DrivingPatternParams d;
  const auto kind = p.required<std::string>("pattern");
  try {
    d.kind = alg::driving_pattern_kind_from_string(kind);
  } catch (const std::invalid_argument&) {
    p.fail("pattern", "expected straight, circle, slalom (figure_eight) or segments, got '" + kind + "'");
  }
  d.speed = p.optional<double>("speed", d.speed);
  d.turn_rate = p.optional<double>("turn_rate", d.turn_rate);
  d.period = p.optional<double>("period", d.period);
  d.phase = p.optional<double>("phase", d.phase);
  d.track_width = p.optional<double>("track_width", d.track_width);
  d.repeat = p.optional<bool>("repeat", d.repeat);
  if (d.kind == alg::DrivingPatternKind::kSegments) {
    for (const auto& e : p.sequence("segments")) {
      const auto v = numbers(p, e, "segments", 3);
      d.segments.push_back({v[0], v[1], v[2]});
    }
  }
  return d;
}

class DriverComponent final : public Component {
 public:
  explicit DriverComponent(const ComponentConfig& c)
      : Component(c), pattern_(driver_params(c.params())), out_(add_output("cmd", {"v_l", "v_r"}, "TrackCommand")) {}
  void step(int64_t /*k*/, double t) override {
    const alg::TrackSpeeds u = pattern_.at(t);
    out_[0] = u.v_l;
    out_[1] = u.v_r;
  }

 private:
  alg::DrivingPattern pattern_;
  OutputPort& out_;
};

const ComponentRegistration kDriver{"skid_steer_driver", ComponentKind::controller,
                                    "driving pattern (straight, circle, slalom, segments); out cmd {v_l, v_r}",
                                    [](const ComponentConfig& c) { return std::make_unique<DriverComponent>(c); }};

}  // namespace
}  // namespace plexus::scenario
