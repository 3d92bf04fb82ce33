#include "plexus/algorithms/skid_steer/knn_classifier.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "../support/validation_message.hpp"

namespace plexus::algorithms {
namespace {

/// A hand-made 2-feature training set.
TrainingSet make_set(const std::vector<std::pair<int, std::pair<double, double>>>& samples) {
  TrainingSet s;
  s.layout.features = 2;
  for (const auto& [label, xy] : samples) {
    s.labels.push_back(label);
    s.features.push_back(xy.first);
    s.features.push_back(xy.second);
  }
  return s;
}

KnnParams params(int k, KnnTieRule tie = KnnTieRule::kNearest, FeatureScaling scaling = FeatureScaling::kNone) {
  KnnParams p;
  p.k = k;
  p.tie_rule = tie;
  p.scaling = scaling;
  return p;
}

std::vector<double> q(double x, double y) { return {x, y}; }

TEST(KnnClassifier, SeparatedClustersAreClassifiedByMajority) {
  const TrainingSet s = make_set({{0, {0, 0}},
                                  {0, {0, 1}},
                                  {0, {1, 0}},
                                  {1, {10, 10}},
                                  {1, {10, 11}},
                                  {1, {11, 10}},
                                  {2, {0, 10}},
                                  {2, {1, 10}},
                                  {2, {0, 11}}});
  for (int k : {1, 3, 5}) {
    const KnnClassifier c(s, params(k));
    EXPECT_EQ(c.classify(q(0.2, 0.3)).label, 0) << k;
    EXPECT_EQ(c.classify(q(9.5, 10.2)).label, 1) << k;
    EXPECT_EQ(c.classify(q(0.5, 9.0)).label, 2) << k;
  }
  const KnnClassifier c3(s, params(3));
  const KnnResult r = c3.classify(q(0.2, 0.3));
  EXPECT_EQ(r.votes, 3);
  EXPECT_EQ(r.neighbours, 3);
  EXPECT_DOUBLE_EQ(r.confidence, 1.0);
  EXPECT_NEAR(r.nearest_distance, std::hypot(0.2, 0.3), 1e-12);
  EXPECT_EQ(c3.classes(), (std::vector<int>{0, 1, 2}));
}

TEST(KnnClassifier, MajorityBeatsTheNearestNeighbour) {
  // Nearest is class 1, but 2 of the 3 nearest are class 0.
  const KnnClassifier c(make_set({{1, {0.0, 0.0}}, {0, {0.3, 0.0}}, {0, {0.0, 0.35}}, {1, {5, 5}}}), params(3));
  const KnnResult r = c.classify(q(0.05, 0.05));
  EXPECT_EQ(r.label, 0);
  EXPECT_EQ(r.votes, 2);
  EXPECT_NEAR(r.confidence, 2.0 / 3.0, 1e-12);
}

TEST(KnnClassifier, TieRules) {
  // Query at the origin; neighbours by distance: class 5 at 1, class 2 at 2, class 5 at 3,
  // class 2 at 4. With k = 4: 2 votes each.
  const TrainingSet s = make_set({{2, {0, 4}}, {5, {1, 0}}, {2, {2, 0}}, {5, {0, 3}}});
  EXPECT_EQ(KnnClassifier(s, params(4, KnnTieRule::kNearest)).classify(q(0, 0)).label, 5);
  EXPECT_EQ(KnnClassifier(s, params(4, KnnTieRule::kLowestLabel)).classify(q(0, 0)).label, 2);
  const KnnResult shrink = KnnClassifier(s, params(4, KnnTieRule::kShrinkK)).classify(q(0, 0));
  EXPECT_EQ(shrink.label, 5);  // k = 3: class 5 has 2 of 3
  EXPECT_EQ(shrink.neighbours, 3);
  // k = 2: shrink_k drops to k = 1 (the nearest, class 5); lowest_label says 2.
  EXPECT_EQ(KnnClassifier(s, params(2, KnnTieRule::kShrinkK)).classify(q(0, 0)).neighbours, 1);
  EXPECT_EQ(KnnClassifier(s, params(2, KnnTieRule::kLowestLabel)).classify(q(0, 0)).label, 2);
}

TEST(KnnClassifier, EqualDistancesGoToTheEarlierTrainingSample) {
  const TrainingSet s = make_set({{7, {1, 0}}, {3, {-1, 0}}});
  EXPECT_EQ(KnnClassifier(s, params(1)).classify(q(0, 0)).label, 7);
}

TEST(KnnClassifier, StandardizingStopsOneLargeFeatureFromDominating) {
  // Feature 0 spans thousands but says nothing; feature 1 separates the classes by 1.
  const TrainingSet s =
      make_set({{0, {0, 0}}, {0, {2900, 0.1}}, {0, {1500, 0}}, {1, {0, 1}}, {1, {3000, 1.1}}, {1, {1500, 1}}});
  const auto query = q(2900, 0.95);  // clearly class 1 on feature 1
  EXPECT_EQ(KnnClassifier(s, params(1, KnnTieRule::kNearest, FeatureScaling::kNone)).classify(query).label, 0);
  EXPECT_EQ(KnnClassifier(s, params(1, KnnTieRule::kNearest, FeatureScaling::kStandardize)).classify(query).label, 1);
  EXPECT_EQ(KnnClassifier(s, params(1, KnnTieRule::kNearest, FeatureScaling::kMinMax)).classify(query).label, 1);
}

TEST(KnnClassifier, ConstantFeatureDoesNotDivideByZero) {
  const TrainingSet s = make_set({{0, {1, 0}}, {1, {1, 1}}});
  const KnnResult r =
      KnnClassifier(s, params(1, KnnTieRule::kNearest, FeatureScaling::kStandardize)).classify(q(1, 0.9));
  EXPECT_EQ(r.label, 1);
  EXPECT_TRUE(std::isfinite(r.nearest_distance));
}

TEST(KnnClassifier, RejectsBadParameters) {
  using testing::invalid_argument_message;
  const TrainingSet s = make_set({{0, {0, 0}}, {1, {1, 1}}});
  EXPECT_EQ(invalid_argument_message<KnnClassifier>(s, params(0)),
            "knn_classifier: k must be in 1..2 (the training samples) (got 0)");
  EXPECT_EQ(invalid_argument_message<KnnClassifier>(s, params(3)),
            "knn_classifier: k must be in 1..2 (the training samples) (got 3)");
  EXPECT_EQ(invalid_argument_message<KnnClassifier>(TrainingSet{}, params(1)),
            "knn_classifier: the training set is empty");
  TrainingSet bad = s;
  bad.features.pop_back();
  EXPECT_EQ(invalid_argument_message<KnnClassifier>(bad, params(1)),
            "knn_classifier: training features do not match labels x features");
  bad = s;
  bad.features[0] = std::nan("");
  EXPECT_EQ(invalid_argument_message<KnnClassifier>(bad, params(1)),
            "knn_classifier: training features must be finite");
  bad = s;
  bad.labels[0] = -1;
  EXPECT_EQ(invalid_argument_message<KnnClassifier>(bad, params(1)), "knn_classifier: label must be >= 0 (got -1)");
  EXPECT_THROW(knn_tie_rule_from_string("random"), std::invalid_argument);
  EXPECT_THROW(feature_scaling_from_string("zscore"), std::invalid_argument);
  EXPECT_EQ(knn_tie_rule_from_string("shrink_k"), KnnTieRule::kShrinkK);
  EXPECT_EQ(feature_scaling_from_string("min_max"), FeatureScaling::kMinMax);
  const KnnClassifier c(s, params(1));
  EXPECT_THROW(c.classify(std::vector<double>{1.0}), std::invalid_argument);
}

}  // namespace
}  // namespace plexus::algorithms
