// Which frame goes to which topic: the bridge's contract with the rest of plexus.
//
// A bridge stands in for the plant simulator of one robot, so it publishes exactly the
// signals that robot's plant and sensors would (same topics, IDL types and QoS profiles:
// it builds them from the same robot section) and reads the same command. Each signal
// travels on the link as the frame its robot's table (the source's own `frames`, or the
// protocol's built-in table, plexus/link/protocol.hpp) has for its topic and type; a signal
// without one is a configuration error.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "plexus/distributed/wire.hpp"
#include "plexus/link/protocol.hpp"
#include "plexus/runtime/qos.hpp"
#include "plexus/scenario/scenario.hpp"

namespace plexus::bridge {

/// A sensor (or ground-truth) topic fed by one frame id.
struct SensorRoute {
  const link::MessageLayout* layout = nullptr;
  std::unique_ptr<scenario::SignalSpec> spec;  // the layout's fields; the WireSignal points at it
  std::unique_ptr<distributed::WirePublisher> publisher;
  uint64_t published = 0;
};

/// The command topic, forwarded as one frame id.
struct CommandRoute {
  const link::MessageLayout* layout = nullptr;
  std::unique_ptr<scenario::SignalSpec> spec;
  std::unique_ptr<distributed::WireSubscriber> subscriber;
  int64_t period_ns = 0;    ///< the command's producer period
  int64_t deadline_ns = 0;  ///< older than this: not forwarded (clock.input_deadline_periods periods)
};

struct BridgeRoutes {
  std::string robot;
  std::shared_ptr<const link::FrameTable> table;  ///< what the layouts point into
  std::vector<SensorRoute> sensors;
  std::array<int16_t, 256> sensor_by_id{};  ///< frame id -> index in sensors, -1 if none
  CommandRoute command;
};

/// Builds the routes of the scenario's one robot (a part or a standalone robot section).
/// Throws InputError naming the robot section for anything the protocol cannot carry.
BridgeRoutes make_routes(scenario::Scenario& sc, rt::Participant& p, const rt::QosProfiles& profiles);

}  // namespace plexus::bridge
