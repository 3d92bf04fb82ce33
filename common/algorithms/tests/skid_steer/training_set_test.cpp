#include "plexus/algorithms/skid_steer/training_set.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace plexus::algorithms {
namespace {

namespace fs = std::filesystem;

class TrainingFile : public ::testing::Test {
 protected:
  fs::path dir_ = fs::temp_directory_path() / ("plexus_training_" + std::to_string(::getpid()));
  void SetUp() override { fs::create_directories(dir_); }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& text) {
    const fs::path p = dir_ / name;
    std::ofstream(p) << text;
    return p.string();
  }
  /// The TrainingFileError message of loading `text`, "" if it loads.
  std::string error_of(const std::string& text) {
    const std::string p = write("t.txt", text);
    try {
      load_training_set(p);
    } catch (const TrainingFileError& e) {
      const std::string m = e.what();
      return m.rfind(p + ":", 0) == 0 ? m.substr(p.size() + 1) : "WRONG PREFIX: " + m;
    }
    return "";
  }
};

const std::string kHeader =
    "plexus-terrain-training 1\nsample_rate_hz 100\nwindow_samples 4\nband_hz 25 50\ntaper rectangular\n"
    "scale linear\nfeatures 2\n";

TEST_F(TrainingFile, WriterOutputLoadsBackExactly) {
  PsdFeatureParams p;
  p.window_samples = 4;
  p.min_hz = 25;
  PsdFeatureExtractor e(p);
  const FeatureLayout layout = FeatureLayout::of(e);
  ASSERT_EQ(layout.features, 2u);
  const std::string path = (dir_ / "w.txt").string();
  {
    TrainingSetWriter w(path, layout, {{0, "concrete"}, {2, "grass land"}}, "a test");
    w.append(0, std::vector<double>{0.1, 1.0 / 3.0});
    w.append(2, std::vector<double>{1e-300, 12345.678901234567});
    EXPECT_EQ(w.written(), 2u);
  }
  const TrainingSet s = load_training_set(path);
  EXPECT_EQ(s.layout.difference(layout), "");
  EXPECT_EQ(s.labels, (std::vector<int>{0, 2}));
  EXPECT_EQ(s.features, (std::vector<double>{0.1, 1.0 / 3.0, 1e-300, 12345.678901234567}));
  EXPECT_EQ(s.class_names.at(2), "grass land");
  EXPECT_EQ(s.sample(1)[1], 12345.678901234567);
}

TEST_F(TrainingFile, CommentsBlankLinesAndCrLfAreAccepted) {
  EXPECT_EQ(error_of("# c\n\n" + kHeader + "# x\nsample 1 0 0.5\r\n\n"), "");
}

TEST_F(TrainingFile, EveryErrorNamesFileAndLine) {
  EXPECT_EQ(error_of(""), "0: empty training file (expected the header 'plexus-terrain-training 1')");
  EXPECT_EQ(error_of("hello 1\n"), "1: expected the header 'plexus-terrain-training 1', got 'hello 1'");
  EXPECT_EQ(error_of("plexus-terrain-training 2\n"), "1: unsupported version 2 (this build reads version 1)");
  EXPECT_EQ(error_of("plexus-terrain-training x\n"), "1: version: expected an integer, got 'x'");
  EXPECT_EQ(error_of("plexus-terrain-training 1 2\n"), "1: 'plexus-terrain-training' takes 1 value, got 2");
  EXPECT_EQ(error_of(kHeader), "0: no samples");
  EXPECT_EQ(error_of(kHeader + "colour red\n"), "8: unknown key 'colour'");
  EXPECT_EQ(error_of(kHeader + "features 2\n"), "8: header key 'features' given twice");
  EXPECT_EQ(error_of("plexus-terrain-training 1\nsample 0 1 2\n"),
            "2: header key 'sample_rate_hz' missing before the first sample");
  EXPECT_EQ(error_of(kHeader + "sample 0 1\n"), "8: expected a class id and 2 features, got 2 values");
  EXPECT_EQ(error_of(kHeader + "sample 0 1 2 3\n"), "8: expected a class id and 2 features, got 4 values");
  EXPECT_EQ(error_of(kHeader + "sample 0 1 x2\n"), "8: feature 2: expected a number, got 'x2'");
  EXPECT_EQ(error_of(kHeader + "sample 0 1 inf\n"), "8: feature 2: must be finite, got 'inf'");
  EXPECT_EQ(error_of(kHeader + "sample 0 nan 1\n"), "8: feature 1: must be finite, got 'nan'");
  EXPECT_EQ(error_of(kHeader + "sample 0 -1 1\n"), "8: feature 1: a PSD must be >= 0, got -1");
  EXPECT_EQ(error_of(kHeader + "sample -1 1 1\n"), "8: class id must be in 0..1000000, got -1");
  EXPECT_EQ(error_of(kHeader + "sample 1.5 1 1\n"), "8: class id: expected an integer, got '1.5'");
  EXPECT_EQ(error_of(kHeader + "sample 0 1 1\nscale log10\n"), "9: header key 'scale' after the first sample");
  EXPECT_EQ(error_of(kHeader + "class 0 a\nclass 0 b\n"), "9: class 0 named twice");
  EXPECT_EQ(error_of(kHeader + "class 0\n"), "8: 'class' takes an id and a name");
  EXPECT_EQ(error_of(kHeader + "class -3 x\n"), "8: class id must be in 0..1000000, got -3");
  const std::string h = "plexus-terrain-training 1\n";
  EXPECT_EQ(error_of(h + "sample_rate_hz 0\n"), "2: sample_rate_hz must be > 0, got 0");
  EXPECT_EQ(error_of(h + "sample_rate_hz\n"), "2: 'sample_rate_hz' takes 1 value, got 0");
  EXPECT_EQ(error_of(h + "window_samples 2\n"), "2: window_samples must be in 4..1000000, got 2");
  EXPECT_EQ(error_of(h + "band_hz 5 1\n"), "2: band_hz must satisfy 0 <= min < max");
  EXPECT_EQ(error_of(h + "band_hz 5\n"), "2: 'band_hz' takes 2 values, got 1");
  EXPECT_EQ(error_of(h + "taper hamming\n"), "2: taper must be rectangular or hann, got 'hamming'");
  EXPECT_EQ(error_of(h + "scale dB\n"), "2: scale must be linear or log10, got 'dB'");
  EXPECT_EQ(error_of(h + "features 0\n"), "2: features must be in 1..100000, got 0");
  // log10 features may be negative
  std::string log_header = kHeader;
  log_header.replace(log_header.find("scale linear"), 12, "scale log10");
  EXPECT_EQ(error_of(log_header + "sample 0 -3 -4\n"), "");
}

TEST_F(TrainingFile, MissingFileAndUnwritablePath) {
  const std::string missing = (dir_ / "nope.txt").string();
  try {
    load_training_set(missing);
    FAIL();
  } catch (const TrainingFileError& e) {
    EXPECT_EQ(std::string(e.what()), missing + ":0: cannot open the training file");
  }
  const std::string bad = (dir_ / "no_dir" / "x.txt").string();
  try {
    TrainingSetWriter w(bad, {});
    FAIL();
  } catch (const TrainingFileError& e) {
    EXPECT_EQ(std::string(e.what()), bad + ":0: cannot open the training file for writing");
  }
}

TEST_F(TrainingFile, WriterRejectsBadSamples) {
  TrainingSetWriter w((dir_ / "w.txt").string(), {});
  EXPECT_THROW(w.append(-1, std::vector<double>(50, 0.0)), std::invalid_argument);
  EXPECT_THROW(w.append(0, std::vector<double>(49, 0.0)), std::invalid_argument);
}

TEST(FeatureLayout, DifferenceNamesTheField) {
  FeatureLayout a, b;
  EXPECT_EQ(a.difference(b), "");
  b.sample_rate_hz = 200;
  EXPECT_EQ(a.difference(b), "sample_rate_hz 100 vs 200");
  b = a;
  b.taper = SpectrumTaper::kHann;
  EXPECT_EQ(a.difference(b), "taper rectangular vs hann");
  b = a;
  b.log10 = true;
  EXPECT_EQ(a.difference(b), "scale linear vs log10");
}

}  // namespace
}  // namespace plexus::algorithms
