// Metrics of the unicycle family (papers 000 and 003; docs/algorithms/unicycle.md).
// Every signal is read at the samples of `estimate` (or `signal`), with the other signals
// held (latest sample at or before); from / to give a window in s (default: the run).
//
//   observer_decay_rate   state (field theta), estimate (fields z3, z4):
//     V_o = |(cos theta - z3, sin theta - z4)|^2 / 2 (paper 000 eq. (9)); value: the fitted
//     exponential rate -d ln V_o / dt (least squares over the window, samples with
//     V_o > 1e-30), 1/s; series: V_o
//   observer_rate_bound   estimate (field L), cmd (field v):
//     2 L v_min with v_min the smallest commanded speed in the window (eq. (10)), 1/s;
//     series: 2 L v(t)
//   observer_decay_ratio  state, estimate, cmd: observer_decay_rate / observer_rate_bound
//     (Theorem 1: >= 1, whatever L, the speeds and the initial heading); series: V_o
//   velocity_observer_error_final   state (theta), cmd (v), estimate (z2, z4):
//     |(v cos theta - z2, v sin theta - z4)| at the end (paper 003 eq. (13)); series: the norm
//   value_norm_final      signal, fields (list): Euclidean norm of the fields at the end
//     of the window (|h| of a path signal with fields [h]); series: the norm
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "plexus/scenario/metric.hpp"
#include "trace_window.hpp"

namespace plexus::scenario {
namespace {

using metric_detail::Held;
using metric_detail::in_window;

struct Field {
  std::string signal;
  std::string field;
};

/// A metric over the samples of `fields[0].signal`: `value(row values)` gives the series,
/// `reduce` the number. Every field is validated at load time.
using SeriesValue = std::function<double(const std::vector<double>&)>;
using Reduce = std::function<double(const std::vector<std::pair<double, double>>&)>;

MetricFunction series_metric(const MetricSetup& s, std::vector<Field> fields, SeriesValue value, Reduce reduce) {
  const auto span = s.window();
  const double from = span.first, to = span.second;
  return [=, step = s.base_step()](const RunLog& log) {
    std::vector<Held> held;
    std::vector<std::size_t> index;
    for (const auto& f : fields) {
      held.push_back({log.find(f.signal)});
      index.push_back(static_cast<std::size_t>(held.back().trace->field_index(f.field)));
    }
    const SignalTrace& base = *held.front().trace;
    std::vector<double> v(fields.size());
    MetricResult r;
    for (std::size_t i = 0; i < base.size(); ++i) {
      const double t = log.time(base.steps[i]);
      bool have = true;
      for (std::size_t f = 0; f < fields.size() && have; ++f) {
        const long row = held[f].row(base.steps[i]);
        have = row >= 0;
        if (have) v[f] = held[f].trace->at(static_cast<std::size_t>(row), index[f]);
      }
      if (have && in_window(t, from, to, step)) r.series.emplace_back(t, value(v));
    }
    r.value = reduce(r.series);
    return r;
  };
}

/// The signal named by `key` with the given fields checked; returns (signal, field) pairs.
std::vector<Field> fields_of(const MetricSetup& s, const std::string& key, const std::vector<std::string>& names) {
  const SignalSpec& sig = s.signal(key);
  std::vector<Field> out;
  for (const auto& f : names) {
    bool found = false;
    for (const auto& g : sig.fields) found = found || g == f;
    if (!found) s.params().fail(key, "signal '" + sig.name + "' has no field '" + f + "'");
    out.push_back({sig.name, f});
  }
  return out;
}

std::vector<Field> operator+(std::vector<Field> a, const std::vector<Field>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

double final_value(const std::vector<std::pair<double, double>>& s) {
  return s.empty() ? std::numeric_limits<double>::quiet_NaN() : s.back().second;
}

/// -slope of the least-squares line through (t, ln V) for V above a floor.
double fitted_decay_rate(const std::vector<std::pair<double, double>>& s) {
  double n = 0, st = 0, sy = 0, stt = 0, sty = 0;
  for (const auto& [t, v] : s) {
    if (!(v > 1e-30)) continue;
    const double y = std::log(v);
    n += 1;
    st += t;
    sy += y;
    stt += t * t;
    sty += t * y;
  }
  const double det = n * stt - st * st;
  if (n < 2 || !(det > 0)) return std::numeric_limits<double>::quiet_NaN();
  return -(n * sty - st * sy) / det;
}

double min_value(const std::vector<std::pair<double, double>>& s) {
  double m = std::numeric_limits<double>::quiet_NaN();
  for (const auto& [t, v] : s) m = std::isnan(m) || v < m ? v : m;
  return m;
}

MetricFunction observer_decay_rate(const MetricSetup& s) {
  // estimate first: the series runs at the estimator's samples.
  return series_metric(
      s, fields_of(s, "estimate", {"z3", "z4"}) + fields_of(s, "state", {"theta"}),
      [](const std::vector<double>& v) {
        const double e3 = std::cos(v[2]) - v[0], e4 = std::sin(v[2]) - v[1];
        return 0.5 * (e3 * e3 + e4 * e4);  // V_o, paper 000 eq. (9)
      },
      fitted_decay_rate);
}

MetricFunction observer_rate_bound(const MetricSetup& s) {
  return series_metric(
      s, fields_of(s, "estimate", {"L"}) + fields_of(s, "cmd", {"v"}),
      [](const std::vector<double>& v) { return 2.0 * v[0] * v[1]; }, min_value);
}

const MetricRegistration kObserverDecayRate{
    "observer_decay_rate", "fitted exponential decay rate of the heading observer's V_o (paper 000 eq. (9)), 1/s",
    observer_decay_rate};

const MetricRegistration kObserverRateBound{
    "observer_rate_bound", "2 L v_min: the heading observer's guaranteed decay rate of V_o (paper 000 eq. (10)), 1/s",
    observer_rate_bound};

const MetricRegistration kObserverDecayRatio{
    "observer_decay_ratio", "observer_decay_rate / observer_rate_bound: Theorem 1 of paper 000 says >= 1",
    [](const MetricSetup& s) -> MetricFunction {
      return [rate = observer_decay_rate(s), bound = observer_rate_bound(s)](const RunLog& log) {
        MetricResult r = rate(log);
        r.value /= bound(log).value;
        return r;
      };
    }};

const MetricRegistration kVelocityObserverError{
    "velocity_observer_error_final",
    "|(v cos theta - z2, v sin theta - z4)| at the end: the velocity observer's error (paper 003 eq. (13))",
    [](const MetricSetup& s) {
      return series_metric(
          s, fields_of(s, "estimate", {"z2", "z4"}) + fields_of(s, "state", {"theta"}) + fields_of(s, "cmd", {"v"}),
          [](const std::vector<double>& v) {
            return std::hypot(v[3] * std::cos(v[2]) - v[0], v[3] * std::sin(v[2]) - v[1]);
          },
          final_value);
    }};

const MetricRegistration kValueNormFinal{
    "value_norm_final", "Euclidean norm of some fields of a signal at the end of the window", [](const MetricSetup& s) {
      const SignalSpec& sig = s.signal("signal");
      std::vector<Field> fields;
      for (const auto& f : s.fields({&sig}, "fields", {})) fields.push_back({sig.name, f});
      if (fields.empty()) s.params().fail("fields", "needs at least one field");
      return series_metric(
          s, fields,
          [](const std::vector<double>& v) {
            double sq = 0;
            for (double x : v) sq += x * x;
            return std::sqrt(sq);
          },
          final_value);
    }};

}  // namespace
}  // namespace plexus::scenario
