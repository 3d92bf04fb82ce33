// Registry entries that fit any family: a measurement sensor, a constant command and a
// circle reference. Parameters are documented in docs/scenarios.md.
//
//   measurement (sensor): reads `fields` of signal `source` (default: the robot's
//     truth/state), adds N(0, noise_std^2) to each field (Box-Muller on the sensor's own
//     seed), then rounds each field to the nearest multiple of `quantum` (0: no
//     quantisation). Output: `<robot>/<sensor name>` with the same fields, carried between
//     processes as the IDL type `message` (for example PositionMeasurement: the fields must
//     be members of it, docs/topics.md); without `message` it runs in `plexus sim` only.
//   constant_command (controller): output cmd {v, omega} = the parameters v, omega.
//   circle_reference (reference): output reference {x, y, dx, dy, ddx, ddy}: the circle of
//     `radius` around (center_x, center_y), run at `speed` m/s (negative: clockwise)
//     from angle `phase0`.
#include <cmath>
#include <memory>

#include "plexus/algorithms/core/random.hpp"
#include "plexus/scenario/params.hpp"
#include "plexus/scenario/registry.hpp"

namespace plexus::scenario {
namespace {

class Measurement final : public Component {
 public:
  explicit Measurement(const ComponentConfig& c)
      : Component(c),
        noise_std_(optional_non_negative(c.params(), "noise_std")),
        quantum_(optional_non_negative(c.params(), "quantum")),
        rng_(c.seed),
        in_(add_input(c.params().optional<std::string>("source", "truth/state"), required_names(c.params(), "fields", kMaxSignalFields),
                      "")),  // any signal of its own robot: read in its process
        out_(add_output(c.key, in_.fields(), c.params().optional<std::string>("message", ""))) {}

  void step(int64_t /*k*/, double /*t*/) override {
    for (std::size_t i = 0; i < in_.fields().size(); ++i) {
      double v = in_[i];
      if (noise_std_ > 0.0) v += noise_std_ * rng_.normal();
      if (quantum_ > 0.0) v = quantum_ * std::round(v / quantum_);
      out_[i] = v;
    }
  }

 private:
  double noise_std_;
  double quantum_;
  algorithms::Rng rng_;
  InputPort& in_;
  OutputPort& out_;
};

class ConstantCommand final : public Component {
 public:
  explicit ConstantCommand(const ComponentConfig& c)
      : Component(c),
        v_(c.params().required<double>("v")),
        omega_(c.params().required<double>("omega")),
        out_(add_output("cmd", {"v", "omega"}, "UnicycleCommand")) {}

  void step(int64_t /*k*/, double /*t*/) override {
    out_[0] = v_;
    out_[1] = omega_;
  }

 private:
  double v_;
  double omega_;
  OutputPort& out_;
};

class CircleReference final : public Component {
 public:
  explicit CircleReference(const ComponentConfig& c)
      : Component(c),
        cx_(c.params().optional<double>("center_x", 0.0)),
        cy_(c.params().optional<double>("center_y", 0.0)),
        radius_(c.params().required<double>("radius")),
        speed_(c.params().required<double>("speed")),
        phase0_(c.params().optional<double>("phase0", 0.0)),
        out_(add_output("reference", {"x", "y", "dx", "dy", "ddx", "ddy"}, "PlanarReference")) {
    if (radius_ <= 0.0) c.params().fail("radius", "must be > 0 m");
    if (speed_ == 0.0) c.params().fail("speed", "must not be 0");
  }

  void step(int64_t /*k*/, double t) override {
    const double w = speed_ / radius_;
    const double a = phase0_ + w * t;
    const double c = std::cos(a);
    const double s = std::sin(a);
    out_[0] = cx_ + radius_ * c;
    out_[1] = cy_ + radius_ * s;
    out_[2] = -radius_ * w * s;
    out_[3] = radius_ * w * c;
    out_[4] = -radius_ * w * w * c;
    out_[5] = -radius_ * w * w * s;
  }

 private:
  double cx_, cy_, radius_, speed_, phase0_;
  OutputPort& out_;
};

const ComponentRegistration kMeasurement{
    "measurement", ComponentKind::sensor, "fields of a signal with Gaussian noise and quantisation",
    [](const ComponentConfig& c) { return std::make_unique<Measurement>(c); }};
const ComponentRegistration kConstantCommand{
    "constant_command", ComponentKind::controller, "open loop: constant cmd {v, omega}",
    [](const ComponentConfig& c) { return std::make_unique<ConstantCommand>(c); }};
const ComponentRegistration kCircleReference{
    "circle_reference", ComponentKind::reference, "circle at constant speed: reference {x, y, dx, dy, ddx, ddy}",
    [](const ComponentConfig& c) { return std::make_unique<CircleReference>(c); }};

}  // namespace
}  // namespace plexus::scenario
