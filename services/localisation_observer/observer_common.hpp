// What both heading observers of localisation_observer share (papers 000 and 003;
// docs/algorithms/unicycle.md): the `discretisation` key, the clock of new position
// samples and the heading made continuous in time.
#pragma once

#include <cstdint>

#include "plexus/algorithms/core/angles.hpp"
#include "plexus/algorithms/unicycle/heading_observer.hpp"
#include "plexus/base/yaml_reader.hpp"
#include "plexus/scenario/component.hpp"

namespace plexus::scenario {

/// `discretisation`: exact_arc (default) | held_position.
algorithms::ObserverDiscretisation discretisation(const YamlMap& p);

/// A heading estimate made continuous in time (like the plant's theta): each new value is
/// the previous one plus the wrapped change; the first is atan2's value in (-pi, pi].
struct ContinuousHeading {
  double value = 0.0;
  bool started = false;
  double operator()(double wrapped) {
    value = started ? value + algorithms::wrap_angle(wrapped - value) : wrapped;
    started = true;
    return value;
  }
};

/// New position sample since the last update? Tracks the producer's step.
struct SampleClock {
  int64_t last = -1;
  /// Seconds since the previous sample (0 for the first), or < 0 when nothing new.
  double advance(const InputPort& in, double base_step) {
    const int64_t s = in.sample().step;
    if (s < 0 || s == last) return -1.0;
    const double dt = last < 0 ? 0.0 : static_cast<double>(s - last) * base_step;
    last = s;
    return dt;
  }
};

}  // namespace plexus::scenario
