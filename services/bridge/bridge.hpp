// A hardware bridge: one robot's device on a serial line or UDP, on the robot's typed
// topics (docs/bridges.md).
//
// Data path, device -> DDS (the I/O thread, which alone touches the device):
//   bytes -> FrameDecoder (COBS, CRC, version: bad frames dropped and counted)
//         -> route by frame id, payload length check
//         -> edge check (WireSignal::check: finite, physical range)
//         -> publish on <robot>/<topic>, data and origin time = when the frame arrived, or
//            with device time, the sample's device time mapped to the host's clock
//            (link::DeviceClock, fitted to the time exchanges the I/O thread makes)
// DDS -> device (the command thread waits on the command reader):
//   <robot>/cmd -> edge check (decode) -> deadline check (older than its deadline: not
//   forwarded) -> pipe -> I/O thread -> command frame. While no fresh command is held the
//   I/O thread sends a STOP frame once per command period.
//
// The device may be absent at start (the bridge retries, heartbeat DEGRADED), unplugged
// mid-run (it stops publishing, so downstream inputs go stale and controllers hold; it
// reopens the device and resumes) or send garbage (dropped, counted, never published).
// Counters travel in the heartbeat's `link` (health/<service>, once a second).
#pragma once

#include <atomic>
#include <memory>
#include <string>

#include "device_link.hpp"
#include "plexus/msg/messages.hpp"
#include "plexus/runtime/participant.hpp"
#include "plexus/runtime/qos.hpp"
#include "plexus/scenario/scenario.hpp"

namespace plexus::bridge {

struct BridgeOptions {
  std::string service;          ///< heartbeat and log name
  double link_timeout_s = 0.5;  ///< no valid frame for this long: link down, heartbeat DEGRADED
  double retry_s = 0.5;         ///< between attempts to open an absent device
  bool device_time = false;     ///< the device stamps its samples (docs/bridges.md, "Device time")
  double time_sync_hz = 50.0;   ///< time exchanges per second, with device_time
  /// With device_time: send the run's cycle in the device's clock (docs/bridges.md, "Cycle
  /// sync"). The cycle is the scenario's base step on the run's grid: from the launcher's
  /// start signal with `start_signal`, else on whole wall-clock seconds, as a service started
  /// by hand steps.
  bool cycle_sync = false;
  bool start_signal = false;  ///< started by plexus launch: the grid's origin is its start signal
};

/// What the bridge did, for its exit line.
struct BridgeReport {
  msg::LinkStatus link;
  uint64_t commands_forwarded = 0;  ///< command frames the device took
  uint64_t commands_refused = 0;    ///< edge check
  double run_s = 0;
};

class Bridge {
 public:
  /// Builds the routes (bridge_routes.hpp): throws InputError for a robot the protocol cannot carry.
  Bridge(scenario::Scenario& sc, rt::Participant& participant, const rt::QosProfiles& profiles,
         std::unique_ptr<DeviceLink> link, BridgeOptions options);
  ~Bridge();
  /// Runs until `stop`; then sends a last STOP frame and returns.
  BridgeReport run(const std::atomic<bool>& stop);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace plexus::bridge
