// Which frame carries which signal of one robot (plexus/link/protocol.hpp). The bridge (the
// host's end of the link) and the device emulator (the device's end) build the same robot
// section and must agree on this, so both ask here.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "plexus/link/protocol.hpp"
#include "plexus/scenario/scenario.hpp"
#include "plexus/scenario/step_executor.hpp"

namespace plexus::bridge {

struct RobotFrames {
  struct Route {
    std::size_t signal = 0;  ///< index in the wiring's signals
    const link::MessageLayout* layout = nullptr;
  };
  std::string robot;
  std::vector<Route> outputs;    ///< every output of the plant and sensors: device -> host frames
  std::optional<Route> command;  ///< the plant's command: a host -> device frame (none if it reads none)
};

/// The frames of the scenario's one robot. `who` names the program in errors ("a bridge").
/// Throws InputError naming the component for a component that is not a plant or a sensor,
/// a second robot, an output or a command the protocol has no frame for, or more than one
/// command.
RobotFrames robot_frames(const scenario::Scenario& sc, const scenario::StepExecutor& wiring, const std::string& who);

/// A signal's topic below its robot: "r1/truth/state" -> "truth/state".
std::string robot_topic(const std::string& signal, const std::string& robot);

}  // namespace plexus::bridge
