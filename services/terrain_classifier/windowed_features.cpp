#include "services/terrain_classifier/windowed_features.hpp"

#include <cmath>
#include <stdexcept>

namespace plexus::scenario {

namespace alg = plexus::algorithms;

WindowedFeatures::WindowedFeatures(const ComponentConfig& c)
    : extractor(feature_params(c)),
      window(samples(c, "window_s", 1.0), hop(c)),
      features(extractor.size()),
      period_steps_(c.period_steps),
      max_fill_(samples(c, "window_s", 1.0) / 10) {}

bool WindowedFeatures::push(const InputPort& in) {
  const int64_t due_before = due_;
  due_ = in.due();
  if (!fresh(in)) return false;
  const int64_t step = in.sample().step;
  const double x = in[0];
  bool ready = false;
  if (pushed_ >= 0 && pushed_ < due_before && step > due_before) {
    // The sample due at the previous step never came: its slot, and any after it, are empty.
    const int64_t gap = (step - pushed_) / period_steps_ - 1;
    if (gap >= 1) {
      missing += static_cast<uint64_t>(gap);
      if (static_cast<std::size_t>(gap) <= max_fill_) {
        for (int64_t i = 1; i <= gap; ++i)
          ready = window.push(last_ + (x - last_) * static_cast<double>(i) / static_cast<double>(gap + 1)) || ready;
      } else {
        window.clear();
        ready = false;
      }
    }
  }
  pushed_ = step;
  last_ = x;
  ready = window.push(x) || ready;
  if (!ready) return false;
  extractor.compute(window.window(), features);
  return true;
}

std::size_t WindowedFeatures::samples(const ComponentConfig& c, const std::string& key, double fallback) {
  const double s = c.params().optional<double>(key, fallback);
  const double n = s / c.period();
  if (!(s > 0.0) || std::abs(n - std::round(n)) > 1e-6 || std::round(n) < 1) {
    c.params().fail(
        key, "must be a positive whole number of the component's periods (" + std::to_string(c.period()) + " s)");
  }
  return static_cast<std::size_t>(std::round(n));
}

std::size_t WindowedFeatures::hop(const ComponentConfig& c) {
  const double w = c.params().optional<double>("window_s", 1.0);
  return samples(c, "hop_s", w);
}

alg::PsdFeatureParams WindowedFeatures::feature_params(const ComponentConfig& c) {
  const YamlMap& p = c.params();
  alg::PsdFeatureParams f;
  f.sample_rate_hz = 1.0 / c.period();
  f.window_samples = static_cast<int>(samples(c, "window_s", 1.0));
  f.min_hz = p.optional<double>("min_hz", f.min_hz);
  f.max_hz = p.optional<double>("max_hz", f.max_hz);
  const auto taper = p.optional<std::string>("taper", "rectangular");
  try {
    f.taper = alg::spectrum_taper_from_string(taper);
  } catch (const std::invalid_argument&) {
    p.fail("taper", "expected rectangular or hann, got '" + taper + "'");
  }
  f.log10 = p.optional<bool>("log10", true);  // measured choice: docs/algorithms/skid_steer.md
  return f;
}

}  // namespace plexus::scenario
