// icr_odometry (estimator; icr_estimator): dead reckoning of the skid-steer robot with the
// no-slip, a fixed or the estimated ICR model (paper 001 section 4;
// docs/algorithms/skid_steer.md). Ports bind to `<robot>/<port>` unless remapped; the
// output names its IDL type (docs/topics.md).
//
//   in wheels {v_l, v_r} (TrackSpeeds), truth/state {x, y, theta} (SkidSteerTruth; read
//     once, at `start`), with model estimated: icr {y_l, y_r, x_G, model_age} (IcrEstimate);
//   out <service name> {x, y, theta} (Pose2D)
//   model: no_slip (track_width 0.4) | fixed (y_l, y_r, x_G) | estimated; start (0 s);
//   with estimated: revise_s (3 s; 0: never)
//
// With model estimated, the estimate's model_age says since when its ICRs apply (data time
// minus model_age). When that time moves (a reset of the ICR EKF that placed the new ICRs at
// the terrain switch it re-estimated, up to rewind_s before the reset), the steps from then
// on are integrated again with the new ICRs, as far back as revise_s: the odometry does not
// keep the heading error the old terrain's ICRs made between the switch and its detection.
// For revise_s after the model's start, every step integrates the steps since it again with
// the newest estimate (the ICRs are constant per terrain and the filter refines them).
#include <cmath>
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
        estimate_(model_ == Model::kEstimated ? &add_input("icr", {"y_l", "y_r", "x_G", "model_age"}, "IcrEstimate")
                                              : nullptr),
        out_(add_output(c.key, {"x", "y", "theta"}, "Pose2D")),
        base_step_(c.base_step),
        revise_s_(revision_seconds(c, model_ == Model::kEstimated)),
        odo_(static_cast<int>(std::lround(revise_s_ / c.period()))) {
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
      if (estimate_ && estimate_->valid()) {
        // Since when the estimate's ICRs apply (its data time minus model_age): when that
        // moves, and for revise_s after it, the kept steps since then are integrated again
        // with the newest estimate (the ICRs are constant per terrain; the filter refines them).
        const double since = static_cast<double>(estimate_->sample().step) * base_step_ - (*estimate_)[3];
        const bool moved = have_since_ && std::abs(since - model_since_) > 0.5 * h_;
        if (!have_since_ || moved) model_since_ = since;
        have_since_ = true;
        if (moved || (revise_s_ > 0.0 && t - model_since_ <= revise_s_)) odo_.revise(model_since_, icr);
      }
      odo_.step({wheels_[0], wheels_[1]}, icr, h_, t);
    }
    out_[0] = odo_.pose().x;
    out_[1] = odo_.pose().y;
    out_[2] = odo_.pose().theta;
  }

 private:
  enum class Model { kNoSlip, kFixed, kEstimated };
  static double revision_seconds(const ComponentConfig& c, bool estimated) {
    const YamlMap& p = c.params();
    if (!estimated) {
      if (p.has("revise_s")) p.fail("revise_s", "only used with model: estimated");
      return 0.0;
    }
    const double s = p.optional<double>("revise_s", 3.0);
    if (!(s >= 0.0 && s <= 60.0)) p.fail("revise_s", "must be in [0, 60] s");
    return s;
  }

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
  bool started_ = false;
  InputPort& wheels_;
  InputPort& truth_;
  InputPort* estimate_;
  OutputPort& out_;
  double base_step_;
  double revise_s_;
  alg::RevisableIcrOdometry odo_;
  double model_since_ = 0.0;  ///< data time since which the estimate's ICRs apply, as last read
  bool have_since_ = false;
};

const ComponentRegistration kIcrOdometry{
    "icr_odometry", ComponentKind::estimator, "dead reckoning with the no-slip, a fixed or the estimated ICR model",
    [](const ComponentConfig& c) { return std::make_unique<IcrOdometryComponent>(c); }};

}  // namespace
}  // namespace plexus::scenario
