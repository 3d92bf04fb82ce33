// Terrain ICR library (terrain_icr_library.hpp): file round trip and errors, the
// accumulator's statistics, and the ICR EKF's prior reset.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "plexus/algorithms/skid_steer/icr_ekf.hpp"
#include "plexus/algorithms/skid_steer/terrain_icr_library.hpp"

namespace plexus::algorithms {
namespace {

std::string temp_file(const std::string& name, const std::string& text = {}) {
  const auto path = (std::filesystem::temp_directory_path() / (name + std::to_string(::getpid()))).string();
  if (!text.empty()) std::ofstream(path) << text;
  return path;
}

std::string error_of(const std::string& text) {
  const auto path = temp_file("icr_lib_bad_", text);
  try {
    load_terrain_icr_library(path);
  } catch (const TrainingFileError& e) {
    std::filesystem::remove(path);
    return std::string(e.what()).substr(path.size());
  }
  std::filesystem::remove(path);
  return "no error";
}

TEST(TerrainIcrLibrary, AccumulatesMeanAndSampleVariancePlusTheFiltersVariance) {
  TerrainIcrAccumulator acc;
  // y_l 1, 2, 3: mean 2, sample variance 1; filter sd 0.5 -> sd = sqrt(1 + 0.25).
  for (double v : {1.0, 2.0, 3.0}) acc.add(4, {v, -1.0, 0.1}, {0.5, 0.5, 0.5});
  const auto lib = acc.library({{4, "sand"}});
  const auto* p = lib.find(4);
  ASSERT_NE(p, nullptr);
  EXPECT_DOUBLE_EQ(p->mean.y_l, 2.0);
  EXPECT_DOUBLE_EQ(p->mean.y_r, -1.0);
  EXPECT_NEAR(p->sd(0), std::sqrt(1.25), 1e-12);
  EXPECT_NEAR(p->sd(1), 0.5, 1e-12);  // no spread: the filter's own sd
  EXPECT_EQ(p->samples, 3);
  EXPECT_EQ(acc.samples(4), 3);
  EXPECT_EQ(acc.samples(0), 0);
}

TEST(TerrainIcrLibrary, SavesAndLoadsTheSameValues) {
  TerrainIcrAccumulator acc;
  acc.add(0, {0.3, -0.5, -0.1}, {0.01, 0.02, 0.03});
  acc.add(2, {0.4, -0.6, -0.2}, {0.01, 0.01, 0.01});
  const auto path = temp_file("icr_lib_");
  save_terrain_icr_library(path, acc.library({{0, "concrete"}, {2, "grass"}}), "a test");
  const auto lib = load_terrain_icr_library(path);
  std::filesystem::remove(path);
  ASSERT_EQ(lib.classes.size(), 2u);
  EXPECT_EQ(lib.names.at(2), "grass");
  EXPECT_NEAR(lib.find(2)->mean.x_G, -0.2, 1e-9);
  EXPECT_NEAR(lib.find(0)->sd(2), 0.03, 1e-6);
  EXPECT_EQ(lib.find(1), nullptr);
}

TEST(TerrainIcrLibrary, BadFilesNameTheLineAndWhatIsWrong) {
  const std::string head = "plexus-terrain-icr-library 1\n";
  EXPECT_EQ(error_of("hello\n"), ":1: expected 'plexus-terrain-icr-library 1'");
  EXPECT_EQ(error_of(head), ": no class records");
  EXPECT_EQ(error_of(head + "klass 0 a 1 -1 0 1 1 1 5\n"), ":2: unknown record 'klass' (expected class)");
  EXPECT_EQ(error_of(head + "class 0 a 1 -1 0 1 1 1\n"),
            ":2: class: expected id, name, y_l, y_r, x_G, sd_y_l, sd_y_r, sd_x_G, samples");
  EXPECT_EQ(error_of(head + "class 0 a 1 -1 nan 1 1 1 5\n"), ":2: x_G: expected a finite number, got 'nan'");
  EXPECT_EQ(error_of(head + "class 0 a -1 1 0 1 1 1 5\n"),
            ":2: y_l must be greater than y_r (left track left of the right one)");
  EXPECT_EQ(error_of(head + "class 0 a 1 -1 0 1 0 1 5\n"), ":2: sd: must be > 0");
  EXPECT_EQ(error_of(head + "class 0 a 1 -1 0 1 1 1 5\nclass 0 b 1 -1 0 1 1 1 5\n"), ":3: class 0 is listed twice");
  EXPECT_EQ(error_of(head + "class -1 a 1 -1 0 1 1 1 5\n"), ":2: class id: must be an integer >= 0");
}

TEST(IcrEkfPriorReset, SetsTheIcrsAndTheirCovarianceAndKeepsThePose) {
  IcrEkf ekf{IcrEkfParams{}};
  ekf.reset({1.0, 2.0, 0.3});
  ekf.predict({0.3, 0.5}, 0.01);
  const Pose2 pose = ekf.pose();
  ekf.reset_to_prior({0.4, -0.6, -0.2}, {0.01, 0.02, 0.03});
  EXPECT_EQ(ekf.pose().x, pose.x);
  EXPECT_EQ(ekf.pose().theta, pose.theta);
  EXPECT_EQ(ekf.icr().y_l, 0.4);
  EXPECT_EQ(ekf.icr().x_G, -0.2);
  EXPECT_DOUBLE_EQ(ekf.covariance()(4, 4), 0.02 * 0.02);
  EXPECT_DOUBLE_EQ(ekf.covariance()(0, 0), IcrEkfParams::paper_p_b()(0));  // the pose block of P_B
  EXPECT_EQ(ekf.covariance()(0, 3), 0.0);
}

TEST(IcrEkfPriorReset, LogLikelihoodFavoursTheFilterWhosePredictionIsRight) {
  // Two filters, same pose, ICRs right (tight) and wrong (tight): after driving a turn, the
  // right one's innovations are more likely (smaller NIS + log det S).
  const IcrParams truth{0.3, -0.5, -0.1};
  IcrEkf right{IcrEkfParams{}}, wrong{IcrEkfParams{}};
  Pose2 p{0, 0, 0};
  right.reset(p), wrong.reset(p);
  right.reset_to_prior(truth, {0.01, 0.01, 0.01});
  wrong.reset_to_prior({0.5, -0.7, -0.3}, {0.01, 0.01, 0.01});
  double l_right = 0, l_wrong = 0;
  for (int k = 1; k <= 100; ++k) {
    const TrackSpeeds u{0.2, 0.6};
    p = icr_euler_step(p, icr_body_velocity(truth, u), 0.01);
    right.predict(u, 0.01), wrong.predict(u, 0.01);
    if (k % 5 == 0) {
      ASSERT_TRUE(right.update(p));
      ASSERT_TRUE(wrong.update(p));
      l_right += right.last_neg2_log_likelihood();
      l_wrong += wrong.last_neg2_log_likelihood();
    }
  }
  EXPECT_LT(l_right + 10.0, l_wrong);
}

}  // namespace
}  // namespace plexus::algorithms
