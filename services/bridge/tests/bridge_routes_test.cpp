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
#include "plexus/scenario/step_executor.hpp"
#include "robot_frames.hpp"

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
      EXPECT_TRUE(l.topic.empty());
      continue;
    }
    if (link::per_joint(l)) {  // sized for an arm: checked for 1 and 16 joints
      for (std::size_t n : {std::size_t{1}, link::kMaxJoints}) {
        const link::MessageLayout sized = link::for_joints(l, n);
        scenario::SignalSpec spec{std::string("r1/") + l.topic, {}, 1, "test", false, l.idl_type};
        for (const auto& f : sized.fields) spec.fields.push_back(f.name);
        EXPECT_NO_THROW(distributed::WireSignal(spec, 1'000'000)) << "frame 0x" << std::hex << int(l.id) << ", " << n;
        EXPECT_LE(sized.payload_size() + 8, link::kMaxPayload);
      }
      continue;
    }
    scenario::SignalSpec spec;
    spec.name = std::string("r1/") + l.topic;
    spec.producer = "test";
    spec.message = l.idl_type;
    for (const auto& f : l.fields) {
      spec.fields.push_back(f.name);
      EXPECT_EQ(f.kind, link::WireKind::f64) << f.name;  // the built-in table: f64 throughout
    }
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

TEST_F(Routes, SkidSteerRobotRoutesEveryTopic) {
  auto sc = robot(R"(
name: t
step: 0.01
clock: {mode: realtime}
robots:
  r2:
    source: {type: udp_bridge, bind: "127.0.0.1:47001", peer: "127.0.0.1:47002"}
    plant: {type: skid_steer}
    sensors:
      gps: {type: pose_sensor, rate: 20}
      wheels: {type: track_speed_sensor}
      imu: {type: imu_z_sensor}
)");
  const BridgeRoutes r = make_routes(sc, *participant, profiles);
  EXPECT_EQ(r.sensors.size(), 4u);
  for (int id : {0x30, 0x31, 0x20, 0x32}) EXPECT_GE(r.sensor_by_id[static_cast<std::size_t>(id)], 0) << id;
  EXPECT_EQ(r.command.layout->id, 0x82);
}

// The arm's frames are sized for its joints: 3 here (phi, dphi, tau per joint), the command
// one torque per joint, the truth five values per joint.
TEST_F(Routes, ArmRoutesEveryTopicSizedForItsJoints) {
  auto sc = robot(R"(
name: t
step: 0.001
clock: {mode: realtime}
robots:
  r4:
    source: {type: udp_bridge, bind: "127.0.0.1:47001", peer: "127.0.0.1:47002"}
    plant: {type: flexible_joint_arm, model: uniform, dof: 3}
    sensors:
      joint_states: {type: joint_encoders, dof: 3}
)");
  const BridgeRoutes r = make_routes(sc, *participant, profiles);
  ASSERT_EQ(r.sensors.size(), 2u);
  const auto& states = r.sensors[static_cast<std::size_t>(r.sensor_by_id[0x40])];
  EXPECT_EQ(states.layout->fields.size(), 9u);
  EXPECT_EQ(states.layout->fields[3].name, "dphi1");
  EXPECT_EQ(r.sensors[static_cast<std::size_t>(r.sensor_by_id[0x41])].layout->payload_size(), 15u * 8);
  EXPECT_EQ(r.command.layout->id, 0x83);
  EXPECT_EQ(r.command.layout->fields.size(), 3u);
  EXPECT_EQ(r.command.layout->fields[2].name, "u3");
  EXPECT_NE(r.table.get(), &link::message_layouts());  // a table of its own
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
  // The cycle is sent in the device's clock (docs/bridges.md, "Cycle sync").
  bad("{type: udp_bridge, bind: 127.0.0.1:1, peer: 127.0.0.1:2, cycle_sync: true}",
      "robots.r1.source.cycle_sync: only with device_time: true");
}

// A device's own frame table (docs/bridges.md, "A device's own frames").
const std::string kEncoderBoard = R"(name: t
step: 0.01
robots:
  r1:
    source:
      type: udp_bridge
      bind: 127.0.0.1:1
      peer: 127.0.0.1:2
      frames:
        - {id: 0x40, direction: to_host, topic: position, type: PositionMeasurement,
           fields: [{name: x, wire: i32, scale: 1.0e-4}, {name: y, wire: f32}]}
        - {id: 0x41, direction: to_host, topic: truth/state, type: Pose2D,
           fields: [{name: x, wire: f32}, {name: y, wire: f32}, {name: theta, wire: i16, scale: 0.001}]}
        - {id: 0x90, direction: to_device, topic: cmd, type: UnicycleCommand,
           fields: [{name: v, wire: i16, scale: 0.001}, {name: omega, wire: i16, scale: 0.001}]}
    plant: {type: unicycle}
    sensors:
      position: {type: position_sensor, kind: exact}
)";

TEST(DeclaredFrames, ARobotsOwnTableReplacesTheBuiltInOne) {
  auto sc = robot(kEncoderBoard);
  const scenario::StepExecutor wiring(sc);
  const RobotFrames f = robot_frames(sc, wiring, "a test");
  ASSERT_NE(f.table.get(), &link::message_layouts());
  ASSERT_EQ(f.outputs.size(), 2u);
  for (const auto& o : f.outputs) EXPECT_TRUE(o.layout->id == 0x40 || o.layout->id == 0x41) << int(o.layout->id);
  ASSERT_TRUE(f.command);
  EXPECT_EQ(f.command->layout->id, 0x90);
  const auto* pos = link::find_layout(*f.table, uint8_t{0x40});
  ASSERT_NE(pos, nullptr);
  EXPECT_EQ(pos->payload_size(), 8u);  // i32 + f32
  EXPECT_EQ(pos->fields[0].kind, link::WireKind::i32);
  EXPECT_DOUBLE_EQ(pos->fields[0].scale, 1e-4);
}

TEST(DeclaredFrames, BadTablesAreRefusedNamingTheEntry) {
  const auto bad = [](const std::string& frames, const std::string& expect, bool device_time = false) {
    const std::string yaml =
        "name: t\nstep: 0.01\nrobots:\n  r1:\n    source:\n      type: udp_bridge\n"
        "      bind: 127.0.0.1:1\n      peer: 127.0.0.1:2\n" +
        std::string(device_time ? "      device_time: true\n" : "") + "      frames:\n" + frames +
        "    plant: {type: unicycle}\n";
    try {
      auto sc = robot(yaml);
      const scenario::StepExecutor wiring(sc);
      (void)robot_frames(sc, wiring, "a test");
      ADD_FAILURE() << frames << " was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(expect), std::string::npos) << e.what();
    }
  };
  const std::string cmd =
      "        - {id: 0x90, direction: to_device, topic: cmd, type: UnicycleCommand, fields: [{name: v}, {name: "
      "omega}]}\n";
  // A duplicate id.
  bad("        - {id: 0x11, direction: to_host, topic: truth/state, type: Pose2D, fields: [{name: x}]}\n"
      "        - {id: 0x11, direction: to_host, topic: truth/state, type: Pose2D, fields: [{name: y}]}\n" +
          cmd,
      "robots.r1.source.frames[1].id: id 17 is declared twice");
  // An unknown field.
  bad("        - {id: 0x11, direction: to_host, topic: truth/state, type: Pose2D, fields: [{name: altitude}]}\n" + cmd,
      "robots.r1.source.frames[0].fields[0].name: 'altitude' is not a field of Pose2D");
  // More fields than a frame carries: LinkJointState's 128 f64 (1024 bytes, a frame's
  // payload) and its count.
  std::string all;
  for (const char* member : {"q", "dq", "ddq", "dddq", "tau", "dtau", "phi", "dphi"})
    for (int i = 1; i <= 16; ++i)
      all += std::string(all.empty() ? "" : ", ") + "{name: " + member + std::to_string(i) + "}";
  bad("        - {id: 0x30, direction: to_host, topic: estimate, type: LinkJointState, fields: [" + all +
          ", {name: count, wire: u16}]}\n" + cmd,
      "robots.r1.source.frames[0]: 129 fields; a frame carries 128 at most");
  // 128 f64 fit, but not with the device time.
  bad("        - {id: 0x30, direction: to_host, topic: estimate, type: LinkJointState, fields: [" + all + "]}\n" + cmd,
      "a payload of 1024 bytes and the device time's 8 is longer than a frame's 1024", true);
  // A wire type the member cannot hold: JointState's count is an unsigned short.
  bad("        - {id: 0x31, direction: to_host, topic: joint_states, type: JointState, fields: [{name: count, wire: "
      "f32}]}\n" +
          cmd,
      "frames[0].fields[0].wire: member count of JointState holds integers");
  // The link's own ids, a direction against its id, an unknown wire type, a scale on a float.
  bad("        - {id: 0x0E, direction: to_host, topic: truth/state, type: Pose2D, fields: [{name: x}]}\n" + cmd,
      "id 0x0E is the link's own");
  bad("        - {id: 0x11, direction: to_host, topic: truth/state, type: Pose2D, fields: [{name: x}]}\n"
      "        - {id: 0x8D, direction: to_device, topic: cmd, type: UnicycleCommand, fields: [{name: v}]}\n",
      "id 0x8D is the link's own");
  bad("        - {id: 0x91, direction: to_host, topic: truth/state, type: Pose2D, fields: [{name: x}]}\n" + cmd,
      "device -> host ids are 0x00 .. 0x7F");
  bad("        - {id: 0x11, direction: to_host, topic: truth/state, type: Pose2D, fields: [{name: x, wire: f16}]}\n" +
          cmd,
      "fields[0].wire: expected f64, f32");
  bad("        - {id: 0x11, direction: to_host, topic: truth/state, type: Pose2D, fields: [{name: x, wire: f32, scale: "
      "2}]}\n" +
          cmd,
      "fields[0].scale: only for integer wire types");
  bad("        - {id: 0x11, direction: to_host, topic: truth/state, type: Pose2D, fields: [{name: x}]}\n",
      "has no frame in the source's own `frames`");
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
