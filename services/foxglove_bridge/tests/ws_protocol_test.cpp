// The Foxglove WebSocket protocol messages: their bytes and fields as docs/spec.md of
// foxglove/ws-protocol gives them, and the client's messages refused with a reason.
#include <gtest/gtest.h>

#include "plexus/msg/messages.hpp"
#include "ws_protocol.hpp"

namespace plexus::foxglove {
namespace {

TEST(WsProtocol, MessageDataIsOpcodeSubscriptionTimeAndPayloadLittleEndian) {
  const unsigned char payload[] = {0x00, 0x01, 0x00, 0x00, 0xAB};
  std::vector<unsigned char> f;
  message_data(f, 0x04030201u, 0x0807060504030201ull, payload, sizeof payload);
  const std::vector<unsigned char> want{0x01, 0x01, 0x02, 0x03, 0x04, 0x01, 0x02, 0x03, 0x04,
                                        0x05, 0x06, 0x07, 0x08, 0x00, 0x01, 0x00, 0x00, 0xAB};
  EXPECT_EQ(f, want);
  const auto t = time_frame(0x0102030405060708ull);
  EXPECT_EQ(t, (std::vector<unsigned char>{0x02, 0x08, 0x07, 0x06, 0x05, 0x04, 0x03, 0x02, 0x01}));
}

TEST(WsProtocol, AdvertiseCarriesTheOmgidlSchemaAndCdr) {
  const auto& ts = msg::type_support<msg::Pose2D>();
  const auto j = nlohmann::json::parse(advertise({Channel{7, "r1/truth/state", &ts}}));
  EXPECT_EQ(j["op"], "advertise");
  ASSERT_EQ(j["channels"].size(), 1u);
  const auto& c = j["channels"][0];
  EXPECT_EQ(c["id"], 7);
  EXPECT_EQ(c["topic"], "r1/truth/state");
  EXPECT_EQ(c["encoding"], "cdr");
  EXPECT_EQ(c["schemaName"], "plexus::msg::Pose2D");
  EXPECT_EQ(c["schemaEncoding"], "omgidl");
  EXPECT_EQ(c["schema"], std::string(ts.schema));
  EXPECT_EQ(nlohmann::json::parse(unadvertise({7, 9}))["channelIds"], nlohmann::json({7, 9}));
  const auto info = nlohmann::json::parse(server_info("x", "s1"));
  EXPECT_EQ(info["op"], "serverInfo");
  EXPECT_EQ(info["capabilities"], nlohmann::json({"time"}));
}

TEST(WsProtocol, ClientMessagesParsed) {
  const auto s =
      parse_client_message(R"({"op":"subscribe","subscriptions":[{"id":0,"channelId":3},{"id":1,"channelId":5}]})");
  ASSERT_EQ(s.op, ClientMessage::Op::subscribe);
  EXPECT_EQ(s.subscriptions, (std::vector<std::pair<uint32_t, uint32_t>>{{0, 3}, {1, 5}}));
  const auto u = parse_client_message(R"({"op":"unsubscribe","subscriptionIds":[0,1]})");
  ASSERT_EQ(u.op, ClientMessage::Op::unsubscribe);
  EXPECT_EQ(u.unsubscriptions, (std::vector<uint32_t>{0, 1}));
}

TEST(WsProtocol, BadClientMessagesRefusedWithAReason) {
  const std::pair<const char*, const char*> cases[] = {
      {"not json", "not a JSON object"},
      {"[1]", "not a JSON object"},
      {R"({"x":1})", "no \"op\""},
      {R"({"op":"subscribe"})", "subscribe: no \"subscriptions\" array"},
      {R"({"op":"subscribe","subscriptions":[{"id":-1,"channelId":1}]})",
       "subscribe: each subscription needs an \"id\" and a \"channelId\" (unsigned 32-bit)"},
      {R"({"op":"subscribe","subscriptions":[{"id":1,"channelId":4294967296}]})",
       "subscribe: each subscription needs an \"id\" and a \"channelId\" (unsigned 32-bit)"},
      {R"({"op":"unsubscribe","subscriptionIds":["a"]})", "unsubscribe: subscription ids are unsigned 32-bit numbers"},
      {R"({"op":"getParameters"})", "op 'getParameters' is not supported by this server"},
  };
  for (const auto& [text, why] : cases) {
    const auto m = parse_client_message(text);
    EXPECT_EQ(m.op, ClientMessage::Op::unknown) << text;
    EXPECT_EQ(m.error, why) << text;
  }
}

}  // namespace
}  // namespace plexus::foxglove
