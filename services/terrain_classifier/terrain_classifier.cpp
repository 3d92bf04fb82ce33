// terrain_classifier (estimator; terrain_classifier): PSD features of the IMU's
// z-acceleration (FFTW) + kNN terrain class per window (paper 001 section 3.2, eqs.
// (18)-(20); docs/algorithms/skid_steer.md). Ports bind to `<robot>/<port>` unless
// remapped; the output names its IDL type (docs/topics.md).
//
//   in imu {a_z} (Imu); out terrain {class, confidence, windows, votes} (TerrainClass;
//     class -1 before the first decision)
//   training_file (required; relative paths from the scenario file's folder), k (5),
//   tie_rule (nearest), scaling (standardize), + the feature keys of windowed_features.hpp:
//   window_s (1.0), hop_s (= window_s), min_hz (1), max_hz (50), taper (rectangular),
//   log10 (true). Run it at the IMU rate.
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include "plexus/algorithms/skid_steer/knn_classifier.hpp"
#include "plexus/algorithms/skid_steer/training_set.hpp"
#include "plexus/scenario/params.hpp"
#include "plexus/scenario/registry.hpp"
#include "services/terrain_classifier/windowed_features.hpp"

namespace plexus::scenario {
namespace {

namespace alg = plexus::algorithms;

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
    p.fail("training_file",
           path + ": its features were computed differently from this classifier's (" + diff + ": file vs classifier)");
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
      : Component(c),
        windows_(c),
        knn_(make_classifier(c, windows_.extractor)),
        in_(add_input("imu", {"a_z"}, "Imu")),
        out_(add_output("terrain", {"class", "confidence", "windows", "votes"}, "TerrainClass")) {
    out_[0] = -1.0;  // no decision yet
  }
  uint64_t dropped_late_samples() const override { return windows_.missing; }

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

const ComponentRegistration kClassifier{
    "terrain_classifier", ComponentKind::estimator,
    "PSD features (FFTW) + kNN terrain class per window (paper 001 section 3.2)",
    [](const ComponentConfig& c) { return std::make_unique<TerrainClassifierComponent>(c); }};

}  // namespace
}  // namespace plexus::scenario
