// Built-in metrics: the distance between two signals, and statistics of one field.
//
//   error_final | error_max | error_mean | error_rms:
//     signal, reference   signal names; the reference is held (latest sample at or before
//                         each sample of `signal`)
//     fields              compared fields, default [x, y]; distance = Euclidean norm
//     from, to            window in s (t >= from and t <= to), default the whole run
//   value_final | value_max | value_min | value_mean | value_max_abs:
//     signal, field, from, to
#include <cmath>
#include <functional>

#include "plexus/scenario/metric.hpp"
#include "trace_window.hpp"

namespace plexus::scenario {
namespace {

using metric_detail::in_window;

using Reduce = std::function<double(const std::vector<std::pair<double, double>>&)>;

double reduce_final(const std::vector<std::pair<double, double>>& s) { return s.empty() ? NAN : s.back().second; }
double reduce_max(const std::vector<std::pair<double, double>>& s) {
  double m = NAN;
  for (const auto& [t, v] : s) m = std::isnan(m) || v > m ? v : m;
  return m;
}
double reduce_min(const std::vector<std::pair<double, double>>& s) {
  double m = NAN;
  for (const auto& [t, v] : s) m = std::isnan(m) || v < m ? v : m;
  return m;
}
double reduce_mean(const std::vector<std::pair<double, double>>& s) {
  if (s.empty()) return NAN;
  double sum = 0;
  for (const auto& [t, v] : s) sum += v;
  return sum / static_cast<double>(s.size());
}
double reduce_rms(const std::vector<std::pair<double, double>>& s) {
  if (s.empty()) return NAN;
  double sum = 0;
  for (const auto& [t, v] : s) sum += v * v;
  return std::sqrt(sum / static_cast<double>(s.size()));
}
double reduce_max_abs(const std::vector<std::pair<double, double>>& s) {
  double m = NAN;
  for (const auto& [t, v] : s) m = std::isnan(m) || std::abs(v) > m ? std::abs(v) : m;
  return m;
}

MetricFactory error_metric(Reduce reduce) {
  return [reduce](const MetricSetup& s) -> MetricFunction {
    const SignalSpec& sig = s.signal("signal");
    const SignalSpec& ref = s.signal("reference");
    const auto fields = s.fields({&sig, &ref}, "fields", {"x", "y"});
    const auto span = s.window();
    const double from = span.first, to = span.second;
    return [=, a = sig.name, b = ref.name, step = s.base_step()](const RunLog& log) {
      const SignalTrace& ta = *log.find(a);
      const SignalTrace& tb = *log.find(b);
      std::vector<int> fa, fb;
      for (const auto& f : fields) {
        fa.push_back(ta.field_index(f));
        fb.push_back(tb.field_index(f));
      }
      MetricResult r;
      std::size_t j = 0;  // reference row held at or before the current sample
      bool have = false;
      for (std::size_t i = 0; i < ta.size(); ++i) {
        while (j < tb.size() && tb.steps[j] <= ta.steps[i]) {
          have = true;
          ++j;
        }
        const double t = log.time(ta.steps[i]);
        if (!have || !in_window(t, from, to, step)) continue;
        double sq = 0;
        for (std::size_t f = 0; f < fields.size(); ++f) {
          const double d = ta.at(i, fa[f]) - tb.at(j - 1, fb[f]);
          sq += d * d;
        }
        r.series.emplace_back(t, std::sqrt(sq));
      }
      r.value = reduce(r.series);
      return r;
    };
  };
}

MetricFactory value_metric(Reduce reduce) {
  return [reduce](const MetricSetup& s) -> MetricFunction {
    const SignalSpec& sig = s.signal("signal");
    const int field = s.field(sig, "field");
    const auto span = s.window();
    const double from = span.first, to = span.second;
    return [=, a = sig.name, step = s.base_step()](const RunLog& log) {
      const SignalTrace& ta = *log.find(a);
      MetricResult r;
      for (std::size_t i = 0; i < ta.size(); ++i) {
        const double t = log.time(ta.steps[i]);
        if (in_window(t, from, to, step)) r.series.emplace_back(t, ta.at(i, field));
      }
      r.value = reduce(r.series);
      return r;
    };
  };
}

const MetricRegistration kErrorFinal{"error_final", "distance between two signals at the end of the window, m",
                                     error_metric(reduce_final)};
const MetricRegistration kErrorMax{"error_max", "largest distance between two signals in the window",
                                   error_metric(reduce_max)};
const MetricRegistration kErrorMean{"error_mean", "mean distance between two signals in the window",
                                    error_metric(reduce_mean)};
const MetricRegistration kErrorRms{"error_rms", "root-mean-square distance between two signals in the window",
                                   error_metric(reduce_rms)};
const MetricRegistration kValueFinal{"value_final", "a field's last value in the window", value_metric(reduce_final)};
const MetricRegistration kValueMax{"value_max", "a field's largest value in the window", value_metric(reduce_max)};
const MetricRegistration kValueMin{"value_min", "a field's smallest value in the window", value_metric(reduce_min)};
const MetricRegistration kValueMean{"value_mean", "a field's mean value in the window", value_metric(reduce_mean)};
const MetricRegistration kValueMaxAbs{"value_max_abs", "a field's largest absolute value in the window",
                                      value_metric(reduce_max_abs)};

}  // namespace
}  // namespace plexus::scenario
