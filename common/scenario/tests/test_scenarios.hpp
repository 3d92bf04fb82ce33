// Scenario texts and helpers shared by the scenario tests.
#pragma once

#include <string>

#include "plexus/base/input_error.hpp"

namespace plexus::scenario::testing {

/// A small valid scenario (line numbers matter to the error tests: keep it stable).
inline const std::string kValid = R"(name: t
duration: 1.0
step: 0.1
seed: 5
robots:
  r1:
    plant:
      type: unicycle
      y0: -1.0
    sensors:
      gps:
        type: measurement
        rate: 5
        fields: [x, y]
        noise_std: 0.1
services:
  driver:
    type: constant_command
    robot: r1
    v: 1.0
    omega: 0.0
metrics:
  - {name: final_x, type: value_final, signal: r1/truth/state, field: x}
expectations:
  final_x: "<= 2"
)";

/// The InputError message of `fn`, or "no error".
template <class F>
std::string error_of(F&& fn) {
  try {
    fn();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace plexus::scenario::testing
