// Did an input get a new sample? For services that update only on a new measurement (the
// terrain windows, the ICR EKF's GPS updates), whatever rate its producer runs at.
#pragma once

#include <cstdint>

#include "plexus/scenario/component.hpp"

namespace plexus::scenario {

/// The producer's step of an input's current sample changed since the last call?
struct NewSample {
  int64_t last = -1;
  bool operator()(const InputPort& in) {
    const int64_t s = in.sample().step;
    if (s < 0 || s == last) return false;
    last = s;
    return true;
  }
};

}  // namespace plexus::scenario
