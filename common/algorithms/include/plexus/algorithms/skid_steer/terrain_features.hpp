// Terrain features: the power spectral density of one window of IMU z-acceleration.
//
// Paper 001 section 3.2: IMU z-acceleration at 100 Hz, windows of 1 s (100 samples),
// "power spectrum at 1-50 Hz" -> a 50-element feature vector. Computed with FFTW3 (a
// real-to-complex DFT, FFTW_ESTIMATE plan created once at construction on buffers owned
// by the extractor; compute() only executes it). The estimate, chosen here:
//   x_n <- (x_n - mean(x)) w_n          (mean removed: gravity and bias are not terrain)
//   X_k = sum_n x_n exp(-2 pi i k n / N)
//   PSD_k = c |X_k|^2 / (fs sum_n w_n^2),  c = 2 except c = 1 at k = 0 and k = N/2
// (one-sided periodogram, (m/s^2)^2/Hz), kept at the bins f_k = k fs / N with
// min_hz <= f_k <= max_hz; with fs = 100 Hz, N = 100 that is k = 1..50 (1 Hz apart).
// Taper w: rectangular (w = 1, the paper's plain PSD) or Hann. Optionally log10(PSD + eps).
//
// Thread safety: FFTW's planner (plan creation and destruction) is not thread-safe. The
// constructor and destructor serialise their planner calls with a mutex private to this
// library, so extractors may be built on several threads; code elsewhere in the process
// that calls the FFTW planner directly must not do so concurrently. compute() on distinct
// extractors is thread-safe (fftw_execute is); one extractor is not shareable across threads.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace plexus::algorithms {

enum class SpectrumTaper { kRectangular, kHann };

/// "rectangular" | "hann"; throws std::invalid_argument otherwise.
SpectrumTaper spectrum_taper_from_string(const std::string& name);
const char* to_string(SpectrumTaper taper);

struct PsdFeatureParams {
  double sample_rate_hz = 100.0;  ///< > 0 (paper: 100)
  int window_samples = 100;       ///< >= 4 (paper: 100, i.e. 1 s)
  double min_hz = 1.0;            ///< >= 0 (paper: 1)
  double max_hz = 50.0;           ///< > min_hz, <= Nyquist (paper: 50); >= 1 bin in between
  SpectrumTaper taper = SpectrumTaper::kRectangular;
  bool log10 = false;        ///< features log10(PSD + log_floor) instead of PSD
  double log_floor = 1e-12;  ///< > 0
};

class PsdFeatureExtractor {
 public:
  /// Validates params and creates the FFTW plan; throws std::invalid_argument.
  explicit PsdFeatureExtractor(const PsdFeatureParams& params);
  ~PsdFeatureExtractor();
  PsdFeatureExtractor(const PsdFeatureExtractor&) = delete;
  PsdFeatureExtractor& operator=(const PsdFeatureExtractor&) = delete;

  /// Number of features (bins kept).
  std::size_t size() const { return last_bin_ - first_bin_ + 1; }
  /// Frequency of feature i, Hz.
  double frequency(std::size_t i) const;

  /// Writes size() features of `window` (window_samples values) into `features`. Throws
  /// std::invalid_argument on a size mismatch. No allocation.
  void compute(std::span<const double> window, std::span<double> features);

  const PsdFeatureParams& params() const { return params_; }

 private:
  PsdFeatureParams params_;
  std::size_t first_bin_ = 0;
  std::size_t last_bin_ = 0;
  std::vector<double> taper_;
  double scale_ = 0.0;    // 1 / (fs sum w^2)
  double* in_ = nullptr;  // fftw_malloc'd, window_samples
  void* out_ = nullptr;   // fftw_complex[window_samples / 2 + 1]
  void* plan_ = nullptr;  // fftw_plan
};

/// Buffers a stream of samples into windows of `size` samples, every `hop` samples
/// (hop = size: consecutive, non-overlapping windows). Fixed storage, no allocation in push.
class SampleWindow {
 public:
  /// size >= 1, 1 <= hop <= size; throws std::invalid_argument.
  SampleWindow(std::size_t size, std::size_t hop);
  /// Adds a sample; true when a window is complete (read it with window()).
  bool push(double x);
  /// The last complete window, oldest sample first.
  std::span<const double> window() const { return {window_.data(), window_.size()}; }
  /// Drops partial data (e.g. after a gap).
  void clear() {
    filled_ = 0;
    since_ = 0;
  }

 private:
  std::vector<double> ring_;
  std::vector<double> window_;
  std::size_t hop_;
  std::size_t head_ = 0;    // next write position in ring_
  std::size_t filled_ = 0;  // samples in ring_, up to size
  std::size_t since_ = 0;   // samples since the last complete window
};

}  // namespace plexus::algorithms
