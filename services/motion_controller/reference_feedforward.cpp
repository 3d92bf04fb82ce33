// reference_feedforward (controller; motion_controller): open loop along a planar
// reference (paper 000 section 6.1 drives the observer-only run with v = v_r,
// omega = theta_r'; docs/algorithms/unicycle.md). Ports bind to `<robot>/<port>` unless
// remapped; the output names its IDL type (docs/topics.md).
//
//   in reference {x, y, dx, dy, ddx, ddy} (PlanarReference);
//   out cmd {v = |p_r'|, omega = heading rate of p_r} (UnicycleCommand). No parameters.
#include <cmath>
#include <memory>

#include "plexus/scenario/registry.hpp"
#include "services/motion_controller/controller_inputs.hpp"

namespace plexus::scenario {
namespace {

namespace alg = plexus::algorithms;

/// Open loop along the reference: v = |p_r'|, omega = (x_r' y_r'' - y_r' x_r'') / v^2
/// (paper 000 section 6.1 drives the observer-only run with v = v_r, omega = theta_r').
class ReferenceFeedforward final : public Component {
 public:
  explicit ReferenceFeedforward(const ComponentConfig& c)
      : Component(c),
        ref_(add_input("reference", kReferenceFields, "PlanarReference")),
        out_(add_output("cmd", {"v", "omega"}, "UnicycleCommand")) {}

  void step(int64_t /*k*/, double /*t*/) override {
    const alg::ReferenceSample r = reference_sample(ref_);
    const double v2 = r.dp.squaredNorm();
    out_[0] = std::sqrt(v2);
    out_[1] = v2 > 0.0 ? (r.dp.x() * r.ddp.y() - r.dp.y() * r.ddp.x()) / v2 : 0.0;
  }

 private:
  InputPort& ref_;
  OutputPort& out_;
};

const ComponentRegistration kFeedforward{
    "reference_feedforward", ComponentKind::controller,
    "open loop along the reference: v = |p_r'|, omega = its heading rate",
    [](const ComponentConfig& c) { return std::make_unique<ReferenceFeedforward>(c); }};

}  // namespace
}  // namespace plexus::scenario
