// Metrics of the balancing family (paper 002; docs/algorithms/balancing.md). Angles are
// recorded in rad; these report degrees, as the paper does, and keep the sign (the paper's
// error mean is signed).
//
//   angle_error_deg:  signal, field (theta), reference, reference_field (theta),
//                     stat: mean | abs_mean (|mean|) | std | max | min | max_abs | rms | final, from, to
//                     error = signal.field - reference.reference_field (reference held at or
//                     before each sample of `signal`), in degrees; std is the population
//                     standard deviation over the window
//   angle_error_std_difference_deg: signal, other, reference, field, reference_field, from, to:
//                     std of (signal - reference) minus std of (other - reference), deg
//                     (< 0: `signal` is the better estimate; the UKF-vs-EKF comparison)
//   angle_deg:        signal, field, stat (as above), from, to: one angle field, in degrees
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "plexus/scenario/metric.hpp"
#include "trace_window.hpp"

namespace plexus::scenario {
namespace {

using metric_detail::in_window;

constexpr double kDeg = 180.0 / std::numbers::pi;
using Series = std::vector<std::pair<double, double>>;

enum class Stat { mean, abs_mean, std_dev, max, min, max_abs, rms, final };

Stat parse_stat(const YamlMap& p) {
  const auto s = p.required<std::string>("stat");
  if (s == "mean") return Stat::mean;
  if (s == "abs_mean") return Stat::abs_mean;
  if (s == "std") return Stat::std_dev;
  if (s == "max") return Stat::max;
  if (s == "min") return Stat::min;
  if (s == "max_abs") return Stat::max_abs;
  if (s == "rms") return Stat::rms;
  if (s == "final") return Stat::final;
  p.fail("stat", "expected mean, abs_mean, std, max, min, max_abs, rms or final, got '" + s + "'");
}

double reduce(const Series& s, Stat stat) {
  if (s.empty()) return NAN;
  const double n = static_cast<double>(s.size());
  double sum = 0, sq = 0, mx = s.front().second, mn = mx, mabs = 0;
  for (const auto& [t, v] : s) {
    sum += v;
    sq += v * v;
    mx = std::max(mx, v);
    mn = std::min(mn, v);
    mabs = std::max(mabs, std::abs(v));
  }
  const double mean = sum / n;
  switch (stat) {
    case Stat::mean: return mean;
    case Stat::abs_mean: return std::abs(mean);
    case Stat::std_dev: {
      double var = 0;
      for (const auto& [t, v] : s) var += (v - mean) * (v - mean);
      return std::sqrt(var / n);
    }
    case Stat::max: return mx;
    case Stat::min: return mn;
    case Stat::max_abs: return mabs;
    case Stat::rms: return std::sqrt(sq / n);
    case Stat::final: return s.back().second;
  }
  return NAN;
}

/// Index of the field named by optional key `key` (default "theta") in `spec`.
int field_or_theta(const MetricSetup& s, const SignalSpec& spec, const std::string& key) {
  const auto name = s.params().optional<std::string>(key, "theta");
  const auto it = std::find(spec.fields.begin(), spec.fields.end(), name);
  if (it == spec.fields.end()) s.params().fail(key, spec.name + " has no field '" + name + "'");
  return static_cast<int>(it - spec.fields.begin());
}

/// (t, (a.ia - b.ib) in degrees) for each sample of a in the window, b held at or before it.
Series error_series(const RunLog& log, const std::string& a, int ia, const std::string& b, int ib, double from,
                    double to, double step) {
  const SignalTrace& ta = *log.find(a);
  const SignalTrace& tb = *log.find(b);
  Series out;
  std::size_t j = 0;
  bool have = false;
  for (std::size_t i = 0; i < ta.size(); ++i) {
    while (j < tb.size() && tb.steps[j] <= ta.steps[i]) {
      have = true;
      ++j;
    }
    const double t = log.time(ta.steps[i]);
    if (!have || !in_window(t, from, to, step)) continue;
    out.emplace_back(t, (ta.at(i, ia) - tb.at(j - 1, ib)) * kDeg);
  }
  return out;
}

const MetricRegistration kAngleErrorDeg{
    "angle_error_deg", "signed error of an angle field against a reference field, deg (stat: mean, std, max, ...)",
    [](const MetricSetup& s) -> MetricFunction {
      const SignalSpec& sig = s.signal("signal");
      const SignalSpec& ref = s.signal("reference");
      const int ia = field_or_theta(s, sig, "field");
      const int ib = field_or_theta(s, ref, "reference_field");
      const Stat stat = parse_stat(s.params());
      const auto span = s.window();
      const double from = span.first, to = span.second;
      return [=, a = sig.name, b = ref.name, step = s.base_step()](const RunLog& log) {
        MetricResult r;
        r.series = error_series(log, a, ia, b, ib, from, to, step);
        r.value = reduce(r.series, stat);
        return r;
      };
    }};

const MetricRegistration kAngleErrorStdDifference{
    "angle_error_std_difference_deg",
    "std of (signal - reference) minus std of (other - reference), deg: < 0 when signal is the better estimate",
    [](const MetricSetup& s) -> MetricFunction {
      const SignalSpec& sig = s.signal("signal");
      const SignalSpec& other = s.signal("other");
      const SignalSpec& ref = s.signal("reference");
      const int ia = field_or_theta(s, sig, "field");
      const int io = field_or_theta(s, other, "field");
      const int ib = field_or_theta(s, ref, "reference_field");
      const auto span = s.window();
      const double from = span.first, to = span.second;
      return [=, a = sig.name, o = other.name, b = ref.name, step = s.base_step()](const RunLog& log) {
        MetricResult r;
        r.value = reduce(error_series(log, a, ia, b, ib, from, to, step), Stat::std_dev) -
                  reduce(error_series(log, o, io, b, ib, from, to, step), Stat::std_dev);
        return r;
      };
    }};

const MetricRegistration kAngleDeg{"angle_deg",
                                   "statistic of one angle field, deg (stat: mean, std, max, min, max_abs, rms, final)",
                                   [](const MetricSetup& s) -> MetricFunction {
                                     const SignalSpec& sig = s.signal("signal");
                                     const int f = s.field(sig, "field");
                                     const Stat stat = parse_stat(s.params());
                                     const auto span = s.window();
                                     const double from = span.first, to = span.second;
                                     return [=, a = sig.name, step = s.base_step()](const RunLog& log) {
                                       const SignalTrace& ta = *log.find(a);
                                       MetricResult r;
                                       for (std::size_t i = 0; i < ta.size(); ++i) {
                                         const double t = log.time(ta.steps[i]);
                                         if (in_window(t, from, to, step)) r.series.emplace_back(t, ta.at(i, f) * kDeg);
                                       }
                                       r.value = reduce(r.series, stat);
                                       return r;
                                     };
                                   }};

}  // namespace
}  // namespace plexus::scenario
