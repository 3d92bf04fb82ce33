#include "ws_protocol.hpp"

namespace plexus::foxglove {
namespace {

void put_le(std::vector<unsigned char>& out, uint64_t v, int bytes) {
  for (int i = 0; i < bytes; ++i) out.push_back(static_cast<unsigned char>(v >> (8 * i)));
}

bool as_u32(const nlohmann::json& j, uint32_t& out) {
  if (!j.is_number_integer() && !j.is_number_unsigned()) return false;
  const int64_t v = j.get<int64_t>();
  if (v < 0 || v > static_cast<int64_t>(UINT32_MAX)) return false;
  out = static_cast<uint32_t>(v);
  return true;
}

}  // namespace

std::string server_info(const std::string& name, const std::string& session_id) {
  return nlohmann::json{{"op", "serverInfo"},
                        {"name", name},
                        {"capabilities", {"time"}},
                        {"metadata", nlohmann::json::object()},
                        {"sessionId", session_id}}
      .dump();
}

std::string advertise(const std::vector<Channel>& channels) {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& c : channels)
    list.push_back({{"id", c.id},
                    {"topic", c.topic},
                    {"encoding", "cdr"},
                    {"schemaName", c.type->type_name},
                    {"schema", c.type->schema},
                    {"schemaEncoding", "omgidl"}});
  return nlohmann::json{{"op", "advertise"}, {"channels", list}}.dump();
}

std::string unadvertise(const std::vector<uint32_t>& channel_ids) {
  return nlohmann::json{{"op", "unadvertise"}, {"channelIds", channel_ids}}.dump();
}

std::string status(int level, const std::string& message) {
  return nlohmann::json{{"op", "status"}, {"level", level}, {"message", message}}.dump(
      -1, ' ', false, nlohmann::json::error_handler_t::replace);
}

void message_data(std::vector<unsigned char>& out, uint32_t subscription_id, uint64_t receive_time_ns,
                  const unsigned char* payload, std::size_t size) {
  out.clear();
  out.reserve(13 + size);
  out.push_back(0x01);
  put_le(out, subscription_id, 4);
  put_le(out, receive_time_ns, 8);
  out.insert(out.end(), payload, payload + size);
}

std::vector<unsigned char> time_frame(uint64_t now_ns) {
  std::vector<unsigned char> out{0x02};
  put_le(out, now_ns, 8);
  return out;
}

ClientMessage parse_client_message(std::string_view text) {
  ClientMessage m;
  const auto j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object()) {
    m.error = "not a JSON object";
    return m;
  }
  const auto op = j.find("op");
  if (op == j.end() || !op->is_string()) {
    m.error = "no \"op\"";
    return m;
  }
  if (*op == "subscribe") {
    const auto subs = j.find("subscriptions");
    if (subs == j.end() || !subs->is_array()) {
      m.error = "subscribe: no \"subscriptions\" array";
      return m;
    }
    for (const auto& s : *subs) {
      uint32_t id = 0, channel = 0;
      if (!s.is_object() || !s.contains("id") || !s.contains("channelId") || !as_u32(s["id"], id) ||
          !as_u32(s["channelId"], channel)) {
        m.error = "subscribe: each subscription needs an \"id\" and a \"channelId\" (unsigned 32-bit)";
        return m;
      }
      m.subscriptions.emplace_back(id, channel);
    }
    m.op = ClientMessage::Op::subscribe;
    return m;
  }
  if (*op == "unsubscribe") {
    const auto ids = j.find("subscriptionIds");
    if (ids == j.end() || !ids->is_array()) {
      m.error = "unsubscribe: no \"subscriptionIds\" array";
      return m;
    }
    for (const auto& s : *ids) {
      uint32_t id = 0;
      if (!as_u32(s, id)) {
        m.error = "unsubscribe: subscription ids are unsigned 32-bit numbers";
        return m;
      }
      m.unsubscriptions.push_back(id);
    }
    m.op = ClientMessage::Op::unsubscribe;
    return m;
  }
  m.error = "op '" + op->get<std::string>() + "' is not supported by this server";
  return m;
}

}  // namespace plexus::foxglove
