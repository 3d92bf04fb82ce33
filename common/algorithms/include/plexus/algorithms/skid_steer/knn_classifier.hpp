// k-nearest-neighbour terrain classifier (paper 001 section 3.2, eqs. (18)-(20)).
//
// Distance: Euclidean, eq. (19), on the feature vectors after the optional scaling;
// decision: majority vote among the k nearest training samples, eq. (20). The paper
// gives neither k nor a tie rule; both are parameters (docs/algorithms/skid_steer.md):
//   tie rule kNearest:     among the tied classes, the one owning the nearest neighbour
//   tie rule kLowestLabel: among the tied classes, the smallest class id
//   tie rule kShrinkK:     drop the farthest of the k neighbours until the tie is broken
// Scaling: kNone (the paper: raw features), kStandardize (each feature minus its training
// mean, divided by its training standard deviation; constant features get scale 1), or
// kMinMax (each feature mapped by its training range to [0, 1]).
// Distance ties between training samples are broken by their order in the training set.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "plexus/algorithms/skid_steer/training_set.hpp"

namespace plexus::algorithms {

enum class KnnTieRule { kNearest, kLowestLabel, kShrinkK };
enum class FeatureScaling { kNone, kStandardize, kMinMax };

/// "nearest" | "lowest_label" | "shrink_k"; throws std::invalid_argument otherwise.
KnnTieRule knn_tie_rule_from_string(const std::string& name);
/// "none" | "standardize" | "min_max"; throws std::invalid_argument otherwise.
FeatureScaling feature_scaling_from_string(const std::string& name);

struct KnnParams {
  int k = 5;  ///< 1 <= k <= training samples
  KnnTieRule tie_rule = KnnTieRule::kNearest;
  FeatureScaling scaling = FeatureScaling::kStandardize;
};

struct KnnResult {
  int label = -1;                 ///< winning class id
  int votes = 0;                  ///< its votes among the neighbours used
  int neighbours = 0;             ///< neighbours used (k, or fewer after kShrinkK)
  double confidence = 0.0;        ///< votes / neighbours
  double nearest_distance = 0.0;  ///< distance to the nearest training sample (scaled space)
};

class KnnClassifier {
 public:
  /// Validates params against the set (k in 1..size, non-empty, consistent sizes) and
  /// precomputes the scaled training features; throws std::invalid_argument.
  KnnClassifier(TrainingSet training, const KnnParams& params);

  /// Classifies one feature vector (training_set().layout.features values). No allocation.
  KnnResult classify(std::span<const double> features) const;

  const TrainingSet& training_set() const { return set_; }
  const KnnParams& params() const { return params_; }
  /// Distinct class ids of the training set, ascending.
  const std::vector<int>& classes() const { return classes_; }

 private:
  TrainingSet set_;
  KnnParams params_;
  std::vector<int> classes_;
  std::vector<std::size_t> class_index_;  // per sample: index into classes_
  std::vector<double> offset_, scale_;    // per feature: (x - offset) / scale
  std::vector<double> scaled_;            // training features, scaled, row-major
  // scratch, sized at construction (classify() is const but not reentrant on one object)
  mutable std::vector<double> query_;
  mutable std::vector<std::pair<double, std::size_t>> dist_;
  mutable std::vector<int> votes_;
  mutable std::vector<int> first_rank_;
};

}  // namespace plexus::algorithms
