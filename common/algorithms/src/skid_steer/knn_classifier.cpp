// kNN terrain classifier (paper 001 eqs. (18)-(20); docs/algorithms/skid_steer.md).
#include "plexus/algorithms/skid_steer/knn_classifier.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "plexus/algorithms/core/validation.hpp"

namespace plexus::algorithms {

KnnTieRule knn_tie_rule_from_string(const std::string& name) {
  if (name == "nearest") return KnnTieRule::kNearest;
  if (name == "lowest_label") return KnnTieRule::kLowestLabel;
  if (name == "shrink_k") return KnnTieRule::kShrinkK;
  throw std::invalid_argument("knn_classifier: tie_rule must be nearest, lowest_label or shrink_k (got '" + name +
                              "')");
}

FeatureScaling feature_scaling_from_string(const std::string& name) {
  if (name == "none") return FeatureScaling::kNone;
  if (name == "standardize") return FeatureScaling::kStandardize;
  if (name == "min_max") return FeatureScaling::kMinMax;
  throw std::invalid_argument("knn_classifier: scaling must be none, standardize or min_max (got '" + name + "')");
}

KnnClassifier::KnnClassifier(TrainingSet training, const KnnParams& params)
    : set_(std::move(training)), params_(params) {
  const std::size_t n = set_.size();
  const std::size_t m = set_.layout.features;
  if (n == 0) throw std::invalid_argument("knn_classifier: the training set is empty");
  if (m == 0 || set_.features.size() != n * m) {
    throw std::invalid_argument("knn_classifier: training features do not match labels x features");
  }
  if (params.k < 1 || static_cast<std::size_t>(params.k) > n) {
    validation::fail("knn_classifier", "k", "in 1.." + std::to_string(n) + " (the training samples)", params.k);
  }
  for (double v : set_.features) {
    if (!std::isfinite(v)) throw std::invalid_argument("knn_classifier: training features must be finite");
  }
  classes_ = set_.labels;
  std::sort(classes_.begin(), classes_.end());
  classes_.erase(std::unique(classes_.begin(), classes_.end()), classes_.end());
  for (int l : set_.labels) {
    if (l < 0) validation::fail("knn_classifier", "label", ">= 0", l);
    class_index_.push_back(
        static_cast<std::size_t>(std::lower_bound(classes_.begin(), classes_.end(), l) - classes_.begin()));
  }
  offset_.assign(m, 0.0);
  scale_.assign(m, 1.0);
  for (std::size_t j = 0; j < m && params.scaling != FeatureScaling::kNone; ++j) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo, sum = 0.0, sum2 = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double v = set_.features[i * m + j];
      lo = std::min(lo, v);
      hi = std::max(hi, v);
      sum += v;
    }
    const double mean = sum / static_cast<double>(n);
    for (std::size_t i = 0; i < n; ++i) sum2 += (set_.features[i * m + j] - mean) * (set_.features[i * m + j] - mean);
    const double sd = std::sqrt(sum2 / static_cast<double>(n));
    if (params.scaling == FeatureScaling::kStandardize) {
      offset_[j] = mean;
      scale_[j] = sd > 0.0 ? sd : 1.0;
    } else {
      offset_[j] = lo;
      scale_[j] = hi > lo ? hi - lo : 1.0;
    }
  }
  scaled_.resize(n * m);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < m; ++j) scaled_[i * m + j] = (set_.features[i * m + j] - offset_[j]) / scale_[j];
  }
  query_.resize(m);
  dist_.resize(n);
  votes_.resize(classes_.size());
  first_rank_.resize(classes_.size());
}

KnnResult KnnClassifier::classify(std::span<const double> features) const {
  const std::size_t n = set_.size();
  const std::size_t m = set_.layout.features;
  if (features.size() != m) throw std::invalid_argument("knn_classifier: query has the wrong number of features");
  for (std::size_t j = 0; j < m; ++j) query_[j] = (features[j] - offset_[j]) / scale_[j];
  for (std::size_t i = 0; i < n; ++i) {
    double d2 = 0.0;
    const double* row = scaled_.data() + i * m;
    for (std::size_t j = 0; j < m; ++j) d2 += (row[j] - query_[j]) * (row[j] - query_[j]);
    dist_[i] = {d2, i};  // (distance^2, index): ties go to the earlier training sample
  }
  auto k = static_cast<std::size_t>(params_.k);
  std::partial_sort(dist_.begin(), dist_.begin() + static_cast<std::ptrdiff_t>(k), dist_.end());
  for (;;) {
    std::fill(votes_.begin(), votes_.end(), 0);
    std::fill(first_rank_.begin(), first_rank_.end(), std::numeric_limits<int>::max());
    for (std::size_t r = 0; r < k; ++r) {
      const std::size_t c = class_index_[dist_[r].second];
      ++votes_[c];
      first_rank_[c] = std::min(first_rank_[c], static_cast<int>(r));
    }
    const int best = *std::max_element(votes_.begin(), votes_.end());
    std::size_t winner = classes_.size();
    int tied = 0;
    for (std::size_t c = 0; c < classes_.size(); ++c) {
      if (votes_[c] != best) continue;
      ++tied;
      // kLowestLabel: classes_ is ascending, so the first tied class wins.
      // kNearest (and kShrinkK once untied): the tied class with the nearest neighbour.
      if (winner == classes_.size() ||
          (params_.tie_rule != KnnTieRule::kLowestLabel && first_rank_[c] < first_rank_[winner])) {
        winner = c;
      }
    }
    if (tied > 1 && params_.tie_rule == KnnTieRule::kShrinkK && k > 1) {
      --k;
      continue;
    }
    KnnResult r;
    r.label = classes_[winner];
    r.votes = best;
    r.neighbours = static_cast<int>(k);
    r.confidence = static_cast<double>(best) / static_cast<double>(k);
    r.nearest_distance = std::sqrt(dist_.front().first);
    return r;
  }
}

}  // namespace plexus::algorithms
