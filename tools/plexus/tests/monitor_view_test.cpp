// What `plexus launch --monitor` shows (launch/monitor_view.cpp): the health rule that turns a
// row red, the plot feed's rows and thinning, and the status message's fields.
#include <gtest/gtest.h>

#include "launch/monitor_view.hpp"

namespace plexus::cli {
namespace {

ProcessView running(double age_s) {
  ProcessView v;
  v.name = "motion_controller controller";
  v.seen = true;
  v.age_s = age_s;
  v.beat.state(msg::SERVICE_RUNNING);
  return v;
}

TEST(MonitorHealth, FromHeartbeatAgeStateAndExit) {
  EXPECT_EQ(health_of(ProcessView{}), Health::starting);
  EXPECT_EQ(health_of(running(0.9)), Health::ok);
  EXPECT_EQ(health_of(running(kHeartbeatSilentS + 0.01)), Health::down);  // silent: down
  ProcessView killed = running(0.1);
  killed.exited = true;  // its pid is gone before its heartbeat is late
  EXPECT_EQ(health_of(killed), Health::down);
  ProcessView held = running(0.1);
  held.beat.state(msg::SERVICE_DEGRADED);
  EXPECT_EQ(health_of(held), Health::degraded);
  ProcessView ended = running(5.0);
  ended.exited = true;
  ended.beat.state(msg::SERVICE_DRAINING);  // stopped at the end of the run, on purpose
  EXPECT_EQ(health_of(ended), Health::done);
}

scenario::RunLog log_of(int rows) {
  scenario::RunLog log;
  log.base_step = 0.01;
  log.signals.resize(1);
  log.signals[0].spec.name = "r1/position";
  log.signals[0].spec.fields = {"x", "y"};
  for (int r = 0; r < rows; ++r) {
    log.signals[0].steps.push_back(r);
    log.signals[0].values.push_back(r);         // x
    log.signals[0].values.push_back(-r * 2.0);  // y
  }
  return log;
}

TEST(MonitorPlot, WholeTraceThenOnlyNewRows) {
  auto log = log_of(5);
  PlotFeed feed;
  EXPECT_TRUE(feed.next(log, 100).is_null());  // nothing selected
  feed.select("r1/position", "y");
  auto first = feed.next(log, 100);
  EXPECT_TRUE(first["reset"].get<bool>());
  ASSERT_EQ(first["points"].size(), 5u);
  EXPECT_DOUBLE_EQ(first["points"][4][0].get<double>(), 0.04);
  EXPECT_DOUBLE_EQ(first["points"][4][1].get<double>(), -8.0);
  log.signals[0].steps.push_back(5);
  log.signals[0].values.insert(log.signals[0].values.end(), {5.0, -10.0});
  auto second = feed.next(log, 100);
  EXPECT_FALSE(second["reset"].get<bool>());
  ASSERT_EQ(second["points"].size(), 1u);
  EXPECT_DOUBLE_EQ(second["points"][0][1].get<double>(), -10.0);
  EXPECT_EQ(feed.next(log, 100)["points"].size(), 0u);
  feed.reset();  // a page connected: everything again
  EXPECT_EQ(feed.next(log, 100)["points"].size(), 6u);
}

TEST(MonitorPlot, ThinsToMaxPointsAndRefusesUnknownFields) {
  auto log = log_of(1000);
  PlotFeed feed;
  feed.select("r1/position", "x");
  const auto j = feed.next(log, 100);
  EXPECT_EQ(j["points"].size(), 100u);  // every 10th row
  EXPECT_DOUBLE_EQ(j["points"][1][1].get<double>(), 10.0);
  feed.select("r1/position", "z");
  EXPECT_TRUE(feed.next(log, 100).is_null());
  feed.select("r2/position", "x");
  EXPECT_TRUE(feed.next(log, 100).is_null());
}

TEST(MonitorStatus, ProcessesHostsAndProgress) {
  ProcessView bridge = running(0.2);
  bridge.name = "udp_bridge r1";
  bridge.host = "h2";
  bridge.rate_hz = 100;
  bridge.restarts = 1;
  bridge.beat.overruns(3);
  bridge.beat.stale_inputs(4);
  bridge.beat.rejected_inputs(5);
  bridge.beat.link().state(msg::LINK_UP);
  bridge.beat.link().frames_in(42);
  ProcessView waiting;
  waiting.name = "plant_simulator";
  waiting.host = "h1";
  const auto s =
      status_json({"running", 12.5, 60}, {waiting, bridge}, {{"h2", 2'500'000}}, nlohmann::json::object(), nullptr);
  EXPECT_EQ(s["type"], "status");
  EXPECT_EQ(s["phase"], "running");
  EXPECT_DOUBLE_EQ(s["t_s"].get<double>(), 12.5);
  ASSERT_EQ(s["processes"].size(), 2u);
  EXPECT_EQ(s["processes"][0]["health"], "starting");
  EXPECT_FALSE(s["processes"][0].contains("state"));
  const auto& b = s["processes"][1];
  EXPECT_EQ(b["health"], "ok");
  EXPECT_EQ(b["state"], "running");
  EXPECT_EQ(b["deadline_misses"], 3);
  EXPECT_EQ(b["stale_inputs"], 4);
  EXPECT_EQ(b["refused_inputs"], 5);
  EXPECT_EQ(b["restarts"], 1);
  EXPECT_EQ(b["link"]["state"], "up");
  EXPECT_EQ(b["link"]["frames_in"], 42);
  ASSERT_EQ(s["hosts"].size(), 2u);
  EXPECT_EQ(s["hosts"][0]["host"], "h1");
  EXPECT_DOUBLE_EQ(s["hosts"][0]["clock_offset_ms"].get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(s["hosts"][1]["clock_offset_ms"].get<double>(), 2.5);
  // A service without a link has none on the page.
  const auto plain = status_json({"running", 1, 60}, {running(0.1)}, {}, nlohmann::json::object(), nullptr);
  EXPECT_TRUE(plain["processes"][0]["link"].is_null());
}

}  // namespace
}  // namespace plexus::cli
