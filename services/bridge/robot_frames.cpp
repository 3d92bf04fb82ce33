#include "robot_frames.hpp"

#include "plexus/base/input_error.hpp"

namespace plexus::bridge {
namespace {

std::string where_of(const scenario::Scenario& sc, const std::string& component) {
  for (const auto& c : sc.components)
    if (c.component->name() == component) return c.where;
  return sc.file;
}

std::string no_frame(const scenario::SignalSpec& s) {
  return s.name + " (" + (s.message.empty() ? "no IDL type" : s.message) +
         ") has no frame in the bridge protocol (docs/bridges.md lists the frames)";
}

}  // namespace

std::string robot_topic(const std::string& signal, const std::string& robot) {
  const std::string prefix = robot + "/";
  return signal.compare(0, prefix.size(), prefix) == 0 ? signal.substr(prefix.size()) : signal;
}

RobotFrames robot_frames(const scenario::Scenario& sc, const scenario::StepExecutor& wiring, const std::string& who) {
  RobotFrames f;
  for (const auto& c : sc.components) {
    if (c.kind != scenario::ComponentKind::plant && c.kind != scenario::ComponentKind::sensor)
      throw InputError(c.where + ": " + who + " stands in for one robot's plant and sensors; '" + c.component->name() +
                       "' is a " + scenario::to_string(c.kind));
    const std::string robot = c.component->name().substr(0, c.component->name().find('/'));
    if (!f.robot.empty() && robot != f.robot)
      throw InputError(c.where + ": " + who + " serves one robot (" + f.robot + " and " + robot + " here)");
    f.robot = robot;
  }
  if (f.robot.empty()) throw InputError(sc.file + ": no robot (plant and sensors) for " + who);
  const auto& signals = wiring.signals();
  for (std::size_t s : wiring.local_outputs()) {
    const auto& spec = signals[s];
    const auto* layout = link::find_layout(robot_topic(spec.name, f.robot), spec.message, link::Direction::to_host);
    if (!layout) throw InputError(where_of(sc, spec.producer) + ": " + no_frame(spec));
    f.outputs.push_back({s, layout});
  }
  const auto commands = wiring.remote_inputs();
  if (commands.size() > 1) {
    std::string names;
    for (std::size_t s : commands) names += (names.empty() ? "" : ", ") + signals[s].name;
    throw InputError(sc.file + ": robot " + f.robot + " reads " + std::to_string(commands.size()) + " signals (" +
                     names + ") from other processes; " + who + " takes exactly one command");
  }
  if (commands.size() == 1) {
    const auto& spec = signals[commands.front()];
    const auto* layout = link::find_layout(robot_topic(spec.name, f.robot), spec.message, link::Direction::to_device);
    if (!layout) throw InputError(sc.file + ": robot " + f.robot + ": " + no_frame(spec));
    f.command = RobotFrames::Route{commands.front(), layout};
  }
  return f;
}

}  // namespace plexus::bridge
