// `plexus service list`'s rows (service_census.cpp) from endpoints and heartbeats made by
// hand: names split, topics by direction with health/ and lockstep/ left out, the loop
// rate between two heartbeats, a restart starting the rate again, a process without one.
#include <gtest/gtest.h>

#include <cstring>

#include "service_census.hpp"

namespace plexus::cli {
namespace {

rt::DiscoveredEndpoint endpoint(const std::string& who, const std::string& topic, const std::string& type,
                                bool writer) {
  rt::DiscoveredEndpoint e;
  e.participant = who;
  e.topic = topic;
  e.type_name = type;
  e.is_writer = writer;
  return e;
}

msg::Heartbeat beat(uint32_t pid, uint64_t loops, int64_t publish_ns) {
  msg::Heartbeat hb;
  hb.pid(pid);
  hb.loop_count(loops);
  hb.header().publish_time_ns(publish_ns);
  hb.state(msg::SERVICE_RUNNING);
  hb.uptime_s(12.5);
  hb.compute_p99_us(80);
  std::memcpy(hb.host().data(), "robot-pc", 8);
  return hb;
}

TEST(ServiceCensus, RowsFromDiscoveryAndHeartbeats) {
  const std::vector<rt::DiscoveredEndpoint> eps = {
      endpoint("plant_simulator r1", "r1/position", "plexus::msg::PositionMeasurement", true),
      endpoint("plant_simulator r1", "r1/cmd", "plexus::msg::UnicycleCommand", false),
      endpoint("plant_simulator r1", "health/plant_simulator_r1", "plexus::msg::Heartbeat", true),
      endpoint("plant_simulator r1", "lockstep/clock", "plexus::msg::ClockStep", false),
      endpoint("plexus_topic", "r1/position", "plexus::msg::PositionMeasurement", false),
  };
  ServiceCensus c;
  c.heartbeat("health/plant_simulator_r1", beat(7, 100, 1'000'000'000), 5'000'000'000);
  c.heartbeat("health/plant_simulator_r1", beat(7, 200, 2'000'000'000), 6'000'000'000);
  const auto rows = c.rows(eps, 6'500'000'000);
  ASSERT_EQ(rows.size(), 2u);
  const auto& plant = rows[0];
  EXPECT_EQ(plant["name"], "plant_simulator r1");
  EXPECT_EQ(plant["executable"], "plant_simulator");
  EXPECT_EQ(plant["hosts"], nlohmann::ordered_json::array({"r1"}));
  EXPECT_EQ(plant["host"], "robot-pc");
  EXPECT_EQ(plant["state"], "running");
  EXPECT_DOUBLE_EQ(plant["loop_hz"].get<double>(), 100.0);  // 100 loops over 1 s of publish time
  EXPECT_DOUBLE_EQ(plant["heartbeat_age_s"].get<double>(), 0.5);
  EXPECT_DOUBLE_EQ(plant["uptime_s"].get<double>(), 12.5);
  ASSERT_EQ(plant["out"].size(), 1u);  // health/ left out
  EXPECT_EQ(plant["out"][0]["topic"], "r1/position");
  ASSERT_EQ(plant["in"].size(), 1u);  // lockstep/ left out
  EXPECT_EQ(plant["in"][0]["type"], "plexus::msg::UnicycleCommand");
  const auto& tool = rows[1];
  EXPECT_EQ(tool["name"], "plexus_topic");
  EXPECT_TRUE(tool["state"].is_null());  // no heartbeat
}

TEST(ServiceCensus, ARestartStartsTheRateAgain) {
  const std::vector<rt::DiscoveredEndpoint> eps = {
      endpoint("motion_controller controller", "health/motion_controller_controller", "plexus::msg::Heartbeat", true)};
  ServiceCensus c;
  c.heartbeat("health/motion_controller_controller", beat(7, 5000, 1'000'000'000), 1);
  c.heartbeat("health/motion_controller_controller", beat(8, 10, 2'000'000'000), 2);  // a new pid
  auto rows = c.rows(eps, 3);
  EXPECT_TRUE(rows[0]["loop_hz"].is_null());  // one heartbeat of the new process
  EXPECT_EQ(rows[0]["pid"], 8);
  c.heartbeat("health/motion_controller_controller", beat(8, 60, 2'500'000'000), 4);
  rows = c.rows(eps, 5);
  EXPECT_DOUBLE_EQ(rows[0]["loop_hz"].get<double>(), 100.0);
  EXPECT_EQ(rows[0]["hosts"], nlohmann::ordered_json::array({"controller"}));
}

}  // namespace
}  // namespace plexus::cli
