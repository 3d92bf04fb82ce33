// foxglove_bridge's server: the Foxglove WebSocket protocol (ws_protocol.hpp) over websocketpp,
// fed from the DDS domain.
//
// - Every typed topic with a writer on the domain is advertised (ChannelTable), with its
//   omgidl schema and cdr encoding; discovery runs every `discovery_period_s`, so topics and
//   services coming and going are advertised and unadvertised.
// - A channel gets a DDS reader when a client first subscribes to it: best effort, volatile,
//   so it never holds a writer up (a reliable writer does not wait for a best-effort reader).
//   Each sample's CDR as received (ReaderBackend::take_raw) goes out unchanged, stamped with
//   its receive time.
// - A slow client never slows anything: a frame for a client whose socket already holds
//   `max_client_buffer_bytes` unsent is dropped and counted, as is a sample when
//   `max_queued_frames` wait for the I/O thread (which takes them all at each wake-up).
// - The server's time goes out every `time_period_s` (capability "time").
#pragma once

#include <nlohmann/json.hpp>

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>

#include "plexus/runtime/participant.hpp"

namespace plexus::foxglove {

struct BridgeOptions {
  std::string address = "127.0.0.1";
  int port = 8765;
  std::size_t max_client_buffer_bytes = 4u << 20;
  int max_queued_frames = 20000;
  double discovery_period_s = 0.5;
  double time_period_s = 0.1;
  std::string name = "plexus foxglove_bridge";
};

class FoxgloveServer {
 public:
  /// Listens on address:port now: InputError naming them if that fails (a port in use).
  FoxgloveServer(rt::Participant& participant, BridgeOptions options);
  ~FoxgloveServer();
  FoxgloveServer(const FoxgloveServer&) = delete;
  FoxgloveServer& operator=(const FoxgloveServer&) = delete;

  /// Discovery and time on the calling thread until `stop`; then closes every connection.
  void run_until(const std::atomic<bool>& stop);
  /// Counters: clients, channels, frames sent and dropped, latency from the DDS sample's
  /// receive to the WebSocket send (p50/p99/max, us).
  nlohmann::ordered_json stats() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace plexus::foxglove
