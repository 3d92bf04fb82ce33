// The bridge protocol's messages against the wire contract, and the routes a robot section
// gives a bridge: every frame names a topic whose IDL type has its fields, a unicycle and a
// balancing robot route completely, a robot the protocol cannot carry is refused by name.
#include <gtest/gtest.h>

#include "bridge_routes.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/distributed/wire.hpp"
#include "plexus/link/frame.hpp"
#include "plexus/link/protocol.hpp"
#include "plexus/scenario/scenario.hpp"

namespace plexus::bridge {
namespace {

constexpr int kDomain = 140;  // tests/bridges: 130..149

TEST(BridgeProtocol, EveryMessageBindsToItsIdlType) {
  for (const auto& l : link::message_layouts()) {
    if (l.id == link::kStopId) {
      EXPECT_TRUE(l.fields.empty());
      continue;
    }
    if (l.id == link::kTimeRequestId || l.id == link::kTimeResponseId) {  // no topic: the link's own
      EXPECT_EQ(l.fields.size(), 3u);
      EXPECT_EQ(*l.topic, '\0');
      continue;
    }
    scenario::SignalSpec spec;
    spec.name = std::string("r1/") + l.topic;
    spec.producer = "test";
    spec.message = l.idl_type;
    spec.fields.assign(l.fields.begin(), l.fields.end());
    EXPECT_NO_THROW(distributed::WireSignal(spec, 1'000'000)) << "frame 0x" << std::hex << int(l.id);
    EXPECT_LE(l.payload_size(), link::kMaxPayload);
  }
}

TEST(BridgeProtocol, IdsAreUniqueAndDirectionsConsistent) {
  std::set<int> ids;
  for (const auto& l : link::message_layouts()) {
    EXPECT_TRUE(ids.insert(l.id).second) << int(l.id);
    EXPECT_EQ(l.direction == link::Direction::to_device, l.id >= 0x80) << int(l.id);
  }
}

scenario::Scenario robot(const std::string& yaml) {
  return scenario::load_scenario_tree(YAML::Load(yaml), "test.yaml", {}, {.partial = true});
}

class Routes : public ::testing::Test {
 protected:
  void SetUp() override {
    rt::ParticipantOptions po;
    po.domain_id = kDomain;
    po.name = "bridge_routes_test";
    participant = rt::Participant::create(po);
  }
  std::unique_ptr<rt::Participant> participant;
  rt::QosProfiles profiles = rt::QosProfiles::load(rt::default_qos_file());
};

TEST_F(Routes, UnicycleRoutesEveryTopic) {
  auto sc = robot(R"(
name: t
step: 0.01
clock: {mode: realtime}
inputs: {r1/cmd: {rate: 50}}
robots:
  r1:
    source: {type: serial_bridge, device: /dev/null}
    plant: {type: unicycle}
    sensors: {position: {type: position_sensor, kind: exact}}
)");
  const BridgeRoutes r = make_routes(sc, *participant, profiles);
  EXPECT_EQ(r.robot, "r1");
  ASSERT_EQ(r.sensors.size(), 2u);
  EXPECT_EQ(r.sensors[static_cast<std::size_t>(r.sensor_by_id[0x11])].spec->name, "r1/truth/state");
  EXPECT_EQ(r.sensors[static_cast<std::size_t>(r.sensor_by_id[0x10])].spec->name, "r1/position");
  EXPECT_EQ(r.sensor_by_id[0x20], -1);
  EXPECT_EQ(r.command.layout->id, 0x80);
  EXPECT_EQ(r.command.period_ns, 20'000'000);    // 50 Hz
  EXPECT_EQ(r.command.deadline_ns, 60'000'000);  // 3 periods
}

TEST_F(Routes, BalancingRobotRoutesEveryTopic) {
  auto sc = robot(R"(
name: t
step: 0.01
clock: {mode: realtime}
robots:
  r1:
    source: {type: udp_bridge, bind: "127.0.0.1:47001", peer: "127.0.0.1:47002"}
    plant: {type: wheeled_inverted_pendulum}
    sensors:
      imu: {type: balancing_imu}
      odometry: {type: wheel_odometry}
)");
  const BridgeRoutes r = make_routes(sc, *participant, profiles);
  EXPECT_EQ(r.sensors.size(), 3u);
  for (int id : {0x20, 0x21, 0x22}) EXPECT_GE(r.sensor_by_id[static_cast<std::size_t>(id)], 0) << id;
  EXPECT_EQ(r.command.layout->id, 0x81);
}

TEST_F(Routes, RefusesASensorTheProtocolCannotCarry) {
  auto sc = robot(R"(
name: t
step: 0.01
clock: {mode: realtime}
robots:
  r1:
    plant: {type: unicycle}
    sensors: {gps: {type: position_sensor, kind: exact}}
)");
  try {
    make_routes(sc, *participant, profiles);
    FAIL() << "a bridge must refuse r1/gps";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("robots.r1.sensors.gps"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("no frame"), std::string::npos) << e.what();
  }
}

TEST(RobotSource, BadSourcesAreRefusedWithTheirKey) {
  const auto bad = [](const std::string& source, const std::string& expect) {
    try {
      robot("name: t\nstep: 0.01\nrobots:\n  r1:\n    source: " + source + "\n    plant: {type: unicycle}\n");
      ADD_FAILURE() << source << " was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(expect), std::string::npos) << e.what();
    }
  };
  bad("serial_bridge", "robots.r1.source");
  bad("{type: teleport}", "robots.r1.source.type");
  bad("{type: serial_bridge}", "device");
  bad("{type: serial_bridge, device: /dev/x, baud: 9600}", "robots.r1.source.baud");
  bad("{type: udp_bridge, bind: 127.0.0.1:1}", "peer");
  bad("{type: serial_bridge, device: /dev/x, colour: red}", "colour");
  bad("{type: serial_bridge, device: /dev/x, retry: -1}", "robots.r1.source.retry");
  bad("{type: udp_bridge, bind: 127.0.0.1:1, peer: 127.0.0.1:2, device_time: true, time_sync_hz: 0.5}",
      "robots.r1.source.time_sync_hz");
  bad("{type: udp_bridge, bind: 127.0.0.1:1, peer: 127.0.0.1:2, time_sync_hz: 20}", "only with device_time");
  bad("{type: serial_bridge, device: /dev/x, device_time: maybe}", "robots.r1.source.device_time");
}

TEST(RobotSource, DeviceTimeIsReadFromTheSource) {
  const auto sc = robot(
      "name: t\nstep: 0.01\nrobots:\n  r1:\n    source: {type: udp_bridge, bind: 127.0.0.1:1, peer: 127.0.0.1:2, "
      "device_time: true, time_sync_hz: 20}\n    plant: {type: unicycle}\n");
  const auto& src = sc.sources.at("r1");
  EXPECT_TRUE(src.device_time);
  EXPECT_EQ(src.time_sync_hz, 20.0);
  const auto plain = robot(
      "name: t\nstep: 0.01\nrobots:\n  r1:\n    source: {type: serial_bridge, device: /dev/x}\n    plant: {type: "
      "unicycle}\n");
  EXPECT_FALSE(plain.sources.at("r1").device_time);
}

}  // namespace
}  // namespace plexus::bridge
