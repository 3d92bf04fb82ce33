// heading_observer (estimator; localisation_observer): the reduced-order heading observer
// of paper 000 (Thm 1, eqs. (5)-(11); docs/algorithms/unicycle.md). Ports bind to
// `<robot>/<port>` unless remapped; naming the position sensor `position` makes the
// defaults connect. The output names its IDL type (docs/topics.md).
//
//   in position {x, y} (PositionMeasurement), cmd {v, omega} (UnicycleCommand);
//   out heading {theta, z3, z4, L} (HeadingEstimate)                 000 Thm 1, eqs. (5)-(11)
//     (theta = atan2(z4, z3) made continuous in time, starting in (-pi, pi], so it
//     overlays the plant's continuous theta; L is the gain, for observer_rate_bound)
//   L (required; tunable while it runs: plexus param), discretisation: exact_arc | held_position,
//     z3_0, z4_0 (0)
//
// It updates when its position input carries a new sample (so a slower sensor is handled)
// and outputs its initial estimate until inputs exist.
#include <cmath>
#include <memory>

#include "plexus/algorithms/unicycle/heading_observer.hpp"
#include "plexus/msg/messages.hpp"
#include "plexus/scenario/registry.hpp"
#include "services/common/input_values.hpp"
#include "services/localisation_observer/observer_common.hpp"

namespace plexus::scenario {
namespace {

namespace alg = plexus::algorithms;

class HeadingObserverComponent final : public Component {
 public:
  explicit HeadingObserverComponent(const ComponentConfig& c)
      : Component(c),
        obs_({c.params().required<double>("L"), discretisation(c.params())}),
        z0_(c.params().optional<double>("z3_0", 0.0), c.params().optional<double>("z4_0", 0.0)),
        base_step_(c.base_step),
        pos_(add_input("position", {"x", "y"}, "PositionMeasurement")),
        cmd_(add_input<msg::UnicycleCommand>("cmd")),
        out_(add_output("heading", {"theta", "z3", "z4", "L"}, "HeadingEstimate")) {
    add_tunable(
        "L", "observer gain, > 0 (paper 000 eq. (5)); the estimate's gain field", [this] { return obs_.params().L; },
        [this](double L) {
          alg::HeadingObserverParams p = obs_.params();
          p.L = L;
          obs_.set_params(p);
        });
  }

  void step(int64_t /*k*/, double /*t*/) override {
    const double dt = clock_.advance(pos_, base_step_);
    if (dt == 0.0) obs_.reset(z0_, vec2(pos_));  // paper 000: z_hat(0) = (0, 0)
    if (dt > 0.0) obs_.update(dt, vec2(pos_), {cmd_.valid() ? cmd_->v() : 0.0, cmd_.valid() ? cmd_->omega() : 0.0});
    const Eigen::Vector2d z = obs_.state().has_position ? obs_.state().z_hat : z0_;
    out_[0] = heading_(std::atan2(z.y(), z.x()));  // eq. (11), made continuous
    out_[1] = z.x();
    out_[2] = z.y();
    out_[3] = obs_.params().L;
  }

 private:
  alg::HeadingObserver obs_;
  Eigen::Vector2d z0_;
  double base_step_;
  SampleClock clock_;
  ContinuousHeading heading_;
  InputPort& pos_;
  TypedInput<msg::UnicycleCommand>& cmd_;
  OutputPort& out_;
};

const ComponentRegistration kHeadingObserver{
    "heading_observer", ComponentKind::estimator, "reduced-order heading observer from positions (paper 000 Thm 1)",
    [](const ComponentConfig& c) { return std::make_unique<HeadingObserverComponent>(c); }};

}  // namespace
}  // namespace plexus::scenario
