// path_following (controller; motion_controller): state-feedback or observer-based path
// following of the unicycle (paper 003 eqs. (5), (15)-(16); docs/algorithms/unicycle.md).
// Ports bind to `<robot>/<port>` unless remapped; the output names its IDL type
// (docs/topics.md).
//
//   in path {h, hx, hy, hxx, hxy, hyy} (PathSample), and truth/state {theta} (Pose2D;
//     feedback: state, 003 eq. (5)) or heading {z2, z4} (HeadingEstimate; feedback:
//     observer, eqs. (15)-(16));
//   out cmd {v = u1, omega = u2} (UnicycleCommand).
//   feedback: state | observer (required), u1 (m/s, != 0), k1, k2 (required),
//     min_abs_g (1e-3), max_turn_rate (inf)
//
// It outputs omega = 0 (and v = u1) until its inputs exist.
#include <cmath>
#include <memory>

#include "plexus/algorithms/unicycle/geometric_path.hpp"
#include "plexus/algorithms/unicycle/path_following_controller.hpp"
#include "plexus/scenario/registry.hpp"
#include "services/common/input_values.hpp"
#include "services/motion_controller/controller_inputs.hpp"

namespace plexus::scenario {
namespace {

namespace alg = plexus::algorithms;

class PathFollowingComponent final : public Component {
 public:
  explicit PathFollowingComponent(const ComponentConfig& c)
      : Component(c),
        observer_(is_second(c.params(), "feedback", "state", "observer")),
        u1_(c.params().required<double>("u1")),
        ctl_(params(c.params())),
        path_(add_input("path", {"h", "hx", "hy", "hxx", "hxy", "hyy"}, "PathSample")),
        vel_(observer_ ? add_input("heading", {"z2", "z4"}, "HeadingEstimate")
                       : add_input("truth/state", {"theta"}, "Pose2D")),
        out_(add_output("cmd", {"v", "omega"}, "UnicycleCommand")) {
    if (!(std::isfinite(u1_) && u1_ != 0.0)) c.params().fail("u1", "must be finite and != 0 m/s");
  }

  void step(int64_t /*k*/, double /*t*/) override {
    double u2 = 0.0;
    if (path_.valid() && vel_.valid()) {
      alg::PathEvaluation e;
      e.h = path_[0];
      e.gradient = {path_[1], path_[2]};
      e.hessian << path_[3], path_[4], path_[4], path_[5];
      // State feedback (003 eq. (5)): w = u1 (cos theta, sin theta); observer-based
      // (eqs. (15)-(16)): w = z_hat.
      const Eigen::Vector2d w =
          observer_ ? vec2(vel_) : Eigen::Vector2d(u1_ * std::cos(vel_[0]), u1_ * std::sin(vel_[0]));
      u2 = ctl_.compute(e, w).u2;
    }
    out_[0] = u1_;
    out_[1] = u2;
  }

 private:
  static alg::PathFollowingParams params(const YamlMap& p) {
    alg::PathFollowingParams f;
    f.k1 = p.required<double>("k1");
    f.k2 = p.required<double>("k2");
    f.min_abs_g = p.optional<double>("min_abs_g", f.min_abs_g);
    f.max_turn_rate = p.optional<double>("max_turn_rate", f.max_turn_rate);
    return f;
  }

  bool observer_;
  double u1_;
  alg::PathFollowingController ctl_;
  InputPort& path_;
  InputPort& vel_;
  OutputPort& out_;
};

const ComponentRegistration kPathFollowing{
    "path_following", ComponentKind::controller,
    "state-feedback / observer-based path following (paper 003 eqs. (5), (15))",
    [](const ComponentConfig& c) { return std::make_unique<PathFollowingComponent>(c); }};

}  // namespace
}  // namespace plexus::scenario
