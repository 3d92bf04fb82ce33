#include "plexus/algorithms/skid_steer/terrain_features.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <thread>
#include <vector>

#include "../support/validation_message.hpp"
#include "plexus/algorithms/core/random.hpp"

namespace plexus::algorithms {
namespace {

std::vector<double> tone(double f, double fs, int n, double amplitude, double offset, double phase = 0.3) {
  std::vector<double> x(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) x[i] = offset + amplitude * std::sin(2.0 * std::numbers::pi * f * i / fs + phase);
  return x;
}

std::size_t argmax(const std::vector<double>& v) {
  return static_cast<std::size_t>(std::max_element(v.begin(), v.end()) - v.begin());
}

TEST(PsdFeatures, PaperLayoutIs50BinsAt1To50Hz) {
  PsdFeatureExtractor e({});
  ASSERT_EQ(e.size(), 50u);
  EXPECT_DOUBLE_EQ(e.frequency(0), 1.0);
  EXPECT_DOUBLE_EQ(e.frequency(49), 50.0);
}

TEST(PsdFeatures, PureTonePeaksInItsBin) {
  for (const SpectrumTaper taper : {SpectrumTaper::kRectangular, SpectrumTaper::kHann}) {
    PsdFeatureParams p;
    p.taper = taper;
    PsdFeatureExtractor e(p);
    std::vector<double> f(e.size());
    for (int hz = 1; hz <= 49; ++hz) {
      e.compute(tone(hz, 100.0, 100, 2.0, 9.81), f);
      EXPECT_EQ(argmax(f), static_cast<std::size_t>(hz - 1)) << hz << " Hz, " << to_string(taper);
      if (taper == SpectrumTaper::kRectangular) {
        // Bin-centred tone, rectangular window: all its power A^2/2 lands in one bin of
        // width 1 Hz, none leaks.
        EXPECT_NEAR(f[hz - 1], 2.0 * 2.0 / 2.0, 1e-9);
        double rest = 0.0;
        for (std::size_t i = 0; i < f.size(); ++i) rest += i == static_cast<std::size_t>(hz - 1) ? 0.0 : f[i];
        EXPECT_LT(rest, 1e-9);
      }
    }
  }
}

TEST(PsdFeatures, OffBinTonePeaksInTheNearestBinAtOtherRates) {
  PsdFeatureParams p;
  p.sample_rate_hz = 200.0;
  p.window_samples = 256;
  p.min_hz = 2.0;
  p.max_hz = 80.0;
  p.taper = SpectrumTaper::kHann;
  PsdFeatureExtractor e(p);
  std::vector<double> f(e.size());
  for (double hz : {7.3, 21.9, 55.55}) {
    e.compute(tone(hz, 200.0, 256, 1.0, 0.0), f);
    const double found = e.frequency(argmax(f));
    EXPECT_LE(std::abs(found - hz), 0.5 * 200.0 / 256.0 + 1e-12) << hz;
  }
}

TEST(PsdFeatures, ParsevalWhiteNoisePowerSumsToTheVariance) {
  PsdFeatureParams p;
  p.min_hz = 0.0;  // all bins 0..50 Hz
  PsdFeatureExtractor e(p);
  std::vector<double> f(e.size());
  Rng rng(3);
  std::vector<double> x(100);
  for (double& v : x) v = rng.normal();
  double mean = 0.0, var = 0.0;
  for (double v : x) mean += v / 100.0;
  for (double v : x) var += (v - mean) * (v - mean) / 100.0;
  e.compute(x, f);
  double power = 0.0;
  for (double v : f) power += v * 1.0;  // bins 1 Hz wide
  EXPECT_NEAR(power, var, 1e-9 * var);
}

TEST(PsdFeatures, Log10Scale) {
  PsdFeatureParams p;
  p.log10 = true;
  PsdFeatureExtractor e(p);
  std::vector<double> f(e.size());
  e.compute(tone(10, 100, 100, 2.0, 0.0), f);
  EXPECT_NEAR(f[9], std::log10(2.0 + 1e-12), 1e-9);
  EXPECT_NEAR(f[0], -12.0, 1e-3);
}

TEST(PsdFeatures, RejectsBadParametersAndSizes) {
  using testing::invalid_argument_message;
  PsdFeatureParams p;
  p.window_samples = 2;
  EXPECT_EQ(invalid_argument_message<PsdFeatureExtractor>(p), "psd_features: window_samples must be >= 4 (got 2)");
  p = {};
  p.max_hz = 60;
  EXPECT_EQ(invalid_argument_message<PsdFeatureExtractor>(p),
            "psd_features: max_hz must be > min_hz and <= the Nyquist frequency 50 Hz (got 60)");
  p = {};
  p.sample_rate_hz = 0;
  EXPECT_EQ(invalid_argument_message<PsdFeatureExtractor>(p),
            "psd_features: sample_rate_hz must be finite and > 0 (got 0)");
  p = {};
  p.min_hz = 1.2;
  p.max_hz = 1.8;
  EXPECT_NE(invalid_argument_message<PsdFeatureExtractor>(p).find("holds a bin"), std::string::npos);
  p = {};
  p.log_floor = 0;
  EXPECT_EQ(invalid_argument_message<PsdFeatureExtractor>(p), "psd_features: log_floor must be finite and > 0 (got 0)");
  EXPECT_THROW(spectrum_taper_from_string("hamming"), std::invalid_argument);
  PsdFeatureExtractor e({});
  std::vector<double> f(50), w(99);
  EXPECT_THROW(e.compute(w, f), std::invalid_argument);
  std::vector<double> f49(49), w100(100);
  EXPECT_THROW(e.compute(w100, f49), std::invalid_argument);
}

TEST(PsdFeatures, ExtractorsOnSeveralThreadsAgree) {
  std::vector<double> a(50), b(50);
  const auto x = tone(13, 100, 100, 1.0, 0.0);
  std::thread t1([&] {
    PsdFeatureExtractor e({});
    e.compute(x, a);
  });
  std::thread t2([&] {
    PsdFeatureExtractor e({});
    e.compute(x, b);
  });
  t1.join();
  t2.join();
  EXPECT_EQ(a, b);
}

TEST(SampleWindow, ConsecutiveAndOverlappingWindows) {
  SampleWindow w(4, 4);
  std::vector<int> complete;
  for (int i = 0; i < 12; ++i) {
    if (w.push(i)) {
      complete.push_back(i);
      EXPECT_EQ(w.window()[0], i - 3);
      EXPECT_EQ(w.window()[3], i);
    }
  }
  EXPECT_EQ(complete, (std::vector<int>{3, 7, 11}));
  SampleWindow o(4, 2);
  complete.clear();
  for (int i = 0; i < 10; ++i) {
    if (o.push(i)) complete.push_back(i);
  }
  EXPECT_EQ(complete, (std::vector<int>{3, 5, 7, 9}));
  EXPECT_THROW(SampleWindow(4, 5), std::invalid_argument);
  EXPECT_THROW(SampleWindow(0, 1), std::invalid_argument);
}

}  // namespace
}  // namespace plexus::algorithms
