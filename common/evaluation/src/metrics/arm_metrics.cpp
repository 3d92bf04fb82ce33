// Metrics of the arm family (paper 004, Table 4, eqs. (61)-(62)).
//
//   tracking_rms: signal, reference, fields (list), scale (default 1; 1000 reports mrad),
//     from, to. sqrt(mean over the samples of |e|^2), e = the named fields of `signal` minus
//     the same fields of `reference` (held at or before each sample): eq. (61) for one
//     field, eq. (62) for several. Series: |e| * scale against time.
//   settling_time: signal, reference, field, band (default 1.15e-3, the paper's), from, to.
//     The time from `from` until |e| enters [-band, band] and stays there to the end of the
//     window: the time of the first sample after the last one outside the band (0 if never
//     outside). null if the last sample is still outside. Series: |e| against time.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "plexus/scenario/metric.hpp"

namespace plexus::scenario {
namespace {

/// (t, e) samples of signal minus reference over named fields, inside [from, to].
struct ErrorSeries {
  std::vector<double> t;
  std::vector<std::vector<double>> e;  // per sample, per field
};

ErrorSeries error_series(const RunLog& log, const std::string& a, const std::string& b,
                         const std::vector<std::string>& fields, double from, double to, double step) {
  const SignalTrace& ta = *log.find(a);
  const SignalTrace& tb = *log.find(b);
  std::vector<int> fa, fb;
  for (const auto& f : fields) {
    fa.push_back(ta.field_index(f));
    fb.push_back(tb.field_index(f));
  }
  ErrorSeries out;
  std::size_t j = 0;
  const double eps = 1e-9 * step;
  for (std::size_t i = 0; i < ta.size(); ++i) {
    while (j < tb.size() && tb.steps[j] <= ta.steps[i]) ++j;
    const double t = log.time(ta.steps[i]);
    if (j == 0 || t < from - eps || t > to + eps) continue;
    std::vector<double> e(fields.size());
    for (std::size_t f = 0; f < fields.size(); ++f) e[f] = ta.at(i, fa[f]) - tb.at(j - 1, fb[f]);
    out.t.push_back(t);
    out.e.push_back(std::move(e));
  }
  return out;
}

const MetricRegistration kTrackingRms{
    "tracking_rms", "RMS of the tracking error over named fields (paper 004 eqs. (61)-(62)), times `scale`",
    [](const MetricSetup& s) -> MetricFunction {
      const SignalSpec& sig = s.signal("signal");
      const SignalSpec& ref = s.signal("reference");
      const auto fields = s.fields({&sig, &ref}, "fields", {});
      if (fields.empty()) s.params().fail("fields", "needs at least one field");
      const double scale = s.params().optional<double>("scale", 1.0);
      if (!(scale > 0.0)) s.params().fail("scale", "must be > 0");
      const auto span = s.window();
      const double from = span.first, to = span.second;
      return [=, a = sig.name, b = ref.name, step = s.base_step()](const RunLog& log) {
        const ErrorSeries es = error_series(log, a, b, fields, from, to, step);
        MetricResult r;
        double sum = 0.0;
        for (std::size_t i = 0; i < es.t.size(); ++i) {
          double sq = 0.0;
          for (double v : es.e[i]) sq += v * v;
          sum += sq;
          r.series.emplace_back(es.t[i], scale * std::sqrt(sq));
        }
        if (!es.t.empty()) r.value = scale * std::sqrt(sum / static_cast<double>(es.t.size()));
        return r;
      };
    }};

const MetricRegistration kSettlingTime{
    "settling_time", "time until |signal - reference| enters +-band for good (paper 004 Table 4), s",
    [](const MetricSetup& s) -> MetricFunction {
      const SignalSpec& sig = s.signal("signal");
      const SignalSpec& ref = s.signal("reference");
      const int f = s.field(sig, "field");
      s.field(ref, "field");  // the reference must have the same field
      const std::string field = sig.fields[static_cast<std::size_t>(f)];
      const double band = s.params().optional<double>("band", 1.15e-3);
      if (!(band > 0.0)) s.params().fail("band", "must be > 0");
      const auto span = s.window();
      const double from = span.first, to = span.second;
      return [=, a = sig.name, b = ref.name, step = s.base_step()](const RunLog& log) {
        const ErrorSeries es = error_series(log, a, b, {field}, from, to, step);
        MetricResult r;
        std::size_t first_inside = 0;  // index of the first sample after the last one outside
        for (std::size_t i = 0; i < es.t.size(); ++i) {
          const double e = std::abs(es.e[i][0]);
          r.series.emplace_back(es.t[i], e);
          if (!(e <= band)) first_inside = i + 1;  // outside, or not a number (a diverged run never settles)
        }
        if (es.t.empty() || first_inside >= es.t.size()) return r;  // never settled: null
        r.value = es.t[first_inside] - from;
        return r;
      };
    }};

}  // namespace
}  // namespace plexus::scenario
