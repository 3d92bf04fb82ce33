// The PSD feature windows the terrain classifier and the terrain recorder share (paper 001
// section 3.2; docs/algorithms/skid_steer.md). Their keys:
//   window_s (1.0), hop_s (= window_s), min_hz (1), max_hz (50), taper (rectangular),
//   log10 (true)
// The sample rate is the component's rate: run it at the IMU's rate.
//
// Sample times (realtime; docs/distributed.md, "Late samples"): a window holds the IMU
// samples of window_s seconds, one per period, each in the slot of its own time. The
// realtime host runs each step once its IMU sample has arrived, so every sample is pushed at
// its own step, in order. A sample that never came in time (a later one arrived before it
// was read) leaves its slot empty: up to a tenth of a window of such slots in a row are
// filled by linear interpolation between the samples on either side, so the window keeps its
// time axis; a longer gap drops the partial window and filling starts again after it.
// `missing` counts the samples that never came. In `plexus sim` and lockstep none is missing.
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
  uint64_t missing = 0;  ///< IMU samples that never came (above)

  explicit WindowedFeatures(const ComponentConfig& c);

  /// Feeds the input's new sample, if any; true when a window's features are ready.
  bool push(const InputPort& in);

 private:
  int64_t period_steps_;  // the IMU's period (the component's), base steps
  std::size_t max_fill_;  // longest gap filled, samples
  int64_t due_ = -1;      // the IMU step due at the previous step
  int64_t pushed_ = -1;   // the step of the last sample pushed
  double last_ = 0.0;     // its value
  static std::size_t samples(const ComponentConfig& c, const std::string& key, double fallback);
  static std::size_t hop(const ComponentConfig& c);
  static algorithms::PsdFeatureParams feature_params(const ComponentConfig& c);
};

}  // namespace plexus::scenario
