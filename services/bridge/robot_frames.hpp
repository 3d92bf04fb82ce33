// Which frame carries which signal of one robot (plexus/link/protocol.hpp). The bridge (the
// host's end of the link) and the device emulator (the device's end) build the same robot
// section and must agree on this, so both ask here.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "plexus/link/protocol.hpp"
#include "plexus/scenario/scenario.hpp"
#include "plexus/scenario/step_executor.hpp"

namespace plexus::bridge {

struct RobotFrames {
  /// The robot's frame table: its source's own (`source.frames`), or the built-in one.
  std::shared_ptr<const link::FrameTable> table;
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
/// a second robot, an output or a command the table has no frame for, or more than one
/// command; and for a declared table (frame_table()) that cannot be one.
RobotFrames robot_frames(const scenario::Scenario& sc, const scenario::StepExecutor& wiring, const std::string& who);

/// A source's declared frames as a table: throws InputError naming the entry for an id of
/// the link's own (STOP 0x8F, the time exchange 0x0E and 0x8E, the cycle 0x8D), a device -> host id at or
/// above 0x80 or a host -> device id below it, or a payload longer than a frame
/// (`extra_bytes`: the device time, with device_time). Empty: the built-in table.
std::shared_ptr<const link::FrameTable> frame_table(const std::vector<scenario::DeclaredFrame>& frames,
                                                    std::size_t extra_bytes);
/// A signal's topic below its robot: "r1/truth/state" -> "truth/state".
std::string robot_topic(const std::string& signal, const std::string& robot);

}  // namespace plexus::bridge
