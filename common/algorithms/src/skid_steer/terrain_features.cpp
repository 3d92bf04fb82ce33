// PSD terrain features with FFTW3 (docs/algorithms/skid_steer.md, "Terrain features").
#include "plexus/algorithms/skid_steer/terrain_features.hpp"

#include <fftw3.h>

#include <cmath>
#include <mutex>
#include <numbers>
#include <stdexcept>

#include "plexus/algorithms/core/validation.hpp"

namespace plexus::algorithms {

namespace {
constexpr const char* kWherePsdFeatures = "psd_features";

/// FFTW's planner is not thread-safe: every plan creation/destruction in this library holds it.
std::mutex& fftw_planner_mutex() {
  static std::mutex m;
  return m;
}
}  // namespace

SpectrumTaper spectrum_taper_from_string(const std::string& name) {
  if (name == "rectangular") return SpectrumTaper::kRectangular;
  if (name == "hann") return SpectrumTaper::kHann;
  throw std::invalid_argument("psd_features: taper must be rectangular or hann (got '" + name + "')");
}

const char* to_string(SpectrumTaper taper) { return taper == SpectrumTaper::kHann ? "hann" : "rectangular"; }

PsdFeatureExtractor::PsdFeatureExtractor(const PsdFeatureParams& params) : params_(params) {
  using namespace validation;
  require_positive(kWherePsdFeatures, "sample_rate_hz", params.sample_rate_hz);
  if (params.window_samples < 4) fail(kWherePsdFeatures, "window_samples", ">= 4", params.window_samples);
  require_non_negative(kWherePsdFeatures, "min_hz", params.min_hz);
  const double nyquist = 0.5 * params.sample_rate_hz;
  if (!(params.max_hz > params.min_hz && params.max_hz <= nyquist)) {
    fail(kWherePsdFeatures, "max_hz", "> min_hz and <= the Nyquist frequency " + format_value(nyquist) + " Hz",
         params.max_hz);
  }
  require_positive(kWherePsdFeatures, "log_floor", params.log_floor);
  const auto n = static_cast<std::size_t>(params.window_samples);
  const double df = params.sample_rate_hz / static_cast<double>(n);
  // Bins with min_hz <= k df <= max_hz (a relative 1e-9 slack absorbs rounding of k df).
  first_bin_ = static_cast<std::size_t>(std::ceil(params.min_hz / df - 1e-9));
  last_bin_ = static_cast<std::size_t>(std::floor(params.max_hz / df + 1e-9));
  if (last_bin_ > n / 2) last_bin_ = n / 2;
  if (last_bin_ < first_bin_) {
    fail(kWherePsdFeatures, "max_hz",
         "such that [min_hz, max_hz] holds a bin (bins are " + format_value(df) + " Hz apart)", params.max_hz);
  }
  taper_.assign(n, 1.0);
  if (params.taper == SpectrumTaper::kHann) {
    for (std::size_t i = 0; i < n; ++i) {
      taper_[i] = 0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n));
    }
  }
  double sum_w2 = 0.0;
  for (double w : taper_) sum_w2 += w * w;
  scale_ = 1.0 / (params.sample_rate_hz * sum_w2);

  const std::lock_guard lock(fftw_planner_mutex());
  in_ = fftw_alloc_real(n);
  out_ = fftw_alloc_complex(n / 2 + 1);
  if (!in_ || !out_) throw std::bad_alloc();
  plan_ = fftw_plan_dft_r2c_1d(params.window_samples, in_, static_cast<fftw_complex*>(out_), FFTW_ESTIMATE);
  if (!plan_) throw std::runtime_error("psd_features: FFTW could not create a plan");
}

PsdFeatureExtractor::~PsdFeatureExtractor() {
  const std::lock_guard lock(fftw_planner_mutex());
  if (plan_) fftw_destroy_plan(static_cast<fftw_plan>(plan_));
  fftw_free(in_);
  fftw_free(out_);
}

double PsdFeatureExtractor::frequency(std::size_t i) const {
  return static_cast<double>(first_bin_ + i) * params_.sample_rate_hz / static_cast<double>(params_.window_samples);
}

void PsdFeatureExtractor::compute(std::span<const double> window, std::span<double> features) {
  const auto n = static_cast<std::size_t>(params_.window_samples);
  if (window.size() != n) throw std::invalid_argument("psd_features: window has the wrong number of samples");
  if (features.size() != size()) throw std::invalid_argument("psd_features: feature buffer has the wrong size");
  double mean = 0.0;
  for (double x : window) mean += x;
  mean /= static_cast<double>(n);
  for (std::size_t i = 0; i < n; ++i) in_[i] = (window[i] - mean) * taper_[i];
  fftw_execute(static_cast<fftw_plan>(plan_));
  const auto* X = static_cast<const fftw_complex*>(out_);
  for (std::size_t k = first_bin_; k <= last_bin_; ++k) {
    const double c = (k == 0 || 2 * k == n) ? 1.0 : 2.0;
    double p = c * (X[k][0] * X[k][0] + X[k][1] * X[k][1]) * scale_;
    if (params_.log10) p = std::log10(p + params_.log_floor);
    features[k - first_bin_] = p;
  }
}

SampleWindow::SampleWindow(std::size_t size, std::size_t hop) : hop_(hop) {
  if (size < 1) throw std::invalid_argument("sample_window: size must be >= 1 (got 0)");
  if (hop < 1 || hop > size) {
    throw std::invalid_argument("sample_window: hop must be in [1, size] (got " + std::to_string(hop) + ")");
  }
  ring_.assign(size, 0.0);
  window_.assign(size, 0.0);
}

bool SampleWindow::push(double x) {
  const std::size_t n = ring_.size();
  ring_[head_] = x;
  head_ = (head_ + 1) % n;
  if (filled_ < n) ++filled_;
  ++since_;
  if (filled_ < n || since_ < hop_) return false;
  since_ = 0;
  for (std::size_t i = 0; i < n; ++i) window_[i] = ring_[(head_ + i) % n];
  return true;
}

}  // namespace plexus::algorithms
