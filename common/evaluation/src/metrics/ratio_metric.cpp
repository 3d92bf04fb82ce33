// ratio: one metric of a run divided by another of the same run, so that two controllers
// or estimators run side by side are compared under the same reference, noise and seed
// (e.g. paper 004 Table 4, CT+PD's tracking error over VDC's: arm_table4.yaml).
//
//   numerator, denominator   each a metric entry of its own: `type` and that type's keys
//                            (no `name`), validated as if it were listed under `metrics`
//
//   - {name: rms_ratio_ctpd_vdc, type: ratio,
//      numerator:   {type: tracking_rms, signal: ctpd/truth/state, reference: ctpd/reference, fields: [q1, q2]},
//      denominator: {type: tracking_rms, signal: vdc/truth/state, reference: vdc/reference, fields: [q1, q2]}}
//
// The value is NaN when the denominator is 0 or either part is NaN. No series.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "plexus/scenario/metric.hpp"

namespace plexus::scenario {
namespace {

MetricFunction part(const MetricSetup& s, const std::string& key) {
  if (!s.params().has(key)) s.params().fail(key, "required: a metric entry ({type: ..., ...})");
  const YamlMap entry = s.params().map(key);
  const auto type_name = entry.required<std::string>("type");
  if (type_name == "ratio") entry.fail("type", "a ratio's parts cannot be ratios");
  const MetricType* type = find_metric_type(type_name);
  if (!type) entry.fail("type", "unknown metric type '" + type_name + "'");
  const MetricSetup setup(entry, s.signals(), s.base_step(), s.duration());
  MetricFunction f = type->factory(setup);
  entry.reject_unknown();
  return f;
}

const MetricRegistration kRatio{"ratio",
                                "one metric of the run divided by another (numerator, denominator: metric entries)",
                                [](const MetricSetup& s) -> MetricFunction {
                                  MetricFunction num = part(s, "numerator");
                                  MetricFunction den = part(s, "denominator");
                                  return [num = std::move(num), den = std::move(den)](const RunLog& log) {
                                    MetricResult r;
                                    const double a = num(log).value;
                                    const double b = den(log).value;
                                    r.value = b != 0.0 ? a / b : std::numeric_limits<double>::quiet_NaN();
                                    return r;
                                  };
                                }};

}  // namespace
}  // namespace plexus::scenario
