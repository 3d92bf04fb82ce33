// icr_odometry (estimator; icr_estimator): dead reckoning of the skid-steer robot with the
// no-slip, a fixed or the estimated ICR model (paper 001 section 4;
// docs/algorithms/skid_steer.md). Ports bind to `<robot>/<port>` unless remapped; the
// output names its IDL type (docs/topics.md).
//
//   in wheels {v_l, v_r} (TrackSpeeds), truth/state {x, y, theta} (SkidSteerTruth; read
//     once, at `start`), with model estimated: icr {y_l, y_r, x_G} (IcrEstimate);
//   out <service name> {x, y, theta} (Pose2D)
//   model: no_slip (track_width 0.4) | fixed (y_l, y_r, x_G) | estimated; start (0 s)
#include <memory>
#include <string>

#include "plexus/algorithms/skid_steer/icr_odometry.hpp"
#include "plexus/scenario/registry.hpp"
#include "services/common/input_values.hpp"

namespace plexus::scenario {
namespace {

namespace alg = plexus::algorithms;

class IcrOdometryComponent final : public Component {
 public:
  explicit IcrOdometryComponent(const ComponentConfig& c)
      : Component(c),
        model_(model(c.params())),
        start_(c.params().optional<double>("start", 0.0)),
        h_(c.period()),
        wheels_(add_input("wheels", {"v_l", "v_r"}, "TrackSpeeds")),
        truth_(add_input("truth/state", {"x", "y", "theta"}, "SkidSteerTruth")),
        estimate_(model_ == Model::kEstimated ? &add_input("icr", {"y_l", "y_r", "x_G"}, "IcrEstimate") : nullptr),
        out_(add_output(c.key, {"x", "y", "theta"}, "Pose2D")) {
    const YamlMap& p = c.params();
    if (!(start_ >= 0.0)) p.fail("start", "must be >= 0 s");
    if (model_ == Model::kNoSlip) fixed_ = alg::no_slip_icr(p.optional<double>("track_width", 0.4));
    if (model_ == Model::kFixed) {
      fixed_ = {p.required<double>("y_l"), p.required<double>("y_r"), p.required<double>("x_G")};
      alg::validate_icr("icr_odometry", fixed_);
    }
  }

  void step(int64_t /*k*/, double t) override {
    if (!started_) {
      if (t + 1e-9 >= start_ && truth_.valid()) {
        odo_.reset(pose_of(truth_));
        started_ = true;
      }
    } else if (wheels_.valid()) {
      const alg::IcrParams icr = estimate_ ? alg::IcrParams{(*estimate_)[0], (*estimate_)[1], (*estimate_)[2]} : fixed_;
      odo_.step({wheels_[0], wheels_[1]}, icr, h_);
    }
    out_[0] = odo_.pose().x;
    out_[1] = odo_.pose().y;
    out_[2] = odo_.pose().theta;
  }

 private:
  enum class Model { kNoSlip, kFixed, kEstimated };
  static Model model(const YamlMap& p) {
    const auto m = p.required<std::string>("model");
    if (m == "no_slip") return Model::kNoSlip;
    if (m == "fixed") return Model::kFixed;
    if (m == "estimated") return Model::kEstimated;
    p.fail("model", "expected no_slip, fixed or estimated, got '" + m + "'");
  }

  Model model_;
  double start_;
  double h_;
  alg::IcrParams fixed_{};
  alg::IcrOdometry odo_;
  bool started_ = false;
  InputPort& wheels_;
  InputPort& truth_;
  InputPort* estimate_;
  OutputPort& out_;
};

const ComponentRegistration kIcrOdometry{
    "icr_odometry", ComponentKind::estimator, "dead reckoning with the no-slip, a fixed or the estimated ICR model",
    [](const ComponentConfig& c) { return std::make_unique<IcrOdometryComponent>(c); }};

}  // namespace
}  // namespace plexus::scenario
