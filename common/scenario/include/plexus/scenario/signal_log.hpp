// The recorded signals of a run: every sample of every signal, in memory.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "plexus/scenario/signal.hpp"

namespace plexus::scenario {

/// All samples of one signal, in step order.
struct SignalTrace {
  SignalSpec spec;
  std::vector<int64_t> steps;  ///< base step of each sample
  std::vector<double> values;  ///< row-major: spec.fields.size() values per sample

  std::size_t size() const { return steps.size(); }
  std::size_t width() const { return spec.fields.size(); }
  double at(std::size_t row, std::size_t field) const { return values[row * width() + field]; }
  /// Index of a field, or -1.
  int field_index(const std::string& field) const;
};

/// Every signal of a run, in the order their producers were declared.
struct RunLog {
  double base_step = 0.0;  ///< s
  int64_t steps = 0;       ///< number of base steps run after step 0 (the last step is `steps`)
  std::vector<SignalTrace> signals;

  /// Appends a sample of signal `index` (reserve the traces first to stay allocation-free).
  void record(std::size_t index, const SignalSample& sample) {
    auto& trace = signals[index];
    trace.steps.push_back(sample.step);
    trace.values.insert(trace.values.end(), sample.values.begin(),
                        sample.values.begin() + static_cast<std::ptrdiff_t>(trace.width()));
  }

  /// The trace of a signal, or nullptr.
  const SignalTrace* find(const std::string& name) const;
  /// Time of a base step, s.
  double time(int64_t step) const { return static_cast<double>(step) * base_step; }
};

}  // namespace plexus::scenario
