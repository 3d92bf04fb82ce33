// Labelled terrain feature vectors: the kNN training set, its file format, loading,
// validation and recording (paper 001 eq. (18): S(N) = {(x_i, c_i)}).
//
// File format (text, one record per line, '#' starts a comment line, blank lines ignored):
//
//   plexus-terrain-training 1          first non-comment line: magic and version
//   sample_rate_hz 100                 header: how the features were computed; must match
//   window_samples 100                 the classifier's feature extractor
//   band_hz 1 50
//   taper rectangular                  rectangular | hann
//   scale linear                       linear | log10
//   features 50                        number of features per sample
//   class 0 concrete                   optional: names of class ids (any order, unique)
//   sample 0 1.25e-03 8.1e-04 ...      one labelled window: class id (integer >= 0), then
//                                      exactly `features` finite numbers (>= 0 if linear)
//
// Every header key must appear exactly once, before the first sample. Every error throws
// TrainingFileError whose message is "<file>:<line>: <what is wrong>" (line 0: the file as
// a whole, e.g. it has no samples or cannot be opened).
#pragma once

#include <cstddef>
#include <fstream>
#include <map>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "plexus/algorithms/skid_steer/terrain_features.hpp"

namespace plexus::algorithms {

class TrainingFileError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// How the features of a training set were computed (the header of the file).
struct FeatureLayout {
  double sample_rate_hz = 100.0;
  int window_samples = 100;
  double min_hz = 1.0;
  double max_hz = 50.0;
  SpectrumTaper taper = SpectrumTaper::kRectangular;
  bool log10 = false;
  std::size_t features = 50;

  /// The layout an extractor produces.
  static FeatureLayout of(const PsdFeatureExtractor& extractor);
  /// "" if equal, else a description of the first difference ("sample_rate_hz 100 vs 200").
  std::string difference(const FeatureLayout& other) const;
};

struct TrainingSet {
  FeatureLayout layout;
  std::map<int, std::string> class_names;  ///< optional names of class ids
  std::vector<int> labels;                 ///< one per sample, >= 0
  std::vector<double> features;            ///< row-major, labels.size() x layout.features

  std::size_t size() const { return labels.size(); }
  std::span<const double> sample(std::size_t i) const {
    return {features.data() + i * layout.features, layout.features};
  }
};

/// Loads and validates a training file; throws TrainingFileError ("file:line: ...").
TrainingSet load_training_set(const std::string& path);

/// Appends labelled windows to a new training file: the file is created (truncated) and the
/// header written at construction; append() writes one `sample` line and flushes (one line
/// per window, so a run that stops early leaves a valid file). Throws TrainingFileError if
/// the file cannot be opened or written.
class TrainingSetWriter {
 public:
  TrainingSetWriter(const std::string& path, const FeatureLayout& layout,
                    const std::map<int, std::string>& class_names = {}, const std::string& comment = {});
  void append(int label, std::span<const double> features);
  std::size_t written() const { return written_; }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  FeatureLayout layout_;
  std::ofstream out_;
  std::size_t written_ = 0;
};

}  // namespace plexus::algorithms
