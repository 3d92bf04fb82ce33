// Registry entries of the skid-steer family (paper 001; docs/algorithms/skid_steer.md has
// every parameter with its default and the paper's value). Ports bind to <robot>/<port>
// unless remapped; each output names its IDL type (docs/topics.md).
//
//   skid_steer (plant)            in cmd {v_l, v_r}; out truth/state {x, y, theta, y_l, y_r, x_G,
//     terrain, a_z, v_l, v_r} (SkidSteerTruth: true ICRs, terrain id, body z-acceleration,
//     applied track speeds)
//     terrains: {name: {y_l, y_r, x_G, floor_rms, resonances: [[f_hz, zeta, rms], ...]}}
//       (default: the paper's A concrete, B tile, C grass; ids in the order given)
//     schedule: [[start_s, terrain name], ...] (default: the first terrain throughout)
//     x0, y0, theta0 (0), vibration_reference_speed (0.5), vibration_speed_exponent (1), gravity (9.81)
//   skid_steer_driver (controller) out cmd {v_l, v_r} (TrackCommand)
//     pattern: straight | circle | figure_eight | segments; speed (0.5), turn_rate (0.5),
//     period (20), phase (0), track_width (0.4), segments: [[duration_s, v_l, v_r], ...], repeat (true)
//   pose_sensor (sensor)          in truth/state {x, y, theta}; out <sensor name> {x, y, theta} (Pose2D)
//     position_std (0.01 m), heading_std_deg (1), wrap_heading (true)
//   track_speed_sensor (sensor)   in truth/state {v_l, v_r}; out <sensor name> {v_l, v_r}
//     (TrackSpeeds); noise_std (0)
//   imu_z_sensor (sensor)         in truth/state {a_z}; out <sensor name> {a_z} (Imu, z axis);
//     noise_std (0.02), bias (0)
//   terrain_classifier (estimator) in imu {a_z}; out terrain {class, confidence, windows, votes}
//     (TerrainClass)
//     training_file (required; relative paths from the scenario file's folder), k (5),
//     tie_rule (nearest), scaling (standardize), + the feature keys below. Run it at the IMU rate.
//   terrain_recorder (estimator)  in imu {a_z}, truth/state {terrain}; out recorder {written}
//     (in process only: it writes a training file under `plexus sim`)
//     output (required; relative to the scenario file's folder), label (default: the plant's
//     true terrain id), windows_per_class (15), class_names ([]), + the feature keys below
//   feature keys: window_s (1.0), hop_s (= window_s), min_hz (1), max_hz (50), taper
//     (rectangular), log10 (true)
//   icr_ekf (estimator)           in wheels {v_l, v_r}, gps {x, y, theta}, and with
//     adaptive_reset: terrain {class, windows}; out icr {x, y, theta, y_l, y_r,
//     x_G, resets, sd_y_l, sd_y_r, sd_x_G} (IcrEstimate)
//     q_diag, r_diag, p0_diag, p_b_diag (lists; paper eq. (21)-(22)), initial_icr ([1, -1, 1]),
//     process_noise (dt_squared), enforce_track_sides (true), track_side_margin (0.01),
//     adaptive_reset (false), consecutive_windows (2)
//   icr_odometry (estimator)      in wheels {v_l, v_r}, truth/state {x, y, theta} (read once,
//     at `start`), with model estimated: icr {y_l, y_r, x_G}; out <service name> {x, y, theta}
//     (Pose2D)
//     model: no_slip (track_width 0.4) | fixed (y_l, y_r, x_G) | estimated; start (0 s)
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "plexus/algorithms/core/random.hpp"
#include "plexus/algorithms/skid_steer/driving_pattern.hpp"
#include "plexus/algorithms/skid_steer/icr_ekf.hpp"
#include "plexus/algorithms/skid_steer/icr_odometry.hpp"
#include "plexus/algorithms/skid_steer/knn_classifier.hpp"
#include "plexus/algorithms/skid_steer/skid_steer_plant.hpp"
#include "plexus/algorithms/skid_steer/skid_steer_sensors.hpp"
#include "plexus/algorithms/skid_steer/terrain_change_detector.hpp"
#include "plexus/algorithms/skid_steer/terrain_features.hpp"
#include "plexus/algorithms/skid_steer/training_set.hpp"
#include "plexus/scenario/params.hpp"
#include "plexus/scenario/registry.hpp"

namespace plexus::scenario {
namespace {

namespace alg = plexus::algorithms;

// ------------------------------------------------------------------------------ helpers

double number(const YamlMap& p, const YAML::Node& n, const std::string& key) {
  try {
    if (n.IsScalar()) return n.as<double>();
  } catch (const YAML::Exception&) {
  }
  throw InputError(p.where(n) + ": " + p.key_path(key) + ": expected a number, got '" + (n.IsScalar() ? n.Scalar() : "a collection") + "'");
}

/// A list of exactly `size` numbers (size 0: any length).
std::vector<double> numbers(const YamlMap& p, const YAML::Node& n, const std::string& key, std::size_t size) {
  if (!n.IsSequence() || (size > 0 && n.size() != size)) {
    throw InputError(p.where(n) + ": " + p.key_path(key) + ": expected a list of " +
                     (size > 0 ? std::to_string(size) + " " : "") + "numbers");
  }
  std::vector<double> out;
  for (const auto& e : n) out.push_back(number(p, e, key));
  return out;
}

template <int N>
Eigen::Matrix<double, N, 1> optional_vector(const YamlMap& p, const std::string& key, const Eigen::Matrix<double, N, 1>& fallback) {
  if (!p.has(key)) return fallback;
  const auto v = numbers(p, p.node(key), key, N);
  return Eigen::Map<const Eigen::Matrix<double, N, 1>>(v.data());
}

/// A path parameter: absolute, or relative to the scenario's folder (ComponentConfig::base_dir).
std::string scenario_relative_path(const ComponentConfig& c, const std::string& key) {
  const YamlMap& p = c.params();
  const std::filesystem::path v = p.required<std::string>(key);
  if (v.empty()) p.fail(key, "must name a file");
  if (v.is_absolute()) return v.string();
  return (std::filesystem::path(c.base_dir) / v).lexically_normal().string();
}

/// The producer's step of an input's current sample changed since the last call?
struct NewSample {
  int64_t last = -1;
  bool operator()(const InputPort& in) {
    const int64_t s = in.sample().step;
    if (s < 0 || s == last) return false;
    last = s;
    return true;
  }
};

alg::Pose2 pose_of(const InputPort& in) { return {in[0], in[1], in[2]}; }

// ------------------------------------------------------------------------------ plant

std::vector<alg::TerrainSpec> terrains(const YamlMap& p, std::map<std::string, int>& ids) {
  std::vector<alg::TerrainSpec> out;
  if (!p.has("terrains")) {
    out = alg::paper_terrains();
  } else {
    const YamlMap t = p.map("terrains");
    for (const auto& name : t.keys()) {
      const YamlMap s = t.map(name);
      alg::TerrainSpec spec;
      spec.name = name;
      spec.icr = {s.required<double>("y_l"), s.required<double>("y_r"), s.required<double>("x_G")};
      spec.vibration.floor_rms = s.optional<double>("floor_rms", 0.0);
      if (s.has("resonances")) {
        for (const auto& r : s.sequence("resonances")) {
          const auto v = numbers(s, r, "resonances", 3);
          spec.vibration.resonances.push_back({v[0], v[1], v[2]});
        }
      }
      s.reject_unknown();
      out.push_back(spec);
    }
    if (out.empty()) p.fail("terrains", "needs at least one terrain");
  }
  for (std::size_t i = 0; i < out.size(); ++i) ids[out[i].name] = static_cast<int>(i);
  return out;
}

alg::SkidSteerPlantParams plant_params(const ComponentConfig& c) {
  const YamlMap& p = c.params();
  alg::SkidSteerPlantParams s;
  std::map<std::string, int> ids;
  s.terrains = terrains(p, ids);
  if (p.has("schedule")) {
    s.schedule.clear();
    for (const auto& e : p.sequence("schedule")) {
      if (!e.IsSequence() || e.size() != 2 || !e[1].IsScalar()) {
        throw InputError(p.where(e) + ": " + p.key_path("schedule") + ": expected [start_s, terrain name]");
      }
      const auto it = ids.find(e[1].Scalar());
      if (it == ids.end()) {
        throw InputError(p.where(e) + ": " + p.key_path("schedule") + ": unknown terrain '" + e[1].Scalar() + "'");
      }
      s.schedule.push_back({number(p, e[0], "schedule"), it->second});
    }
  }
  s.initial_pose = {p.optional<double>("x0", 0.0), p.optional<double>("y0", 0.0), p.optional<double>("theta0", 0.0)};
  s.step = c.period();
  s.reference_speed = p.optional<double>("vibration_reference_speed", s.reference_speed);
  s.speed_exponent = p.optional<double>("vibration_speed_exponent", s.speed_exponent);
  s.gravity = p.optional<double>("gravity", s.gravity);
  return s;
}

class SkidSteerPlantComponent final : public Component {
 public:
  explicit SkidSteerPlantComponent(const ComponentConfig& c)
      : Component(c), plant_(plant_params(c)), rng_(c.seed), cmd_(add_input("cmd", {"v_l", "v_r"}, "TrackCommand")),
        out_(add_output("truth/state", {"x", "y", "theta", "y_l", "y_r", "x_G", "terrain", "a_z", "v_l", "v_r"}, "SkidSteerTruth")) {}

  void step(int64_t k, double t) override {
    if (k > 0) {
      u_ = cmd_.valid() ? alg::TrackSpeeds{cmd_[0], cmd_[1]} : alg::TrackSpeeds{};
      // The step from t - h to t, with the terrain at its start.
      plant_.step(t - plant_.params().step, u_, rng_);
    }
    const alg::SkidSteerState& s = plant_.state();
    const double v[] = {s.pose.x, s.pose.y, s.pose.theta, s.icr.y_l, s.icr.y_r, s.icr.x_G,
                        static_cast<double>(s.terrain), s.a_z, u_.v_l, u_.v_r};
    for (std::size_t i = 0; i < std::size(v); ++i) out_[i] = v[i];
  }

 private:
  alg::SkidSteerPlant plant_;
  alg::Rng rng_;
  alg::TrackSpeeds u_{};
  InputPort& cmd_;
  OutputPort& out_;
};

// ------------------------------------------------------------------------------ driver

alg::DrivingPatternParams driver_params(const YamlMap& p) {
  alg::DrivingPatternParams d;
  const auto kind = p.required<std::string>("pattern");
  try {
    d.kind = alg::driving_pattern_kind_from_string(kind);
  } catch (const std::invalid_argument&) {
    p.fail("pattern", "expected straight, circle, figure_eight or segments, got '" + kind + "'");
  }
  d.speed = p.optional<double>("speed", d.speed);
  d.turn_rate = p.optional<double>("turn_rate", d.turn_rate);
  d.period = p.optional<double>("period", d.period);
  d.phase = p.optional<double>("phase", d.phase);
  d.track_width = p.optional<double>("track_width", d.track_width);
  d.repeat = p.optional<bool>("repeat", d.repeat);
  if (d.kind == alg::DrivingPatternKind::kSegments) {
    for (const auto& e : p.sequence("segments")) {
      const auto v = numbers(p, e, "segments", 3);
      d.segments.push_back({v[0], v[1], v[2]});
    }
  }
  return d;
}

class DriverComponent final : public Component {
 public:
  explicit DriverComponent(const ComponentConfig& c)
      : Component(c), pattern_(driver_params(c.params())), out_(add_output("cmd", {"v_l", "v_r"}, "TrackCommand")) {}
  void step(int64_t /*k*/, double t) override {
    const alg::TrackSpeeds u = pattern_.at(t);
    out_[0] = u.v_l;
    out_[1] = u.v_r;
  }

 private:
  alg::DrivingPattern pattern_;
  OutputPort& out_;
};

// ------------------------------------------------------------------------------ sensors

class PoseSensorComponent final : public Component {
 public:
  explicit PoseSensorComponent(const ComponentConfig& c)
      : Component(c), sensor_(params(c.params())), rng_(c.seed), in_(add_input("truth/state", {"x", "y", "theta"}, "SkidSteerTruth")),
        out_(add_output(c.key, {"x", "y", "theta"}, "Pose2D")) {}
  void step(int64_t /*k*/, double /*t*/) override {
    const alg::Pose2 m = sensor_.measure(pose_of(in_), rng_);
    out_[0] = m.x;
    out_[1] = m.y;
    out_[2] = m.theta;
  }

 private:
  static alg::PoseSensorParams params(const YamlMap& p) {
    alg::PoseSensorParams s;
    s.position_std = optional_non_negative(p, "position_std", s.position_std);
    s.heading_std = optional_non_negative(p, "heading_std_deg", 1.0) * std::numbers::pi / 180.0;
    s.wrap_heading = p.optional<bool>("wrap_heading", true);
    return s;
  }
  alg::PoseSensor sensor_;
  alg::Rng rng_;
  InputPort& in_;
  OutputPort& out_;
};

class TrackSpeedSensorComponent final : public Component {
 public:
  explicit TrackSpeedSensorComponent(const ComponentConfig& c)
      : Component(c), sensor_(optional_non_negative(c.params(), "noise_std")), rng_(c.seed),
        in_(add_input("truth/state", {"v_l", "v_r"}, "SkidSteerTruth")), out_(add_output(c.key, {"v_l", "v_r"}, "TrackSpeeds")) {}
  void step(int64_t /*k*/, double /*t*/) override {
    const alg::TrackSpeeds m = sensor_.measure({in_[0], in_[1]}, rng_);
    out_[0] = m.v_l;
    out_[1] = m.v_r;
  }

 private:
  alg::TrackSpeedSensor sensor_;
  alg::Rng rng_;
  InputPort& in_;
  OutputPort& out_;
};

class ImuZSensorComponent final : public Component {
 public:
  explicit ImuZSensorComponent(const ComponentConfig& c)
      : Component(c), sensor_(optional_non_negative(c.params(), "noise_std", 0.02), c.params().optional<double>("bias", 0.0)),
        rng_(c.seed), in_(add_input("truth/state", {"a_z"}, "SkidSteerTruth")), out_(add_output(c.key, {"a_z"}, "Imu")) {}
  void step(int64_t /*k*/, double /*t*/) override { out_[0] = sensor_.measure(in_[0], rng_); }

 private:
  alg::ImuZSensor sensor_;
  alg::Rng rng_;
  InputPort& in_;
  OutputPort& out_;
};

// ------------------------------------------------------------------------------ terrain windows

/// Window and feature parameters shared by the classifier and the recorder: the sample
/// rate is the component's rate (run it at the IMU's rate).
struct WindowedFeatures {
  alg::PsdFeatureExtractor extractor;
  alg::SampleWindow window;
  std::vector<double> features;
  NewSample fresh;

  explicit WindowedFeatures(const ComponentConfig& c)
      : extractor(feature_params(c)), window(samples(c, "window_s", 1.0), hop(c)), features(extractor.size()) {}

  /// Feeds the input's new sample, if any; true when a window's features are ready.
  bool push(const InputPort& in) {
    if (!fresh(in)) return false;
    if (!window.push(in[0])) return false;
    extractor.compute(window.window(), features);
    return true;
  }

 private:
  static std::size_t samples(const ComponentConfig& c, const std::string& key, double fallback) {
    const double s = c.params().optional<double>(key, fallback);
    const double n = s / c.period();
    if (!(s > 0.0) || std::abs(n - std::round(n)) > 1e-6 || std::round(n) < 1) {
      c.params().fail(key, "must be a positive whole number of the component's periods (" +
                               std::to_string(c.period()) + " s)");
    }
    return static_cast<std::size_t>(std::round(n));
  }
  static std::size_t hop(const ComponentConfig& c) {
    const double w = c.params().optional<double>("window_s", 1.0);
    return samples(c, "hop_s", w);
  }
  static alg::PsdFeatureParams feature_params(const ComponentConfig& c) {
    const YamlMap& p = c.params();
    alg::PsdFeatureParams f;
    f.sample_rate_hz = 1.0 / c.period();
    f.window_samples = static_cast<int>(samples(c, "window_s", 1.0));
    f.min_hz = p.optional<double>("min_hz", f.min_hz);
    f.max_hz = p.optional<double>("max_hz", f.max_hz);
    const auto taper = p.optional<std::string>("taper", "rectangular");
    try {
      f.taper = alg::spectrum_taper_from_string(taper);
    } catch (const std::invalid_argument&) {
      p.fail("taper", "expected rectangular or hann, got '" + taper + "'");
    }
    f.log10 = p.optional<bool>("log10", true);  // measured choice: docs/algorithms/skid_steer.md
    return f;
  }
};

alg::KnnClassifier make_classifier(const ComponentConfig& c, const alg::PsdFeatureExtractor& extractor) {
  const YamlMap& p = c.params();
  const std::string path = scenario_relative_path(c, "training_file");
  alg::TrainingSet set;
  try {
    set = alg::load_training_set(path);
  } catch (const alg::TrainingFileError& e) {
    p.fail("training_file", e.what());
  }
  const std::string diff = set.layout.difference(alg::FeatureLayout::of(extractor));
  if (!diff.empty()) {
    p.fail("training_file", path + ": its features were computed differently from this classifier's (" + diff +
                                ": file vs classifier)");
  }
  alg::KnnParams k;
  k.k = p.optional<int>("k", k.k);
  const auto tie = p.optional<std::string>("tie_rule", "nearest");
  const auto scaling = p.optional<std::string>("scaling", "standardize");
  try {
    k.tie_rule = alg::knn_tie_rule_from_string(tie);
  } catch (const std::invalid_argument&) {
    p.fail("tie_rule", "expected nearest, lowest_label or shrink_k, got '" + tie + "'");
  }
  try {
    k.scaling = alg::feature_scaling_from_string(scaling);
  } catch (const std::invalid_argument&) {
    p.fail("scaling", "expected none, standardize or min_max, got '" + scaling + "'");
  }
  try {
    return alg::KnnClassifier(std::move(set), k);
  } catch (const std::invalid_argument& e) {
    p.fail("k", e.what());
  }
}

class TerrainClassifierComponent final : public Component {
 public:
  explicit TerrainClassifierComponent(const ComponentConfig& c)
      : Component(c), windows_(c), knn_(make_classifier(c, windows_.extractor)), in_(add_input("imu", {"a_z"}, "Imu")),
        out_(add_output("terrain", {"class", "confidence", "windows", "votes"}, "TerrainClass")) {
    out_[0] = -1.0;  // no decision yet
  }
  void step(int64_t /*k*/, double /*t*/) override {
    if (windows_.push(in_)) {
      const alg::KnnResult r = knn_.classify(windows_.features);
      ++count_;
      out_[0] = r.label;
      out_[1] = r.confidence;
      out_[2] = static_cast<double>(count_);
      out_[3] = r.votes;
    }
  }

 private:
  WindowedFeatures windows_;
  alg::KnnClassifier knn_;
  long count_ = 0;
  InputPort& in_;
  OutputPort& out_;
};

class TerrainRecorderComponent final : public Component {
 public:
  explicit TerrainRecorderComponent(const ComponentConfig& c)
      : Component(c), windows_(c), label_(c.params().optional<int>("label", -1)),
        per_class_(c.params().optional<int>("windows_per_class", 15)),
        writer_(open(c, windows_.extractor)), in_(add_input("imu", {"a_z"}, "Imu")),
        truth_(add_input("truth/state", {"terrain"}, "SkidSteerTruth")),
        out_(add_output("recorder", {"written"}, "")) {  // writes a file: `plexus sim` only
    if (c.params().has("label") && label_ < 0) c.params().fail("label", "must be >= 0");
    if (per_class_ < 1) c.params().fail("windows_per_class", "must be >= 1");
    labels_.assign(windows_.window.window().size(), -1);
  }
  void step(int64_t /*k*/, double /*t*/) override {
    const int label = label_ >= 0 ? label_ : static_cast<int>(std::lround(truth_[0]));
    // Track the label of every sample in the window so a window across a terrain change
    // (mixed vibration) is not recorded.
    const int64_t before = windows_.fresh.last;
    const bool ready = windows_.push(in_);
    if (windows_.fresh.last != before) {
      labels_[head_] = label;
      head_ = (head_ + 1) % labels_.size();
    }
    if (!ready) return;
    for (int l : labels_) {
      if (l != label) return;
    }
    int& n = counts_[label];
    if (n >= per_class_) return;
    ++n;
    writer_.append(label, windows_.features);
    out_[0] = static_cast<double>(writer_.written());
  }

 private:
  static alg::TrainingSetWriter open(const ComponentConfig& c, const alg::PsdFeatureExtractor& e) {
    const YamlMap& p = c.params();
    std::map<int, std::string> names;
    if (p.has("class_names")) {
      int i = 0;
      for (const auto& n : p.sequence("class_names")) names[i++] = n.Scalar();
    }
    const std::string path = scenario_relative_path(c, "output");
    try {
      return alg::TrainingSetWriter(path, alg::FeatureLayout::of(e), names, "recorded by service '" + c.name + "'");
    } catch (const alg::TrainingFileError& err) {
      p.fail("output", err.what());
    }
  }

  WindowedFeatures windows_;
  int label_;
  int per_class_;
  alg::TrainingSetWriter writer_;
  std::vector<int> labels_;
  std::size_t head_ = 0;
  std::map<int, int> counts_;  // class ids seen; inserted at most once per class (window rate)
  InputPort& in_;
  InputPort& truth_;
  OutputPort& out_;
};

// ------------------------------------------------------------------------------ ICR EKF

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

class IcrEkfComponent final : public Component {
 public:
  explicit IcrEkfComponent(const ComponentConfig& c)
      : Component(c), ekf_(ekf_params(c.params())), adaptive_(c.params().optional<bool>("adaptive_reset", false)),
        detector_(c.params().optional<int>("consecutive_windows", 2)), dt_(c.period()),
        wheels_(add_input("wheels", {"v_l", "v_r"}, "TrackSpeeds")), gps_(add_input("gps", {"x", "y", "theta"}, "Pose2D")),
        classes_(adaptive_ ? &add_input("terrain", {"class", "windows"}, "TerrainClass") : nullptr),
        out_(add_output("icr", {"x", "y", "theta", "y_l", "y_r", "x_G", "resets", "sd_y_l", "sd_y_r", "sd_x_G"},
                        "IcrEstimate")) {
    write();
  }

  void step(int64_t /*k*/, double /*t*/) override {
    if (started_ && wheels_.valid()) ekf_.predict({wheels_[0], wheels_[1]}, dt_);
    if (new_gps_(gps_)) {
      if (!started_) {
        ekf_.reset(pose_of(gps_));
        started_ = true;
      } else {
        ekf_.update(pose_of(gps_));
      }
    }
    // One decision per classifier window: a new `windows` count (the classifier publishes
    // at every one of its steps, holding its last decision in between).
    if (classes_ && classes_->valid() && (*classes_)[1] != last_window_ && (*classes_)[0] >= 0.0) {
      last_window_ = (*classes_)[1];
      if (detector_.observe(static_cast<int>(std::lround((*classes_)[0])))) {
        ekf_.reset_covariance_to_p_b();  // paper 001 eq. (22)
        ++resets_;
      }
    }
    write();
  }

 private:
  void write() {
    const alg::IcrVector& x = ekf_.state();
    for (int i = 0; i < 6; ++i) out_[static_cast<std::size_t>(i)] = x(i);
    out_[6] = static_cast<double>(resets_);
    for (int i = 0; i < 3; ++i) out_[static_cast<std::size_t>(7 + i)] = std::sqrt(ekf_.covariance()(3 + i, 3 + i));
  }

  alg::IcrEkf ekf_;
  bool adaptive_;
  alg::TerrainChangeDetector detector_;
  double dt_;
  bool started_ = false;
  long resets_ = 0;
  double last_window_ = 0.0;
  NewSample new_gps_;
  InputPort& wheels_;
  InputPort& gps_;
  InputPort* classes_;
  OutputPort& out_;
};

// ------------------------------------------------------------------------------ odometry

class IcrOdometryComponent final : public Component {
 public:
  explicit IcrOdometryComponent(const ComponentConfig& c)
      : Component(c), model_(model(c.params())), start_(c.params().optional<double>("start", 0.0)), h_(c.period()),
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

template <class T>
ComponentFactory make() {
  return [](const ComponentConfig& c) { return std::make_unique<T>(c); };
}

const ComponentRegistration kPlant{"skid_steer", ComponentKind::plant,
                                   "skid-steer ICR kinematics with a terrain schedule and vibration (paper 001); "
                                   "in cmd {v_l, v_r}, out state {x, y, theta, y_l, y_r, x_G, terrain, a_z, v_l, v_r}",
                                   make<SkidSteerPlantComponent>()};
const ComponentRegistration kDriver{"skid_steer_driver", ComponentKind::controller,
                                    "driving pattern (straight, circle, figure_eight, segments); out cmd {v_l, v_r}",
                                    make<DriverComponent>()};
const ComponentRegistration kPose{"pose_sensor", ComponentKind::sensor,
                                  "GPS position + heading with Gaussian noise (paper 001: 0.01 m, 1 deg)",
                                  make<PoseSensorComponent>()};
const ComponentRegistration kWheels{"track_speed_sensor", ComponentKind::sensor, "track speeds v_l, v_r with noise",
                                    make<TrackSpeedSensorComponent>()};
const ComponentRegistration kImu{"imu_z_sensor", ComponentKind::sensor, "IMU z-acceleration with noise and bias",
                                 make<ImuZSensorComponent>()};
const ComponentRegistration kClassifier{"terrain_classifier", ComponentKind::estimator,
                                        "PSD features (FFTW) + kNN terrain class per window (paper 001 section 3.2)",
                                        make<TerrainClassifierComponent>()};
const ComponentRegistration kRecorder{"terrain_recorder", ComponentKind::estimator,
                                      "records labelled PSD feature windows into a training file",
                                      make<TerrainRecorderComponent>()};
const ComponentRegistration kEkf{"icr_ekf", ComponentKind::estimator,
                                 "6-state ICR EKF with optional classifier-driven covariance reset (paper 001)",
                                 make<IcrEkfComponent>()};
const ComponentRegistration kOdometry{"icr_odometry", ComponentKind::estimator,
                                      "dead reckoning with the no-slip, a fixed or the estimated ICR model",
                                      make<IcrOdometryComponent>()};

}  // namespace
}  // namespace plexus::scenario
