// circle_reference (reference; component_host): a circle at constant speed, for any
// family with a planar reference. Parameters are documented in docs/scenarios.md; the
// output binds to `<robot>/reference` unless remapped and names its IDL type
// (docs/topics.md).
//
//   out reference {x, y, dx, dy, ddx, ddy} (PlanarReference): the circle of `radius`
//   (required, > 0 m) around (center_x, center_y) (0, 0), run at `speed` m/s (required,
//   != 0; negative: clockwise) from angle `phase0` (rad, 0).
#include <cmath>
#include <memory>

#include "plexus/scenario/registry.hpp"

namespace plexus::scenario {
namespace {

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

const ComponentRegistration kCircleReference{
    "circle_reference", ComponentKind::reference, "circle at constant speed: reference {x, y, dx, dy, ddx, ddy}",
    [](const ComponentConfig& c) { return std::make_unique<CircleReference>(c); }};

}  // namespace
}  // namespace plexus::scenario
