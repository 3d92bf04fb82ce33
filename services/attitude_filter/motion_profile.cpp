// motion_profile (reference; attitude_filter): the balancing robot's travel reference:
// balance, then ramp to a speed (paper 002; docs/algorithms/balancing.md). The output
// binds to `<robot>/reference` unless remapped and names its IDL type (docs/topics.md).
//
//   out reference {x, v} (TravelState): hold_time (s, 1), ramp_time (s, 1.5), speed (m/s, 0.3)
#include <memory>

#include "plexus/algorithms/balancing/balancing_controller.hpp"
#include "plexus/scenario/registry.hpp"

namespace plexus::scenario {
namespace {

namespace alg = plexus::algorithms;

class MotionProfileComponent final : public Component {
 public:
  explicit MotionProfileComponent(const ComponentConfig& c)
      : Component(c), profile_(params(c.params())), out_(add_output("reference", {"x", "v"}, "TravelState")) {}

  void step(int64_t /*k*/, double t) override {
    const alg::MotionReference r = profile_.sample(t);
    out_[0] = r.x;
    out_[1] = r.v;
  }

 private:
  static alg::MotionProfileParams params(const YamlMap& p) {
    alg::MotionProfileParams m;
    m.hold_time = p.optional<double>("hold_time", m.hold_time);
    m.ramp_time = p.optional<double>("ramp_time", m.ramp_time);
    m.speed = p.optional<double>("speed", m.speed);
    return m;
  }

  alg::MotionProfile profile_;
  OutputPort& out_;
};

const ComponentRegistration kProfile{
    "motion_profile", ComponentKind::reference, "balance, then ramp to a speed; out reference {x, v}",
    [](const ComponentConfig& c) { return std::make_unique<MotionProfileComponent>(c); }};

}  // namespace
}  // namespace plexus::scenario
