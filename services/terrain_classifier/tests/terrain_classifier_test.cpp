// terrain_classifier: terrain_classifier (PSD features + kNN, paper 001 section 3.2) and
// terrain_recorder. Imu {a_z} in -> edge check -> window -> features -> kNN ->
// TerrainClass out; Imu + SkidSteerTruth {terrain} in -> labelled windows -> training file.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include "plexus/algorithms/core/random.hpp"
#include "plexus/algorithms/skid_steer/knn_classifier.hpp"
#include "plexus/algorithms/skid_steer/terrain_features.hpp"
#include "plexus/algorithms/skid_steer/training_set.hpp"
#include "service_harness.hpp"

namespace plexus::services_test {
namespace {

// The component types of services/terrain_classifier/ whose data path this file tests.
const Covers kCovers{"terrain_classifier", "terrain_recorder"};

namespace alg = plexus::algorithms;
namespace fs = std::filesystem;

// The services' feature defaults at 100 Hz: 1 s windows (100 samples), 1..50 Hz, log10.
alg::PsdFeatureParams feature_params() {
  alg::PsdFeatureParams p;
  p.sample_rate_hz = 100.0;
  p.window_samples = 100;
  p.log10 = true;
  return p;
}

// The vibration of a terrain on gravity: a tone of `hz` and broadband noise, strong on the
// rough terrain (20 Hz), weak on the smooth one (5 Hz): every feature tells them apart. The
// noise is reproducible (drawn from the sample's index).
double vibration(double hz, int64_t k) {
  const double t = 0.01 * static_cast<double>(k);
  alg::Rng noise(static_cast<uint64_t>(k) * 7919u + 17u);
  return 9.81 + std::sin(2 * std::numbers::pi * hz * t) + (hz > 10.0 ? 1.0 : 0.1) * noise.normal();
}

std::vector<double> features_of(double hz, int64_t first) {
  alg::PsdFeatureExtractor e(feature_params());
  std::vector<double> window, f(e.size());
  for (int64_t k = first; k < first + 100; ++k) window.push_back(vibration(hz, k));
  e.compute(window, f);
  return f;
}

class TempDir {
 public:
  TempDir() : path_(fs::temp_directory_path() / ("plexus_services_test_" + std::to_string(::getpid()))) {
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  fs::path path_;
};

// Training set: class 0 "smooth" at 5 Hz, class 1 "rough" at 20 Hz, three windows each,
// recorded elsewhere in time than the windows the tests classify (other noise).
std::string write_training(const TempDir& dir) {
  const std::string path = dir.file("training.txt");
  alg::PsdFeatureExtractor e(feature_params());
  alg::TrainingSetWriter w(path, alg::FeatureLayout::of(e), {{0, "smooth"}, {1, "rough"}});
  for (int64_t first : {1000, 1100, 1200}) {
    w.append(0, features_of(5.0, first));
    w.append(1, features_of(20.0, first));
  }
  return path;
}

std::string classifier_doc(const std::string& training, int k = 3) {
  return "name: cls_part\nstep: 0.01\nservices:\n  cls: {type: terrain_classifier, robot: r2, k: " + std::to_string(k) +
         ", training_file: " + training + "}\n";
}

msg::Imu imu(const ServiceUnderTest& s, int64_t k, double a_z) {
  auto m = s.stamped<msg::Imu>(k);
  m.linear_acceleration()[2] = a_z;
  return m;
}

// --- terrain_classifier -----------------------------------------------------------------

TEST(TerrainClassifier, ClassOfAKnownWindow) {
  const TempDir dir;
  const std::string doc = classifier_doc(write_training(dir));
  ServiceUnderTest s(doc);
  EXPECT_EQ(s.message_type("r2/imu"), "Imu");
  EXPECT_EQ(s.message_type("r2/terrain"), "TerrainClass");
  // First window (steps 0..99): the 20 Hz terrain, class 1; second (100..199): 5 Hz, class 0.
  for (int64_t k = 0; k < 200; ++k) {
    ASSERT_EQ(s.deliver("r2/imu", imu(s, k, vibration(k < 100 ? 20.0 : 5.0, k))), Rejection::none);
    s.step(k);
    if (k == 98) {
      EXPECT_EQ(s.published<msg::TerrainClass>("r2/terrain").terrain_id(), -1);  // no decision yet
    }
    if (k == 99) {
      const auto m = s.published<msg::TerrainClass>("r2/terrain");
      EXPECT_EQ(m.terrain_id(), 1);
      EXPECT_EQ(m.confidence(), 1.0);
      EXPECT_EQ(m.windows(), 1u);
      EXPECT_EQ(m.votes(), 3);  // all three nearest windows are rough ones
    }
  }
  const auto m = s.published<msg::TerrainClass>("r2/terrain");
  EXPECT_EQ(m.terrain_id(), 0);
  EXPECT_EQ(m.windows(), 2u);
  EXPECT_EQ(s.check_output("r2/terrain"), Rejection::none);
  // The same decision as the algorithm's on that window's features.
  alg::KnnParams kp;
  kp.k = 3;
  const alg::KnnClassifier knn(alg::load_training_set(dir.file("training.txt")), kp);
  const alg::KnnResult first = knn.classify(features_of(20.0, 0)), second = knn.classify(features_of(5.0, 100));
  EXPECT_EQ(first.label, 1);
  EXPECT_EQ(second.label, 0);
  EXPECT_EQ(m.votes(), second.votes);
  EXPECT_EQ(m.confidence(), second.confidence);
}

TEST(TerrainClassifier, AMissingSampleIsInterpolatedInItsSlot) {
  // Realtime: the IMU sample of step 50 never came (step 50 reads the one of 49, step 51
  // the one of 51). Its slot gets the mean of its neighbours, so the first window is still
  // samples 0..99, decided at step 99, on the window the algorithm gets with that value.
  const TempDir dir;
  ServiceUnderTest s(classifier_doc(write_training(dir)));
  std::vector<double> window;
  for (int64_t k = 0; k < 100; ++k) {
    if (k != 50) {
      ASSERT_EQ(s.deliver("r2/imu", imu(s, k, vibration(20.0, k))), Rejection::none);
    }
    s.step(k);
    window.push_back(k == 50 ? vibration(20.0, 49) + (vibration(20.0, 51) - vibration(20.0, 49)) * 0.5
                             : vibration(20.0, k));
  }
  const auto m = s.published<msg::TerrainClass>("r2/terrain");
  EXPECT_EQ(m.terrain_id(), 1);
  EXPECT_EQ(m.windows(), 1u);
  alg::PsdFeatureExtractor e(feature_params());
  std::vector<double> f(e.size());
  e.compute(window, f);
  alg::KnnParams kp;
  kp.k = 3;
  const alg::KnnResult r = alg::KnnClassifier(alg::load_training_set(dir.file("training.txt")), kp).classify(f);
  EXPECT_EQ(m.votes(), r.votes);
  EXPECT_EQ(m.confidence(), r.confidence);
  EXPECT_EQ(s.scenario().components[0].component->dropped_late_samples(), 1u);
}

TEST(TerrainClassifier, AGapLongerThanATenthOfAWindowRestartsIt) {
  // 20 samples (steps 50..69) never came: more than a tenth of a window to fill, so the
  // partial window is dropped and the first one is samples 70..169, decided at step 169.
  const TempDir dir;
  ServiceUnderTest s(classifier_doc(write_training(dir)));
  for (int64_t k = 0; k < 170; ++k) {
    if (k < 50 || k >= 70) {
      ASSERT_EQ(s.deliver("r2/imu", imu(s, k, vibration(20.0, k))), Rejection::none);
    }
    s.step(k);
    if (k == 168) {
      EXPECT_EQ(s.published<msg::TerrainClass>("r2/terrain").terrain_id(), -1) << "no decision yet";
    }
  }
  const auto m = s.published<msg::TerrainClass>("r2/terrain");
  EXPECT_EQ(m.terrain_id(), 1);
  EXPECT_EQ(m.windows(), 1u);
  EXPECT_EQ(s.scenario().components[0].component->dropped_late_samples(), 20u);
}

TEST(TerrainClassifier, BadSamplesAreRefusedAndLeaveTheWindowAlone) {
  const TempDir dir;
  const std::string doc = classifier_doc(write_training(dir));
  const Feed feed = [](ServiceUnderTest& s, int64_t k) {
    ASSERT_EQ(s.deliver("r2/imu", imu(s, k, vibration(20.0, k))), Rejection::none);
  };
  expect_refused_without_effect(
      doc, {}, {"r2/terrain"}, 100, 60, feed,
      {
          {"a_z NaN", [](ServiceUnderTest& s, int64_t k) { return s.deliver("r2/imu", imu(s, k, kNaN)); },
           Rejection::non_finite},
          {"a_z 2e7", [](ServiceUnderTest& s, int64_t k) { return s.deliver("r2/imu", imu(s, k, 2e7)); },
           Rejection::out_of_range},
          {"before the epoch", [](ServiceUnderTest& s, int64_t) { return s.deliver("r2/imu", imu(s, -1, 5.0)); },
           Rejection::negative_time},
      });
}

TEST(TerrainClassifier, BadParametersAreConfigurationErrors) {
  const TempDir dir;
  const std::string doc = classifier_doc(write_training(dir));
  expect_config_errors(doc,
                       {
                           {"services.cls.training_file=" + dir.file("missing.txt"), {"services.cls.training_file"}},
                           {"services.cls.k=0", {"services.cls.k"}},
                           {"services.cls.tie_rule=coin", {"services.cls.tie_rule"}},
                           {"services.cls.scaling=log", {"services.cls.scaling"}},
                           {"services.cls.window_s=0.015", {"services.cls.window_s"}},
                           {"services.cls.min_hz=2", {"services.cls.training_file", "differently"}},
                           {"services.cls.taper=triangle", {"services.cls.taper"}},
                       });
}

// --- terrain_recorder -------------------------------------------------------------------

std::string recorder_doc(const std::string& output) {
  return "name: rec_part\nstep: 0.01\nservices:\n  rec: {type: terrain_recorder, robot: r2, windows_per_class: 1, "
         "output: " +
         output + "}\n";
}

msg::SkidSteerTruth truth(const ServiceUnderTest& s, int64_t k, int terrain) {
  auto m = s.stamped<msg::SkidSteerTruth>(k);
  m.terrain_id(terrain);
  return m;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Terrain 2 for two windows, then a window that crosses to terrain 1, then terrain 1.
int terrain_at(int64_t k) { return k < 250 ? 2 : 1; }

void feed_recorder(ServiceUnderTest& s, int64_t k) {
  ASSERT_EQ(s.deliver("r2/imu", imu(s, k, vibration(terrain_at(k) == 2 ? 20.0 : 5.0, k))), Rejection::none);
  ASSERT_EQ(s.deliver("r2/truth/state", truth(s, k, terrain_at(k))), Rejection::none);
}

TEST(TerrainRecorder, RecordsLabelledWindowsOfOneTerrainOnly) {
  const TempDir dir;
  const std::string out = dir.file("recorded.txt");
  ServiceUnderTest s(recorder_doc(out));
  EXPECT_EQ(s.message_type("r2/truth/state"), "SkidSteerTruth");
  for (int64_t k = 0; k < 400; ++k) {
    feed_recorder(s, k);
    s.step(k);
    if (k == 99) {
      EXPECT_EQ(s.out("r2/recorder", "written"), 1.0);  // window 0..99, terrain 2
    }
    if (k == 199) {
      EXPECT_EQ(s.out("r2/recorder", "written"), 1.0);  // terrain 2 again: 1 per class
    }
    if (k == 299) {
      EXPECT_EQ(s.out("r2/recorder", "written"), 1.0);  // 200..299 crosses 2 -> 1: skipped
    }
  }
  EXPECT_EQ(s.out("r2/recorder", "written"), 2.0);  // 300..399: terrain 1
  const alg::TrainingSet set = alg::load_training_set(out);
  ASSERT_EQ(set.labels, (std::vector<int>{2, 1}));
  const auto f0 = features_of(20.0, 0), f1 = features_of(5.0, 300);
  for (std::size_t i = 0; i < set.layout.features; ++i) {
    EXPECT_NEAR(set.sample(0)[i], f0[i], 1e-12) << i;
    EXPECT_NEAR(set.sample(1)[i], f1[i], 1e-12) << i;
  }
}

TEST(TerrainRecorder, BadSamplesAreRefusedAndLeaveTheRecordingAlone) {
  const TempDir dir;
  const std::string out = dir.file("recorded.txt");
  auto record = [&](const BadSample* bad) {
    const auto log = run_steps(recorder_doc(out), {}, {"r2/recorder"}, 100, feed_recorder, bad, 40);
    return std::make_pair(log.back().values[0], read_file(out));
  };
  const auto clean = record(nullptr);
  EXPECT_EQ(clean.first, 1.0);
  const std::vector<BadSample> table{
      {"a_z inf", [](ServiceUnderTest& s, int64_t k) { return s.deliver("r2/imu", imu(s, k, kInf)); },
       Rejection::non_finite},
      {"terrain -5", [](ServiceUnderTest& s, int64_t k) { return s.deliver("r2/truth/state", truth(s, k, -5)); },
       Rejection::out_of_range},
      {"truth x NaN",
       [](ServiceUnderTest& s, int64_t k) {
         auto m = truth(s, k, 1);
         m.x(kNaN);  // not a member it reads: its signal is {terrain} only
         return s.deliver("r2/truth/state", m);
       },
       Rejection::none},
  };
  for (std::size_t i = 0; i < 2; ++i) {
    const auto dirty = record(&table[i]);
    EXPECT_EQ(dirty.first, clean.first) << table[i].what;
    EXPECT_EQ(dirty.second, clean.second) << table[i].what;
  }
  ServiceUnderTest s(recorder_doc(out));
  EXPECT_EQ(table[2].deliver(s, 0), Rejection::none);
}

TEST(TerrainRecorder, BadParametersAreConfigurationErrors) {
  const TempDir dir;
  expect_config_errors(recorder_doc(dir.file("r.txt")),
                       {
                           {"services.rec.output=" + dir.file("no/such/dir/r.txt"), {"services.rec.output"}},
                           {"services.rec.label=-1", {"services.rec.label"}},
                           {"services.rec.windows_per_class=0", {"services.rec.windows_per_class"}},
                           {"services.rec.hop_s=2", {"services.rec", "hop"}},
                       });
}

}  // namespace
}  // namespace plexus::services_test
