// icr_ekf (estimator; icr_estimator): the 6-state ICR EKF of paper 001 (section 3.1, eqs.
// (7)-(17), (21)-(22)) with optional classifier-driven covariance reset
// (docs/algorithms/skid_steer.md has every parameter with its default and the paper's
// value). Ports bind to `<robot>/<port>` unless remapped; the output names its IDL type
// (docs/topics.md).
//
//   in wheels {v_l, v_r} (TrackSpeeds), gps {x, y, theta} (Pose2D), and with
//     adaptive_reset: terrain {class, windows} (TerrainClass); out icr {x, y, theta, y_l,
//     y_r, x_G, resets, sd_y_l, sd_y_r, sd_x_G, model_age} (IcrEstimate)
//   q_diag, r_diag, p0_diag, p_b_diag (lists; paper eq. (21)-(22)), initial_icr ([1, -1, 1]),
//   process_noise (dt_squared), enforce_track_sides (true), track_side_margin (0.01),
//   adaptive_reset (false), consecutive_windows (2), reset_mode (covariance | prior),
//   icr_library (required with prior: a terrain ICR library file, relative to the scenario's
//   folder), prior_check_updates (60), rewind_s (3 s with prior, 0 with covariance; 0..30),
//   rewind_candidates (60)
//
// reset_mode prior (plexus; docs/algorithms/skid_steer.md "Prior reset"): on a confirmed
// change to a terrain the library knows, the ICRs restart from that terrain's learned values
// and covariance instead of paper 001's P_B around the old terrain's values. A wrong label
// gives a wrong prior, so the paper's covariance reset runs beside it as a second hypothesis
// (a shadow filter on the same inputs) for the next prior_check_updates GPS updates; the
// hypothesis whose innovations are less likely (summed NIS + log det S) is dropped, as soon
// as the sums differ by 10 (a likelihood ratio of e^5) or at the end: a wrong prior is
// replaced by the paper's filter. A terrain the library lacks gets the paper's reset.
//
// rewind_s (common/algorithms/include/plexus/algorithms/skid_steer/icr_terrain_reset.hpp):
// each reset is applied at the switch time it makes most likely among the last rewind_s
// seconds of steps, which are filtered again, not at the confirmation a second after the
// switch; model_age publishes since when the published ICRs apply (icr_odometry integrates
// those steps again).
//
// It starts (pose from the GPS) at its first GPS sample; from then on it predicts with the
// track speeds at every step and updates at every new GPS sample.
//
// Sample times (realtime; docs/distributed.md, "Late samples"): each step predicts over its
// own period with the latest track speeds, held over the period (the sim's zero-order hold).
// A GPS pose is a measurement of the pose at its own step: the realtime host runs each
// step of the EKF once the samples it reads have arrived, so a GPS sample meets the
// prediction of its own step. One that arrives later than that (first read at a step one
// EKF period or more after its own) would update the pose of a later time with an older
// position, a bias of speed x delay that the ICRs absorb; it is dropped and counted
// (dropped_late_samples). In `plexus sim` and lockstep every GPS sample is read at its step.
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

#include "plexus/algorithms/skid_steer/icr_ekf.hpp"
#include "plexus/algorithms/skid_steer/icr_terrain_reset.hpp"
#include "plexus/algorithms/skid_steer/terrain_change_detector.hpp"
#include "plexus/algorithms/skid_steer/terrain_icr_library.hpp"
#include "plexus/scenario/params.hpp"
#include "plexus/scenario/registry.hpp"
#include "services/common/input_values.hpp"
#include "services/common/new_sample.hpp"

namespace plexus::scenario {
namespace {

namespace alg = plexus::algorithms;

template <int N>
Eigen::Matrix<double, N, 1> optional_vector(const YamlMap& p, const std::string& key,
                                            const Eigen::Matrix<double, N, 1>& fallback) {
  if (!p.has(key)) return fallback;
  const auto v = numbers(p, p.node(key), key, N);
  return Eigen::Map<const Eigen::Matrix<double, N, 1>>(v.data());
}

alg::IcrEkfParams ekf_params(const YamlMap& p) {
  alg::IcrEkfParams e;
  e.q_diag = optional_vector<6>(p, "q_diag", e.q_diag);
  e.r_diag = optional_vector<3>(p, "r_diag", e.r_diag);
  e.p0_diag = optional_vector<6>(p, "p0_diag", e.p0_diag);
  e.p_b_diag = optional_vector<6>(p, "p_b_diag", e.p_b_diag);
  const Eigen::Vector3d icr = optional_vector<3>(p, "initial_icr", Eigen::Vector3d(1.0, -1.0, 1.0));
  e.initial_icr = {icr(0), icr(1), icr(2)};
  e.enforce_track_sides = p.optional<bool>("enforce_track_sides", e.enforce_track_sides);
  e.track_side_margin = p.optional<double>("track_side_margin", e.track_side_margin);
  const auto model = p.optional<std::string>("process_noise", "dt_squared");
  try {
    e.process_noise = alg::process_noise_model_from_string(model);
  } catch (const std::invalid_argument&) {
    p.fail("process_noise", "expected dt_squared, continuous or per_step, got '" + model + "'");
  }
  return e;
}

alg::TerrainIcrLibrary library_of(const ComponentConfig& c, bool prior) {
  const YamlMap& p = c.params();
  if (!prior) {
    if (p.has("icr_library")) p.fail("icr_library", "only used with reset_mode: prior");
    return {};
  }
  if (!p.has("icr_library")) p.fail("icr_library", "required with reset_mode: prior (a terrain ICR library file)");
  try {
    return alg::load_terrain_icr_library(scenario_relative_path(c, "icr_library"));
  } catch (const alg::TrainingFileError& e) {
    p.fail("icr_library", e.what());
  }
}

bool prior_mode(const YamlMap& p) { return choice(p, "reset_mode", "covariance", {"covariance", "prior"}) == "prior"; }

alg::IcrTerrainResetOptions reset_options(const ComponentConfig& c, bool prior) {
  const YamlMap& p = c.params();
  alg::IcrTerrainResetOptions o;
  o.check_updates = p.optional<int>("prior_check_updates", o.check_updates);
  if (o.check_updates < 1) p.fail("prior_check_updates", "must be >= 1");
  o.max_candidates = p.optional<int>("rewind_candidates", o.max_candidates);
  if (o.max_candidates < 1) p.fail("rewind_candidates", "must be >= 1");
  // Default: rewound for plexus's prior reset, at the confirmation for paper 001's reset.
  const double rewind_s = p.optional<double>("rewind_s", prior ? 3.0 : 0.0);
  if (!(rewind_s >= 0.0 && rewind_s <= 30.0)) p.fail("rewind_s", "must be in [0, 30] s");
  if (p.has("rewind_s") && !p.optional<bool>("adaptive_reset", false))
    p.fail("rewind_s", "only used with adaptive_reset: true");
  o.rewind_steps = static_cast<int>(std::lround(rewind_s / c.period()));
  return o;
}

class IcrEkfComponent final : public Component {
 public:
  explicit IcrEkfComponent(const ComponentConfig& c)
      : Component(c),
        prior_(prior_mode(c.params())),
        filter_(ekf_params(c.params()), reset_options(c, prior_)),
        adaptive_(c.params().optional<bool>("adaptive_reset", false)),
        detector_(c.params().optional<int>("consecutive_windows", 2)),
        dt_(c.period()),
        wheels_(add_input("wheels", {"v_l", "v_r"}, "TrackSpeeds")),
        gps_(add_input("gps", {"x", "y", "theta"}, "Pose2D")),
        classes_(adaptive_ ? &add_input("terrain", {"class", "windows"}, "TerrainClass") : nullptr),
        out_(add_output("icr",
                        {"x", "y", "theta", "y_l", "y_r", "x_G", "resets", "sd_y_l", "sd_y_r", "sd_x_G", "model_age"},
                        "IcrEstimate")),
        library_(library_of(c, prior_)) {
    if (prior_ && !adaptive_) c.params().fail("reset_mode", "prior needs adaptive_reset: true");
    write();
  }

  uint64_t dropped_late_samples() const override { return late_gps_; }

  void step(int64_t /*k*/, double /*t*/) override {
    const int64_t due_before = gps_due_;
    gps_due_ = gps_.due();
    const bool fresh = new_gps_(gps_);
    const bool late = fresh && gps_.sample().step <= due_before;
    if (late) ++late_gps_;  // it was due at the previous step already: one EKF period late or more, dropped (above)
    const alg::Pose2 z = pose_of(gps_);
    if (filter_.started()) {
      const alg::TrackSpeeds u{wheels_.valid() ? wheels_[0] : 0.0, wheels_.valid() ? wheels_[1] : 0.0};
      filter_.step(wheels_.valid() ? &u : nullptr, dt_, fresh && !late ? &z : nullptr);
    } else if (fresh && !late) {
      filter_.start(z);
    }
    // One decision per classifier window: a new `windows` count (the classifier publishes
    // at every one of its steps, holding its last decision in between).
    if (classes_ && classes_->valid() && (*classes_)[1] != last_window_ && (*classes_)[0] >= 0.0) {
      last_window_ = (*classes_)[1];
      if (detector_.observe(static_cast<int>(std::lround((*classes_)[0])))) {
        filter_.terrain_changed(prior_ ? library_.find(detector_.current()) : nullptr);
      }
    }
    write();
  }

 private:
  void write() {
    const alg::IcrEkf& f = filter_.published();
    const alg::IcrVector& x = f.state();
    for (int i = 0; i < 6; ++i) out_[static_cast<std::size_t>(i)] = x(i);
    out_[6] = static_cast<double>(filter_.resets());
    for (int i = 0; i < 3; ++i) out_[static_cast<std::size_t>(7 + i)] = std::sqrt(f.covariance()(3 + i, 3 + i));
    out_[10] = static_cast<double>(filter_.published_model_steps()) * dt_;
  }

  bool prior_;
  alg::IcrTerrainResetFilter filter_;
  bool adaptive_;
  alg::TerrainChangeDetector detector_;
  double dt_;
  double last_window_ = 0.0;
  NewSample new_gps_;
  int64_t gps_due_ = -1;   ///< the GPS step due at the previous step
  uint64_t late_gps_ = 0;  ///< GPS samples dropped for arriving after their step
  InputPort& wheels_;
  InputPort& gps_;
  InputPort* classes_;
  OutputPort& out_;
  alg::TerrainIcrLibrary library_;
};

const ComponentRegistration kEkf{"icr_ekf",
                                 ComponentKind::estimator,
                                 "6-state ICR EKF with optional classifier-driven covariance reset (paper 001)",
                                 [](const ComponentConfig& c) { return std::make_unique<IcrEkfComponent>(c); },
                                 {"paper001.estimator"}};

}  // namespace
}  // namespace plexus::scenario
