// velocity_heading_observer (estimator; localisation_observer): the velocity and heading
// observer of paper 003 (Thm 1, eqs. (11)-(14); docs/algorithms/unicycle.md). Ports bind
// to `<robot>/<port>` unless remapped; naming the position sensor `position` makes the
// defaults connect. The output names its IDL type (docs/topics.md).
//
//   in position {x, y} (PositionMeasurement), cmd {omega} (UnicycleCommand);
//   out heading {theta, speed, z2, z4} (HeadingEstimate)             003 Thm 1, eqs. (11)-(14)
//     (theta = atan2(z4, z2) made continuous in time; speed = |z|)
//   L2, L4 (required), discretisation (exact_arc | held_position), z2_0, z4_0 (0)
//
// It updates when its position input carries a new sample (so a slower sensor is handled)
// and outputs its initial estimate until inputs exist.
#include <cmath>
#include <memory>

#include "plexus/algorithms/unicycle/velocity_heading_observer.hpp"
#include "plexus/scenario/registry.hpp"
#include "services/common/input_values.hpp"
#include "services/localisation_observer/observer_common.hpp"

namespace plexus::scenario {
namespace {

namespace alg = plexus::algorithms;

class VelocityHeadingObserverComponent final : public Component {
 public:
  explicit VelocityHeadingObserverComponent(const ComponentConfig& c)
      : Component(c),
        obs_({c.params().required<double>("L2"), c.params().required<double>("L4"), discretisation(c.params())}),
        z0_(c.params().optional<double>("z2_0", 0.0), c.params().optional<double>("z4_0", 0.0)),
        base_step_(c.base_step),
        pos_(add_input("position", {"x", "y"}, "PositionMeasurement")),
        cmd_(add_input("cmd", {"omega"}, "UnicycleCommand")),
        out_(add_output("heading", {"theta", "speed", "z2", "z4"}, "HeadingEstimate")) {}

  void step(int64_t /*k*/, double /*t*/) override {
    const double dt = clock_.advance(pos_, base_step_);
    if (dt == 0.0) obs_.reset(z0_, vec2(pos_));
    if (dt > 0.0) obs_.update(dt, vec2(pos_), cmd_.valid() ? cmd_[0] : 0.0);
    const Eigen::Vector2d z = obs_.state().has_position ? obs_.state().z_hat : z0_;
    out_[0] = heading_(std::atan2(z.y(), z.x()));  // eq. (14), made continuous
    out_[1] = z.norm();
    out_[2] = z.x();
    out_[3] = z.y();
  }

 private:
  alg::VelocityHeadingObserver obs_;
  Eigen::Vector2d z0_;
  double base_step_;
  SampleClock clock_;
  ContinuousHeading heading_;
  InputPort& pos_;
  InputPort& cmd_;
  OutputPort& out_;
};

const ComponentRegistration kVelocityObserver{
    "velocity_heading_observer", ComponentKind::estimator,
    "velocity and heading observer from positions (paper 003 Thm 1)",
    [](const ComponentConfig& c) { return std::make_unique<VelocityHeadingObserverComponent>(c); }};

}  // namespace
}  // namespace plexus::scenario
