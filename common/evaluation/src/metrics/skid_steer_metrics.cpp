// Metrics of the skid-steer family (paper 001; definitions in docs/algorithms/skid_steer.md).
// `fields` defaults to [y_l, y_r, x_G]; from / to give a window in s (default: the run).
//
//   icr_rise_time        estimate: the largest, over the fields, 10 % -> 90 % rise time of
//     the estimate from its value at the window start p0 to its final value pf (the mean
//     over the last `final_average_s` (1 s) of the window): t90 - t10 with t_x the first
//     time (p - p0) / (pf - p0) >= x (paper 001 section 4.1, after Dorf & Bishop). The
//     window length when a field never rises. Series: the normalised progress of the
//     slowest field.
//   icr_error_final      estimate, truth: the largest absolute error over the fields at the
//     last estimate sample of the window (truth held). Series: largest error vs time.
//   icr_reconvergence_time  estimate, truth, tolerance (0.02 m): for every change of the
//     true fields (a terrain switch) at time s, the time from s until every field is
//     within `tolerance` of the truth and stays so until the next switch (or the end);
//     value: the largest over the switches; a switch that never re-converges counts as
//     the run length (the duration). NaN if the truth never changes. Series: largest error.
//     `switch: N` (1-based) reports the N-th switch only (NaN if there are fewer).
//   icr_reconvergence_rise_time  estimate, truth, fraction (0.9), switch: the paper's own
//     convergence definition (10 % -> 90 % of the step, section 4.1) applied to a terrain
//     switch and counted from the switch: for every switch, the time until each field's
//     estimate first covers `fraction` of its true step (new - old truth; fields that do
//     not change are skipped); the slowest field; the largest over the switches; the run
//     length if a field never gets there. Series: (switch time, its value).
//   classification_accuracy  classifier (fields class, windows), truth (field terrain),
//     window_s (1.0): over the classifier's decisions in the window (a new `windows`
//     count), the fraction whose class equals the true terrain, counting only decisions
//     whose whole window (t - window_s, t] lay on one terrain. Series: 1 correct / 0 wrong.
//   odometry_error_ratio  signal, other, reference (fields x, y): the position error of
//     `signal` against `reference` at the end of the window divided by that of `other`
//     (< 1 when `signal` is the better dead reckoning; paper 001 section 4.2 compares the
//     odometry of the AKF with the EKF's and the no-slip model's, Fig. 7). Series: the ratio.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "plexus/scenario/metric.hpp"
#include "trace_window.hpp"

namespace plexus::scenario {
namespace {

using metric_detail::Held;
using metric_detail::in_window;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Named fields of one signal, validated at load time.
struct Columns {
  std::string signal;
  std::vector<std::size_t> index;
};

Columns columns(const MetricSetup& s, const std::string& key, const std::vector<std::string>& names) {
  const SignalSpec& sig = s.signal(key);
  Columns c{sig.name, {}};
  for (const auto& f : s.fields({&sig}, "fields", names)) {
    c.index.push_back(
        static_cast<std::size_t>(std::find(sig.fields.begin(), sig.fields.end(), f) - sig.fields.begin()));
  }
  return c;
}

Columns columns_of(const MetricSetup& s, const std::string& key, const std::vector<std::string>& names) {
  const SignalSpec& sig = s.signal(key);
  Columns c{sig.name, {}};
  for (const auto& f : names) {
    const auto it = std::find(sig.fields.begin(), sig.fields.end(), f);
    if (it == sig.fields.end()) s.params().fail(key, "signal '" + sig.name + "' has no field '" + f + "'");
    c.index.push_back(static_cast<std::size_t>(it - sig.fields.begin()));
  }
  return c;
}

const std::vector<std::string> kIcrFields = {"y_l", "y_r", "x_G"};

/// Rows of `trace` at or before increasing steps.
/// (t, largest |estimate - truth| over the fields, truth values) at every estimate sample in the window.
struct ErrorSample {
  double t;
  double error;
  std::vector<double> truth;
  std::vector<double> estimate;
};

std::vector<ErrorSample> errors(const RunLog& log, const Columns& est, const Columns& tru, double from, double to) {
  const SignalTrace& e = *log.find(est.signal);
  Held truth{log.find(tru.signal)};
  std::vector<ErrorSample> out;
  for (std::size_t i = 0; i < e.size(); ++i) {
    const double t = log.time(e.steps[i]);
    const long r = truth.row(e.steps[i]);
    if (r < 0 || !in_window(t, from, to, log.base_step)) continue;
    ErrorSample s{t, 0.0, {}, {}};
    for (std::size_t f = 0; f < est.index.size(); ++f) {
      const double tv = truth.trace->at(static_cast<std::size_t>(r), tru.index[f]);
      s.truth.push_back(tv);
      s.estimate.push_back(e.at(i, est.index[f]));
      s.error = std::max(s.error, std::abs(e.at(i, est.index[f]) - tv));
    }
    out.push_back(std::move(s));
  }
  return out;
}

const MetricRegistration kRiseTime{"icr_rise_time",
                                   "largest 10%->90% rise time of the ICR estimates towards their final values, s",
                                   [](const MetricSetup& s) -> MetricFunction {
                                     const Columns est = columns(s, "estimate", kIcrFields);
                                     const auto span = s.window();
                                     const double from = span.first, to = span.second;
                                     const double avg = s.params().optional<double>("final_average_s", 1.0);
                                     if (!(avg > 0.0) || avg > to - from)
                                       s.params().fail("final_average_s", "must be > 0 and fit in the window");
                                     return [=](const RunLog& log) {
                                       const SignalTrace& e = *log.find(est.signal);
                                       std::vector<std::size_t> rows;
                                       for (std::size_t i = 0; i < e.size(); ++i) {
                                         if (in_window(log.time(e.steps[i]), from, to, log.base_step))
                                           rows.push_back(i);
                                       }
                                       MetricResult r;
                                       if (rows.size() < 2) return r;
                                       double worst = -1.0;
                                       for (std::size_t f : est.index) {
                                         const double p0 = e.at(rows.front(), f);
                                         double pf = 0.0;
                                         int n = 0;
                                         for (std::size_t i : rows) {
                                           if (log.time(e.steps[i]) >= to - avg) pf += e.at(i, f), ++n;
                                         }
                                         pf /= n;
                                         double t10 = kNaN, t90 = kNaN;
                                         std::vector<std::pair<double, double>> progress;
                                         for (std::size_t i : rows) {
                                           const double t = log.time(e.steps[i]);
                                           const double x = pf == p0 ? 1.0 : (e.at(i, f) - p0) / (pf - p0);
                                           progress.emplace_back(t, x);
                                           if (std::isnan(t10) && x >= 0.1) t10 = t;
                                           if (std::isnan(t90) && x >= 0.9) t90 = t;
                                         }
                                         const double rise = std::isnan(t90) || std::isnan(t10) ? to - from : t90 - t10;
                                         if (rise > worst) {
                                           worst = rise;
                                           r.series = std::move(progress);
                                         }
                                       }
                                       r.value = worst;
                                       return r;
                                     };
                                   }};

const MetricRegistration kIcrErrorFinal{"icr_error_final",
                                        "largest absolute ICR estimate error at the end of the window, m",
                                        [](const MetricSetup& s) -> MetricFunction {
                                          const Columns est = columns(s, "estimate", kIcrFields);
                                          const Columns tru = columns(s, "truth", kIcrFields);
                                          const auto span = s.window();
                                          const double from = span.first, to = span.second;
                                          return [=](const RunLog& log) {
                                            MetricResult r;
                                            for (const ErrorSample& e : errors(log, est, tru, from, to))
                                              r.series.emplace_back(e.t, e.error);
                                            if (!r.series.empty()) r.value = r.series.back().second;
                                            return r;
                                          };
                                        }};

/// One change of the truth (a terrain switch): samples [begin, end) lie on the new truth;
/// the switch happened between samples begin - 1 and begin, at t = samples[begin - 1].t.
struct Switch {
  std::size_t begin, end;
  double t;
};

std::vector<Switch> switches(const std::vector<ErrorSample>& samples) {
  std::vector<Switch> out;
  for (std::size_t i = 1; i < samples.size(); ++i) {
    if (samples[i].truth == samples[i - 1].truth) continue;
    if (!out.empty()) out.back().end = i;
    out.push_back({i, samples.size(), samples[i - 1].t});
  }
  return out;
}

/// `switch` (optional, 1-based): report that switch only; default 0 = the largest over all.
int switch_choice(const MetricSetup& s) {
  const int k = s.params().optional<int>("switch", 0);
  if (k < 0) s.params().fail("switch", "must be >= 1 (or 0: the largest over the switches)");
  return k;
}

/// The chosen switch's value, or the largest; NaN without switches or past the last one.
double pick(const std::vector<double>& per_switch, int choice) {
  if (choice > 0) return static_cast<std::size_t>(choice) <= per_switch.size() ? per_switch[choice - 1] : kNaN;
  if (per_switch.empty()) return kNaN;
  return *std::max_element(per_switch.begin(), per_switch.end());
}

const MetricRegistration kReconvergence{
    "icr_reconvergence_time",
    "largest time from a terrain switch until the ICR estimates stay within tolerance of the truth, s",
    [](const MetricSetup& s) -> MetricFunction {
      const Columns est = columns(s, "estimate", kIcrFields);
      const Columns tru = columns(s, "truth", kIcrFields);
      const auto span = s.window();
      const double from = span.first, to = span.second;
      const double tol = s.params().optional<double>("tolerance", 0.02);
      if (!(tol > 0.0)) s.params().fail("tolerance", "must be > 0");
      const int choice = switch_choice(s);
      const double duration = s.duration();
      return [=](const RunLog& log) {
        const std::vector<ErrorSample> samples = errors(log, est, tru, from, to);
        MetricResult r;
        for (const ErrorSample& e : samples) r.series.emplace_back(e.t, e.error);
        std::vector<double> times;
        for (const Switch& w : switches(samples)) {
          // Last sample of the segment outside the tolerance; converged right after it.
          std::size_t settled = w.begin;
          for (std::size_t i = w.begin; i < w.end; ++i) {
            if (!(samples[i].error <= tol)) settled = i + 1;
          }
          times.push_back(settled >= w.end ? duration : samples[settled].t - w.t);
        }
        r.value = pick(times, choice);
        return r;
      };
    }};

const MetricRegistration kReconvergenceRise{
    "icr_reconvergence_rise_time",
    "largest time from a terrain switch until every ICR estimate first covers 90 % of its step, s",
    [](const MetricSetup& s) -> MetricFunction {
      const Columns est = columns(s, "estimate", kIcrFields);
      const Columns tru = columns(s, "truth", kIcrFields);
      const auto span = s.window();
      const double from = span.first, to = span.second;
      const double fraction = s.params().optional<double>("fraction", 0.9);
      if (!(fraction > 0.0 && fraction <= 1.0)) s.params().fail("fraction", "must be in (0, 1]");
      const int choice = switch_choice(s);
      const double duration = s.duration();
      return [=](const RunLog& log) {
        const std::vector<ErrorSample> samples = errors(log, est, tru, from, to);
        MetricResult r;
        std::vector<double> times;
        for (const Switch& w : switches(samples)) {
          const std::vector<double>& before = samples[w.begin - 1].truth;
          const std::vector<double>& after = samples[w.begin].truth;
          double slowest = 0.0;
          for (std::size_t f = 0; f < after.size(); ++f) {
            const double step = after[f] - before[f];
            if (step == 0.0) continue;  // this field did not change
            double reached = duration;
            for (std::size_t i = w.begin; i < w.end; ++i) {
              if ((samples[i].estimate[f] - before[f]) / step >= fraction) {
                reached = samples[i].t - w.t;
                break;
              }
            }
            slowest = std::max(slowest, reached);
          }
          times.push_back(slowest);
          r.series.emplace_back(w.t, slowest);
        }
        r.value = pick(times, choice);
        return r;
      };
    }};

const MetricRegistration kAccuracy{
    "classification_accuracy", "fraction of classifier windows (on one terrain) whose class is the true terrain",
    [](const MetricSetup& s) -> MetricFunction {
      const Columns cls = columns_of(s, "classifier", {"class", "windows"});
      const Columns tru = columns_of(s, "truth", {"terrain"});
      const auto span = s.window();
      const double from = span.first, to = span.second;
      const double window = s.params().optional<double>("window_s", 1.0);
      if (!(window > 0.0)) s.params().fail("window_s", "must be > 0 s");
      return [=](const RunLog& log) {
        const SignalTrace& c = *log.find(cls.signal);
        const SignalTrace& t = *log.find(tru.signal);
        MetricResult r;
        double last_count = 0.0;
        long counted = 0, correct = 0;
        for (std::size_t i = 0; i < c.size(); ++i) {
          const double count = c.at(i, cls.index[1]);
          if (count == last_count) continue;
          last_count = count;
          const double ti = log.time(c.steps[i]);
          if (!in_window(ti, from, to, log.base_step)) continue;
          // True terrain over (ti - window, ti]: every truth sample in it, plus the one held at its start.
          double terrain = kNaN;
          bool uniform = true;
          for (std::size_t j = 0; j < t.size(); ++j) {
            const double tj = log.time(t.steps[j]);
            const bool held_at_start =
                tj <= ti - window && (j + 1 == t.size() || log.time(t.steps[j + 1]) > ti - window);
            if (tj > ti + 1e-9 * log.base_step || (!held_at_start && tj <= ti - window)) continue;
            const double v = t.at(j, tru.index[0]);
            if (std::isnan(terrain)) terrain = v;
            uniform = uniform && v == terrain;
          }
          if (!uniform || std::isnan(terrain)) continue;
          const bool ok = std::lround(c.at(i, cls.index[0])) == std::lround(terrain);
          ++counted;
          correct += ok ? 1 : 0;
          r.series.emplace_back(ti, ok ? 1.0 : 0.0);
        }
        if (counted > 0) r.value = static_cast<double>(correct) / static_cast<double>(counted);
        return r;
      };
    }};

/// |(x, y) of `signal` - (x, y) of `reference` (held)| at each sample of `signal` in the window.
std::vector<std::pair<double, double>> position_errors(const RunLog& log, const Columns& sig, const Columns& ref,
                                                       double from, double to) {
  const SignalTrace& a = *log.find(sig.signal);
  Held reference{log.find(ref.signal)};
  std::vector<std::pair<double, double>> out;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double t = log.time(a.steps[i]);
    const long r = reference.row(a.steps[i]);
    if (r < 0 || !in_window(t, from, to, log.base_step)) continue;
    const auto row = static_cast<std::size_t>(r);
    out.emplace_back(t, std::hypot(a.at(i, sig.index[0]) - reference.trace->at(row, ref.index[0]),
                                   a.at(i, sig.index[1]) - reference.trace->at(row, ref.index[1])));
  }
  return out;
}

const MetricRegistration kOdometryRatio{
    "odometry_error_ratio",
    "final position error of one dead reckoning divided by another's (< 1: the first is better)",
    [](const MetricSetup& s) -> MetricFunction {
      const Columns sig = columns_of(s, "signal", {"x", "y"});
      const Columns other = columns_of(s, "other", {"x", "y"});
      const Columns ref = columns_of(s, "reference", {"x", "y"});
      const auto span = s.window();
      const double from = span.first, to = span.second;
      return [=](const RunLog& log) {
        const auto a = position_errors(log, sig, ref, from, to);
        const auto b = position_errors(log, other, ref, from, to);
        MetricResult r;
        for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) {
          if (a[i].first == b[i].first && b[i].second > 0.0)
            r.series.emplace_back(a[i].first, a[i].second / b[i].second);
        }
        if (!a.empty() && !b.empty() && b.back().second > 0.0) r.value = a.back().second / b.back().second;
        return r;
      };
    }};

}  // namespace
}  // namespace plexus::scenario
