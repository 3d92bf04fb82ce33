// The Foxglove WebSocket protocol, subprotocol foxglove.websocket.v1
// (github.com/foxglove/ws-protocol, docs/spec.md): the server's messages as JSON text or
// binary frames, and the client's messages parsed and checked. No sockets here.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "plexus/msg/type_support.hpp"

namespace plexus::foxglove {

inline constexpr char kSubprotocol[] = "foxglove.websocket.v1";

/// One advertised channel: a typed topic on the domain, its omgidl schema, cdr encoding
/// (the same schema and encoding as plexus's MCAP channels).
struct Channel {
  uint32_t id = 0;
  std::string topic;
  const msg::TypeSupport* type = nullptr;
};

std::string server_info(const std::string& name, const std::string& session_id);
std::string advertise(const std::vector<Channel>& channels);
std::string unadvertise(const std::vector<uint32_t>& channel_ids);
/// level: 0 info, 1 warning, 2 error.
std::string status(int level, const std::string& message);

/// Message Data (opcode 1): subscription id, receive time (ns), the CDR as received.
void message_data(std::vector<unsigned char>& out, uint32_t subscription_id, uint64_t receive_time_ns,
                  const unsigned char* payload, std::size_t size);
/// Time (opcode 2): the server's time (ns, wall clock).
std::vector<unsigned char> time_frame(uint64_t now_ns);

/// A client's text message, checked: subscribe (id -> channel id pairs) or unsubscribe
/// (ids). Anything else is `unknown` with a reason for a status message.
struct ClientMessage {
  enum class Op { subscribe, unsubscribe, unknown };
  Op op = Op::unknown;
  std::vector<std::pair<uint32_t, uint32_t>> subscriptions;  ///< subscribe: (subscription id, channel id)
  std::vector<uint32_t> unsubscriptions;                     ///< unsubscribe: subscription ids
  std::string error;                                         ///< unknown: why
};
ClientMessage parse_client_message(std::string_view text);

}  // namespace plexus::foxglove
