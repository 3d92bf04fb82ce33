// The PSD feature windows the terrain classifier and the terrain recorder share (paper 001
// section 3.2; docs/algorithms/skid_steer.md). Their keys:
//   window_s (1.0), hop_s (= window_s), min_hz (1), max_hz (50), taper (rectangular),
//   log10 (true)
// The sample rate is the component's rate: run it at the IMU's rate.
//
// Sample times (realtime; docs/distributed.md, "Late samples"): a window is a run of
// consecutive IMU samples. The realtime host runs each step once its IMU sample has arrived,
// so every sample is pushed at its own step, in order. A sample that never came in time (a
// later one arrived before it was read) leaves a gap: a window across it would not be evenly
// sampled, so the partial window is dropped and filling starts again from the sample after
// the gap (gaps counts them). In `plexus sim` and lockstep there is never a gap.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "plexus/algorithms/skid_steer/terrain_features.hpp"
#include "plexus/scenario/component.hpp"
#include "services/common/new_sample.hpp"

namespace plexus::scenario {

/// Window and feature parameters shared by the classifier and the recorder: the sample
/// rate is the component's rate (run it at the IMU's rate).
struct WindowedFeatures {
  algorithms::PsdFeatureExtractor extractor;
  algorithms::SampleWindow window;
  std::vector<double> features;
  NewSample fresh;
  uint64_t gaps = 0;  ///< partial windows dropped for a missing sample (above)

  explicit WindowedFeatures(const ComponentConfig& c);

  /// Feeds the input's new sample, if any; true when a window's features are ready.
  bool push(const InputPort& in);

 private:
  int64_t due_ = -1;     // the IMU step due at the previous step
  int64_t pushed_ = -1;  // the step of the last sample pushed
  static std::size_t samples(const ComponentConfig& c, const std::string& key, double fallback);
  static std::size_t hop(const ComponentConfig& c);
  static algorithms::PsdFeatureParams feature_params(const ComponentConfig& c);
};

}  // namespace plexus::scenario
