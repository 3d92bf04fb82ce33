// trajectory_tracking (controller; motion_controller): state- or output-feedback
// trajectory tracking of the unicycle (paper 000 eqs. (14), (27)-(28);
// docs/algorithms/unicycle.md). Ports bind to `<robot>/<port>` unless remapped; the output
// names its IDL type (docs/topics.md).
//
//   in reference {x, y, dx, dy, ddx, ddy} (PlanarReference), and truth/state {x, y, theta}
//     (Pose2D; feedback: state, 000 eq. (14)) or position {x, y} (PositionMeasurement) +
//     heading {z3, z4} (HeadingEstimate; feedback: output, eqs. (27)-(28));
//   out cmd {v, omega} (UnicycleCommand).
//   feedback: state | output (required), k1, k2, k3 (required; tunable while it runs:
//     plexus param), gamma (0.9),
//     min_speed_for_turn (1e-3), reference_min_speed (m/s, the reference's lowest speed
//     v_rm: gain condition (15) is checked against it at start; none: not checked)
//
// It outputs zeros until all its inputs exist.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <spdlog/spdlog.h>

#include "plexus/algorithms/unicycle/tracking_controller.hpp"
#include "plexus/base/logging.hpp"
#include "plexus/scenario/registry.hpp"
#include "services/common/input_values.hpp"
#include "services/motion_controller/controller_inputs.hpp"

namespace plexus::scenario {
namespace {

namespace alg = plexus::algorithms;

/// Warnings go to stderr (stdout carries `plexus sim --json`).
spdlog::logger& unicycle_log() {
  static const std::shared_ptr<spdlog::logger> logger = named_logger("scenario.unicycle");
  return *logger;
}

class TrajectoryTrackingComponent final : public Component {
 public:
  explicit TrajectoryTrackingComponent(const ComponentConfig& c)
      : Component(c),
        output_feedback_(is_second(c.params(), "feedback", "state", "output")),
        ctl_(params(c.params())),
        ref_(add_input("reference", kReferenceFields, "PlanarReference")),
        pos_(add_input(
            output_feedback_ ? "position" : "truth/state",
            output_feedback_ ? std::vector<std::string>{"x", "y"} : std::vector<std::string>{"x", "y", "theta"},
            output_feedback_ ? "PositionMeasurement" : "Pose2D")),
        est_(output_feedback_ ? &add_input("heading", {"z3", "z4"}, "HeadingEstimate") : nullptr),
        out_(add_output("cmd", {"v", "omega"}, "UnicycleCommand")) {
    check_gain_condition(c);
    const auto gain = [this](double alg::TrackingControllerParams::*member, const char* key, const char* what) {
      add_tunable(
          key, what, [this, member] { return ctl_.params().*member; },
          [this, member](double value) {
            alg::TrackingControllerParams p = ctl_.params();
            p.*member = value;
            ctl_.set_params(p);  // gain condition (15) is a start-time warning, not checked again here
          });
    };
    gain(&alg::TrackingControllerParams::k1, "k1", "m/s, > 0: gain of f1 = k1 atan(zeta1) (paper 000 eq. (14))");
    gain(&alg::TrackingControllerParams::k2, "k2", "m/s, > 0: gain of f2 = k2 atan(zeta2) (paper 000 eq. (14))");
    gain(&alg::TrackingControllerParams::k3, "k3", "1/s, > 0: heading gain (paper 000 eqs. (14), (28))");
  }

  void step(int64_t /*k*/, double /*t*/) override {
    alg::UnicycleInput u;
    if (ref_.valid() && pos_.valid() && (!est_ || est_->valid())) {
      const alg::ReferenceSample r = reference_sample(ref_);
      u = output_feedback_ ? ctl_.output_feedback(r, vec2(pos_), vec2(*est_)).input      // 000 eqs. (27)-(28)
                           : ctl_.state_feedback(r, {pos_[0], pos_[1], pos_[2]}).input;  // 000 eq. (14)
    }
    out_[0] = u.v;
    out_[1] = u.omega;
  }

 private:
  static alg::TrackingControllerParams params(const YamlMap& p) {
    alg::TrackingControllerParams t;
    t.k1 = p.required<double>("k1");
    t.k2 = p.required<double>("k2");
    t.k3 = p.required<double>("k3");
    t.gamma = p.optional<double>("gamma", t.gamma);
    t.min_speed_for_turn = p.optional<double>("min_speed_for_turn", t.min_speed_for_turn);
    return t;
  }

  /// Gain condition (15) of paper 000 against the configured reference: one warning, here.
  void check_gain_condition(const ComponentConfig& c) const {
    std::optional<double> v_rm;
    if (c.params().has("reference_min_speed")) {
      v_rm = c.params().required<double>("reference_min_speed");
      if (!(*v_rm > 0.0)) c.params().fail("reference_min_speed", "must be > 0 m/s");
    }
    if (!v_rm) {
      unicycle_log().info(
          "{}: gain condition (15) of paper 000 not checked: set reference_min_speed (m/s), the "
          "lowest speed of the reference {} (a figure-eight's: h1 h2 sqrt(31) / 8)",
          c.name, ref_.signal());
      return;
    }
    if (const auto warning = alg::check_gain_condition(ctl_.params(), *v_rm))
      c.warn(c.name + ": gain condition (15) of paper 000 not met against reference " + ref_.signal(),
             c.name + " (reference " + ref_.signal() + "): " + *warning);  // logged once the scenario is valid
  }

  bool output_feedback_;
  alg::TrajectoryTrackingController ctl_;
  InputPort& ref_;
  InputPort& pos_;
  InputPort* est_;
  OutputPort& out_;
};

const ComponentRegistration kTracking{
    "trajectory_tracking",
    ComponentKind::controller,
    "state / output-feedback trajectory tracking (paper 000 eqs. (14), (27)-(28))",
    [](const ComponentConfig& c) { return std::make_unique<TrajectoryTrackingComponent>(c); },
    {"paper000.controller"}};

}  // namespace
}  // namespace plexus::scenario
