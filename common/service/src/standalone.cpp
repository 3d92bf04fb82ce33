#include "plexus/service/standalone.hpp"

#include <cmath>
#include <utility>

#include "plexus/base/input_error.hpp"
#include "plexus/base/yaml_reader.hpp"
#include "plexus/scenario/overrides.hpp"

namespace plexus::scenario {

Scenario load_standalone(const StandaloneSpec& s, const std::vector<std::string>& sets, bool realtime) {
  YAML::Node params = s.params_file.empty() ? YAML::Node(YAML::NodeType::Map) : load_yaml_file(s.params_file);
  const std::string origin = s.params_file.empty() ? s.program + " (command line)" : s.params_file;
  if (!params.IsMap()) throw InputError(origin + ": expected a map of parameters");
  YAML::Node root(YAML::NodeType::Map);
  root["name"] = s.robot_section ? s.program : s.name;
  root["clock"]["mode"] = realtime ? "realtime" : "lockstep";
  std::string prefix;
  double step = s.step;
  if (s.robot_section) {
    if (s.extra && s.extra.IsMap())
      for (const auto& kv : s.extra) params[kv.first.as<std::string>()] = kv.second;
    // Its base step: --step, else the params file's `step:` (a robot's file carries the rate its
    // sensors are published at, docs/topics.md), else 0.01 s (100 Hz, the unicycles' rate).
    if (const YAML::Node own = params["step"]) {
      const double v = own.IsScalar() ? own.as<double>(0.0) : 0.0;
      if (!(v > 0.0 && v <= 1.0) || !std::isfinite(v))
        throw InputError(origin + ":" + std::to_string(own.Mark().line + 1) + ": step: must be a number in (0, 1] s");
      if (step <= 0.0) step = v;
      params.remove("step");
    }
    root["robots"][s.robot] = params;
    prefix = "robots." + s.robot + ".";
    if (step <= 0.0) step = 0.01;
  } else {
    if (!params["type"] && !s.type.empty()) params["type"] = s.type;
    if (!params["robot"]) params["robot"] = s.robot;
    root["services"][s.name] = params;
    prefix = "services." + s.name + ".";
  }
  std::vector<Override> overrides;
  for (const auto& a : sets) overrides.push_back(parse_override(prefix + a));  // --set L=0.6: its own key
  if (step <= 0.0) {
    // One base step per period of its own rate (after --set), unless given; a bad rate is
    // left to the loader, which names it.
    YAML::Node probe = YAML::Clone(root);
    apply_overrides(probe, overrides);
    const YAML::Node rate = probe["services"][s.name]["rate"];
    const double hz = rate && rate.IsScalar() ? rate.as<double>(0.0) : 0.0;
    step = hz > 0.0 && std::isfinite(hz) ? 1.0 / hz : 0.01;
  }
  root["step"] = step;
  YAML::Node inputs(YAML::NodeType::Map);
  for (const auto& in : s.input_rates) {
    const auto eq = in.find('=');
    if (eq == std::string::npos || eq == 0) throw InputError("--input-rate " + in + ": expected PORT=HZ");
    const std::string port = in.substr(0, eq);
    inputs[port.find('/') == std::string::npos ? s.robot + "/" + port : port]["rate"] = in.substr(eq + 1);
  }
  // The robot's command at its default rate, unless --input-rate gave it (as cmd or r1/cmd).
  const std::string command = s.robot + "/cmd";
  if (s.robot_section && s.command_rate_hz > 0.0 && !std::as_const(inputs)[command])
    inputs[command]["rate"] = s.command_rate_hz;
  if (inputs.size() > 0) root["inputs"] = inputs;
  return load_scenario_tree(root, origin, overrides, {.partial = true});
}

}  // namespace plexus::scenario
