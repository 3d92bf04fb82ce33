// terrain_recorder (estimator; terrain_classifier): records labelled PSD feature windows
// of the IMU's z-acceleration into a training file for terrain_classifier (paper 001
// section 3.2, eq. (18); docs/algorithms/skid_steer.md). Ports bind to `<robot>/<port>`
// unless remapped.
//
//   in imu {a_z} (Imu), truth/state {terrain} (SkidSteerTruth); out recorder {written}
//     (in process only: it writes a training file under `plexus sim`)
//   output (required; relative to the scenario file's folder), label (default: the plant's
//   true terrain id), windows_per_class (15), class_names ([]), + the feature keys of
//   windowed_features.hpp: window_s (1.0), hop_s (= window_s), min_hz (1), max_hz (50),
//   taper (rectangular), log10 (true)
#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "plexus/algorithms/skid_steer/training_set.hpp"
#include "plexus/scenario/params.hpp"
#include "plexus/scenario/registry.hpp"
#include "services/terrain_classifier/windowed_features.hpp"

namespace plexus::scenario {
namespace {

namespace alg = plexus::algorithms;

class TerrainRecorderComponent final : public Component {
 public:
  explicit TerrainRecorderComponent(const ComponentConfig& c)
      : Component(c),
        windows_(c),
        label_(c.params().optional<int>("label", -1)),
        per_class_(c.params().optional<int>("windows_per_class", 15)),
        writer_(open(c, windows_.extractor)),
        in_(add_input("imu", {"a_z"}, "Imu")),
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

const ComponentRegistration kTerrainRecorder{
    "terrain_recorder", ComponentKind::estimator, "records labelled PSD feature windows into a training file",
    [](const ComponentConfig& c) { return std::make_unique<TerrainRecorderComponent>(c); }};

}  // namespace
}  // namespace plexus::scenario
