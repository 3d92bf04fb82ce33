// Metrics: numbers computed from the recorded signals of a run, by registered type.
//
// A scenario lists its metrics:
//
//   metrics:
//     - {name: final_error_m, type: error_final, signal: r1/truth/state, reference: r1/reference}
//     - {name: steady_max_error_m, type: error_max, signal: r1/truth/state, reference: r1/reference, from: 100}
//
// `name` is what metrics.json and expectations call it (default: the type); the other
// keys are the type's parameters. A family adds a metric type in one file under
// common/scenario/src/metrics/ with one static registration:
//
//   const plexus::scenario::MetricRegistration kDecay{
//       "observer_decay_rate", "fitted exponential decay rate of a signal field, 1/s",
//       [](const plexus::scenario::MetricSetup& s) -> plexus::scenario::MetricFunction {
//         const auto& sig = s.signal("signal");              // validated signal name
//         const int f = s.field(sig, "field");               // validated field name
//         return [name = sig.name, f](const plexus::scenario::RunLog& log) {
//           plexus::scenario::MetricResult r; /* ... */ return r; };
//       }};
//
// The factory validates its parameters at load time (so a bad metric is exit 2 before
// the run), and returns the function that computes the value after the run.
#pragma once

#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "plexus/base/yaml_reader.hpp"
#include "plexus/scenario/signal_log.hpp"

namespace plexus::scenario {

/// A metric's value, and optionally the time series it summarises (plotted by `plexus report`).
struct MetricResult {
  double value = std::numeric_limits<double>::quiet_NaN();
  std::vector<std::pair<double, double>> series;  ///< (t, value); empty if none
};

using MetricFunction = std::function<MetricResult(const RunLog&)>;

/// What a metric factory gets: its YAML entry and the signals of the scenario.
class MetricSetup {
 public:
  MetricSetup(const YamlMap& entry, const std::vector<SignalSpec>& signals, double base_step, double duration)
      : entry_(entry), signals_(signals), base_step_(base_step), duration_(duration) {}

  /// The metric's YAML entry: read your parameters here; unread keys are rejected.
  const YamlMap& params() const { return entry_; }
  /// The signal named by required key `key`; unknown signal names are an error.
  const SignalSpec& signal(const std::string& key) const;
  /// Index of the field named by required key `key` in `spec`.
  int field(const SignalSpec& spec, const std::string& key) const;
  /// The field names listed by optional key `key` (a list), or `fallback` when the key is
  /// absent; each must be a field of every spec given.
  std::vector<std::string> fields(const std::vector<const SignalSpec*>& specs, const std::string& key,
                                  const std::vector<std::string>& fallback) const;
  /// Optional time window [from, to] in seconds (keys `from`, default 0, and `to`,
  /// default the duration), validated to lie in [0, duration] with from <= to. (Read it into
  /// two variables, not a structured binding, where a lambda captures them: clang 14, which
  /// builds the fuzz targets, cannot capture a structured binding.)
  std::pair<double, double> window() const;

  /// The scenario's signals (a composite metric builds its parts' setups from them).
  const std::vector<SignalSpec>& signals() const { return signals_; }
  double base_step() const { return base_step_; }
  double duration() const { return duration_; }

 private:
  const YamlMap& entry_;
  const std::vector<SignalSpec>& signals_;
  double base_step_;
  double duration_;
};

using MetricFactory = std::function<MetricFunction(const MetricSetup&)>;

struct MetricType {
  std::string name;
  std::string summary;
  MetricFactory factory;
};

/// Registers a metric type at static-initialisation time (duplicate names abort at start-up).
struct MetricRegistration {
  MetricRegistration(std::string name, std::string summary, MetricFactory factory);
};

/// The registered metric type, or nullptr.
const MetricType* find_metric_type(const std::string& name);
/// All registered metric types, sorted by name.
std::vector<const MetricType*> metric_types();

}  // namespace plexus::scenario
