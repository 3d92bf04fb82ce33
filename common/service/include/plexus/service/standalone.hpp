// What a service started on its own runs: its parameters as the one component of a part
// document, or a robot's plant and sensors (plant_simulator, the bridges, the device
// emulator). The same loader `plexus launch` parts go through (LoadOptions::partial), so a
// hand-started service is checked exactly as a launched one.
#pragma once

#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "plexus/scenario/scenario.hpp"

namespace plexus::scenario {

/// The command rate the plant simulator and the bridges assume on their own (the example
/// controllers' rate); `--input-rate cmd=HZ` overrides it.
inline constexpr double kDefaultCommandRateHz = 100.0;

struct StandaloneSpec {
  std::string program;         ///< the executable, for errors ("plant_simulator")
  bool robot_section = false;  ///< params are a robot section (plant, sensors), not a service's
  std::string robot = "r1";
  std::string name;                      ///< service name (services only)
  std::string type;                      ///< component type when params has none (services only)
  std::string params_file;               ///< YAML; empty: no parameters
  double step = 0.0;                     ///< base step (s); 0: 1 / the service's rate (robots: 0.001)
  std::vector<std::string> input_rates;  ///< PORT=HZ: an input's producer rate
  /// Robot sections: the rate of the robot's command (<robot>/cmd) when input_rates does not
  /// give it; 0: the base step's. The plant simulator and the bridges use
  /// kDefaultCommandRateHz, so that a 1 kHz plant does not take a 100 Hz command for a
  /// stale one 7 ticks in 10 (and apply the zero command meanwhile).
  double command_rate_hz = 0.0;
  /// Robot sections: keys added to the section before loading (a bridge's `source`).
  YAML::Node extra;
};

/// Loads the standalone scenario: clock mode realtime or lockstep, overrides `sets`
/// (key=value of its own section). Throws InputError naming the file and key.
Scenario load_standalone(const StandaloneSpec& spec, const std::vector<std::string>& sets, bool realtime);

}  // namespace plexus::scenario
