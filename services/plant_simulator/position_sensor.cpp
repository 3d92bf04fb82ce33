// position_sensor (sensor; plant_simulator): the unicycle's position measurement of paper
// 000 section 6.3.2 (docs/algorithms/unicycle.md). Naming the sensor `position` makes the
// consumers' default ports connect (`<robot>/position`).
//
//   in truth/state {x, y}; out <sensor name> {x, y} (PositionMeasurement)
//   kind: exact | gaussian | rfid_grid, sigma (m), grid_spacing (m, 0.1),
//   grid_origin_x, grid_origin_y (m, 0); rate and seed are the common keys
#include <memory>
#include <stdexcept>
#include <string>

#include "plexus/algorithms/core/random.hpp"
#include "plexus/algorithms/unicycle/position_sensor.hpp"
#include "plexus/scenario/registry.hpp"
#include "services/common/input_values.hpp"

namespace plexus::scenario {
namespace {

namespace alg = plexus::algorithms;

class PositionSensorComponent final : public Component {
 public:
  explicit PositionSensorComponent(const ComponentConfig& c)
      : Component(c),
        sensor_(params(c)),
        rng_(sensor_.make_rng()),
        in_(add_input("truth/state", {"x", "y"}, "Pose2D")),
        out_(add_output(c.key, {"x", "y"}, "PositionMeasurement")) {}

  void step(int64_t /*k*/, double /*t*/) override {
    const Eigen::Vector2d m = sensor_.measure(vec2(in_), rng_);
    out_[0] = m.x();
    out_[1] = m.y();
  }

 private:
  static alg::PositionSensorParams params(const ComponentConfig& c) {
    const YamlMap& p = c.params();
    alg::PositionSensorParams s;
    const auto kind = p.required<std::string>("kind");
    try {
      s.kind = alg::position_sensor_kind_from_string(kind);
    } catch (const std::invalid_argument&) {
      p.fail("kind", "expected exact, gaussian or rfid_grid, got '" + kind + "'");
    }
    if (s.kind == alg::PositionSensorKind::kGaussian) s.sigma = p.required<double>("sigma");
    if (s.kind == alg::PositionSensorKind::kRfidGrid) {
      s.grid_spacing = p.optional<double>("grid_spacing", s.grid_spacing);
      s.grid_origin = {p.optional<double>("grid_origin_x", 0.0), p.optional<double>("grid_origin_y", 0.0)};
    }
    s.rate_hz = 1.0 / c.period();
    s.seed = c.seed;
    return s;
  }

  alg::PositionSensor sensor_;
  alg::Rng rng_;
  InputPort& in_;
  OutputPort& out_;
};

const ComponentRegistration kPositionSensor{
    "position_sensor", ComponentKind::sensor, "position {x, y}: exact, Gaussian or RFID grid (paper 000 6.3.2)",
    [](const ComponentConfig& c) { return std::make_unique<PositionSensorComponent>(c); }};

}  // namespace
}  // namespace plexus::scenario
