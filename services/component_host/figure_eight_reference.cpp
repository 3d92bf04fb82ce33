// figure_eight_reference (reference; component_host): the figure-eight of paper 000
// eq. (51) (docs/algorithms/unicycle.md). The output binds to `<robot>/reference` unless
// remapped and names its IDL type (docs/topics.md).
//
//   out reference {x, y, dx, dy, ddx, ddy} (PlanarReference)
//   h1 (m, 5), h2 (rad/s, 0.02), t0 (s, 3 pi / (2 h2): starts at (0, -h1))     000 eq. (51)
#include <memory>

#include "plexus/algorithms/unicycle/figure_eight_reference.hpp"
#include "plexus/scenario/registry.hpp"

namespace plexus::scenario {
namespace {

namespace alg = plexus::algorithms;

class FigureEightComponent final : public Component {
 public:
  explicit FigureEightComponent(const ComponentConfig& c)
      : Component(c),
        ref_(params(c.params())),
        out_(add_output("reference", {"x", "y", "dx", "dy", "ddx", "ddy"}, "PlanarReference")) {}

  void step(int64_t /*k*/, double t) override {
    const alg::ReferenceSample r = ref_.sample(t);
    out_[0] = r.p.x();
    out_[1] = r.p.y();
    out_[2] = r.dp.x();
    out_[3] = r.dp.y();
    out_[4] = r.ddp.x();
    out_[5] = r.ddp.y();
  }

 private:
  static alg::FigureEightParams params(const YamlMap& p) {
    alg::FigureEightParams f;
    f.h1 = p.optional<double>("h1", f.h1);
    f.h2 = p.optional<double>("h2", f.h2);
    if (!(f.h2 > 0.0)) p.fail("h2", "must be > 0 rad/s");
    f.t0 = p.optional<double>("t0", alg::FigureEightParams::paper_t0(f.h2));
    return f;
  }

  alg::FigureEightReference ref_;
  OutputPort& out_;
};

const ComponentRegistration kFigureEight{
    "figure_eight_reference", ComponentKind::reference,
    "figure-eight h1 sin(2 h2 (t+t0)), h1 sin(h2 (t+t0)) (paper 000 eq. (51))",
    [](const ComponentConfig& c) { return std::make_unique<FigureEightComponent>(c); }};

}  // namespace
}  // namespace plexus::scenario
