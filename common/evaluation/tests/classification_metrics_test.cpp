// classification_accuracy (skid_steer_metrics.cpp) on a synthetic run whose accuracy can be
// counted by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "metric_on_log.hpp"
#include "plexus/scenario/metric.hpp"

namespace plexus::scenario {
namespace {

constexpr double kStep = 0.1;
constexpr int64_t kSteps = 300;  // 30 s
constexpr double kDuration = kStep * kSteps;

/// True terrain 0 on [0, 10), 1 on [10, 20), 2 on [20, 30], recorded every `truth_rate` steps.
double terrain(int64_t k) { return k < 100 ? 0.0 : (k < 200 ? 1.0 : 2.0); }

/// The classifier (class, confidence, windows, votes), recorded every step, decides every
/// 0.5 s: decision n = 1..60 at step 5n (t = 0.5 n) bumps `windows` to n; between
/// decisions every field is held; before the first, class is -1 and windows 0 (as the
/// terrain_classifier component does). Decision n is wrong (class = terrain + 1) when n is a
/// multiple of 4, otherwise right, its class read back off by +-0.3 (the metric rounds
/// classes and terrains to the nearest integer).
RunLog classification_run(int truth_rate = 1) {
  RunLog log;
  log.base_step = kStep;
  log.steps = kSteps;
  SignalTrace truth{{"r/truth/state", {"x", "terrain"}, truth_rate, "plant", true, ""}, {}, {}};
  SignalTrace cls{{"r/terrain", {"class", "confidence", "windows", "votes"}, 1, "knn", false, ""}, {}, {}};
  SignalTrace bad{{"r/votes", {"class", "votes"}, 1, "knn", false, ""}, {}, {}};
  double c = -1.0, n = 0.0;
  for (int64_t k = 0; k <= kSteps; ++k) {
    if (k % truth_rate == 0) {
      truth.steps.push_back(k);
      truth.values.insert(truth.values.end(), {0.1 * static_cast<double>(k), terrain(k)});
    }
    if (k > 0 && k % 5 == 0) {
      n += 1.0;
      const auto i = static_cast<int64_t>(n);
      c = terrain(k) + (i % 4 == 0 ? 1.0 : (i % 2 == 0 ? -0.3 : 0.3));
    }
    cls.steps.push_back(k);
    cls.values.insert(cls.values.end(), {c, 0.8, n, 5.0});
    bad.steps.push_back(k);
    bad.values.insert(bad.values.end(), {c, 5.0});
  }
  log.signals = {truth, cls, bad};
  return log;
}

MetricResult compute(const RunLog& log, const std::string& yaml) {
  return testing::metric_on_log(log, yaml, kStep, kDuration);
}

const std::string kAcc = "{type: classification_accuracy, classifier: r/terrain, truth: r/truth/state";

TEST(ClassificationMetrics, AccuracyIsTheFractionOfCorrectDecisionsOnOneTerrain) {
  const RunLog log = classification_run();
  // window_s 1: decisions 20, 21 (t = 10, 10.5) and 40, 41 (t = 20, 20.5) have (t - 1, t]
  // across a terrain switch and are not counted: 56 counted. Wrong: n = 4, 8, ..., 60 (15)
  // minus 20 and 40 (not counted) = 13. Accuracy (56 - 13) / 56.
  const MetricResult r = compute(log, kAcc + "}");
  EXPECT_NEAR(r.value, 43.0 / 56.0, 1e-12);
  ASSERT_EQ(r.series.size(), 56u);
  EXPECT_NEAR(r.series[0].first, 0.5, 1e-12);  // the first decision, right
  EXPECT_EQ(r.series[0].second, 1.0);
  EXPECT_NEAR(r.series[3].first, 2.0, 1e-12);  // decision 4, wrong
  EXPECT_EQ(r.series[3].second, 0.0);
  EXPECT_NEAR(r.series[19].first, 11.0, 1e-12);  // decision 22: 20 and 21 were skipped
  // window_s 0.3: only decisions 20 and 40 straddle a switch (t = 10.5 looks at (10.2,
  // 10.5], all terrain 1): 58 counted, the same 13 wrong.
  EXPECT_NEAR(compute(log, kAcc + ", window_s: 0.3}").value, 45.0 / 58.0, 1e-12);
}

TEST(ClassificationMetrics, AWindowsTerrainIncludesTheTruthHeldAtItsStart) {
  // Truth recorded once a second (t = 0, 1, ..., 30): (t - w, t] also takes the sample held
  // at t - w. window_s 1: decision 20 (t = 10) sees 9 (0) and 10 (1), decision 21 sees 9 and
  // 10 as well: both skipped, as with dense truth: 43 / 56. window_s 0.3: decision 21
  // (t = 10.5) has no truth sample in (10.2, 10.5], only the one held from 10 (terrain 1):
  // counted; decision 20 sees 9 (held) and 10: skipped: 45 / 58.
  const RunLog log = classification_run(10);
  EXPECT_NEAR(compute(log, kAcc + "}").value, 43.0 / 56.0, 1e-12);
  EXPECT_NEAR(compute(log, kAcc + ", window_s: 0.3}").value, 45.0 / 58.0, 1e-12);
}

TEST(ClassificationMetrics, WindowSelectsTheDecisions) {
  const RunLog log = classification_run();
  // [15, 30]: decisions 30..60 (31), minus 40, 41: 29; wrong 32, 36, 44, 48, 52, 56, 60: 7.
  EXPECT_NEAR(compute(log, kAcc + ", from: 15}").value, 22.0 / 29.0, 1e-12);
  // [0, 9.5]: decisions 1..19, all on terrain 0; wrong 4, 8, 12, 16.
  EXPECT_NEAR(compute(log, kAcc + ", to: 9.5}").value, 15.0 / 19.0, 1e-12);
  // [29.6, 29.9]: no decision (29.5 and 30 lie outside): null.
  const MetricResult none = compute(log, kAcc + ", from: 29.6, to: 29.9}");
  EXPECT_TRUE(std::isnan(none.value));
  EXPECT_TRUE(none.series.empty());
}

TEST(ClassificationMetrics, ConfigurationErrorsNameTheKey) {
  const RunLog log = classification_run();
  auto fails = [&](const std::string& yaml, const std::string& expected) {
    return testing::metric_fails(log, yaml, kStep, kDuration, expected);
  };
  EXPECT_TRUE(fails("{type: classification_accuracy, classifier: r/votes, truth: r/truth/state}",
                    "classifier: signal 'r/votes' has no field 'windows'"));
  EXPECT_TRUE(fails("{type: classification_accuracy, classifier: r/terrain, truth: r/terrain}",
                    "truth: signal 'r/terrain' has no field 'terrain'"));
  EXPECT_TRUE(fails("{type: classification_accuracy, classifier: r/terrain}", "truth: required key is missing"));
  EXPECT_TRUE(fails(kAcc + ", window_s: 0}", "window_s: must be > 0 s"));
  EXPECT_TRUE(fails(kAcc + ", from: 31}", "from: must be in [0, duration]"));
  EXPECT_TRUE(fails(kAcc + ", tolerance: 0.02}", "tolerance: unknown key"));
}

}  // namespace
}  // namespace plexus::scenario
