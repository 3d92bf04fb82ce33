#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "plexus/scenario/overrides.hpp"
#include "plexus/scenario/scenario.hpp"
#include "test_scenarios.hpp"

namespace plexus::scenario {
namespace {

using testing::error_of;
using testing::kValid;

/// Replaces the first occurrence of `from` in the valid scenario.
std::string with(const std::string& from, const std::string& to) {
  std::string s = kValid;
  const auto pos = s.find(from);
  EXPECT_NE(pos, std::string::npos) << from;
  return s.replace(pos, from.size(), to);
}

std::string load_error(const std::string& text) {
  return error_of([&] { load_scenario_text(text, "t.yaml"); });
}

TEST(ScenarioLoader, LoadsTheValidScenario) {
  const Scenario sc = load_scenario_text(kValid, "t.yaml");
  EXPECT_EQ(sc.name, "t");
  EXPECT_EQ(sc.steps, 10);
  EXPECT_EQ(sc.seed, 5u);
  EXPECT_EQ(sc.clock, ClockMode::lockstep);
  ASSERT_EQ(sc.components.size(), 3u);  // by stage: plant, sensor, controller
  EXPECT_EQ(sc.components[0].component->name(), "r1/plant");
  EXPECT_EQ(sc.components[1].component->name(), "r1/gps");
  EXPECT_EQ(sc.components[1].period_steps, 2);
  EXPECT_EQ(sc.components[2].component->name(), "driver");
  ASSERT_EQ(sc.signals.size(), 3u);
  EXPECT_EQ(sc.signals[0].name, "r1/truth/state");
  EXPECT_TRUE(sc.signals[0].plant_state);
  EXPECT_EQ(sc.signals[1].name, "r1/gps");
  EXPECT_EQ(sc.signals[2].name, "r1/cmd");
  ASSERT_EQ(sc.expectations.size(), 1u);
  EXPECT_EQ(sc.expectations[0].text(), "<= 2");
  // Derived seeds are written into the resolved tree.
  EXPECT_TRUE(sc.resolved["robots"]["r1"]["sensors"]["gps"]["seed"]);
}

TEST(ScenarioLoader, PaperInconsistentMarksItsExpectation) {
  const Scenario sc = load_scenario_text(
      with("  final_x: \"<= 2\"\n", "  final_x: \"<= 2\"\npaper_inconsistent:\n  final_x: docs/x.md, \"Why\"\n"),
      "t.yaml");
  ASSERT_EQ(sc.expectations.size(), 1u);
  EXPECT_EQ(sc.expectations[0].inconsistent, "docs/x.md, \"Why\"");
}

TEST(ScenarioLoader, RealtimeClockSettings) {
  const Scenario sc = load_scenario_text(
      with("seed: 5\n", "seed: 5\nclock: {mode: realtime, input_deadline_periods: 4, blind_after_s: 0.5}\n"), "t.yaml");
  EXPECT_EQ(sc.clock, ClockMode::realtime);
  EXPECT_EQ(sc.input_deadline_periods, 4.0);
  EXPECT_EQ(sc.blind_after_s, 0.5);
  EXPECT_EQ(load_scenario_text(kValid, "t.yaml").blind_after_s, 0.3);  // the documented default
  const std::string e = load_error(with("seed: 5\n", "seed: 5\nclock: {mode: realtime, blind_after_s: -1}\n"));
  EXPECT_NE(e.find("clock.blind_after_s"), std::string::npos) << e;
  EXPECT_NE(e.find("must be in [0, 60] s"), std::string::npos) << e;
  EXPECT_EQ(e.find('\n'), std::string::npos) << e;  // one line
}

// An estimator's own blind grace (issue 33, item 5: a 1 kHz arm needs a shorter one than the
// scenario's 0.3 s); only an estimator takes one.
TEST(ScenarioLoader, EstimatorBlindGrace) {
  const std::string rfid = std::string(PLEXUS_SOURCE_DIR) + "/deploy/scenarios/wmr_output_feedback_rfid.yaml";
  auto component = [](const Scenario& sc, const std::string& name) -> const ScenarioComponent& {
    for (const auto& c : sc.components)
      if (c.component->name() == name) return c;
    throw std::runtime_error("no component " + name);
  };
  const Scenario plain = load_scenario(rfid);
  EXPECT_EQ(component(plain, "observer").blind_after_s, 0.3);  // the clock's default
  const Scenario clock =
      load_scenario(rfid, {parse_override("clock.mode=realtime"), parse_override("clock.blind_after_s=0.5")});
  EXPECT_EQ(component(clock, "observer").blind_after_s, 0.5);  // the clock's own
  const Scenario own = load_scenario(rfid, {parse_override("services.observer.blind_after_s=0.01")});
  EXPECT_EQ(component(own, "observer").blind_after_s, 0.01);
  EXPECT_EQ(own.blind_after_s, 0.3);  // the scenario's grace is unchanged
  std::string e = error_of([&] { load_scenario(rfid, {parse_override("services.observer.blind_after_s=-1")}); });
  EXPECT_NE(e.find("services.observer.blind_after_s"), std::string::npos) << e;
  EXPECT_NE(e.find("must be in [0, 60] s"), std::string::npos) << e;
  e = error_of([&] { load_scenario(rfid, {parse_override("services.controller.blind_after_s=0.1")}); });
  EXPECT_NE(e.find("services.controller.blind_after_s"), std::string::npos) << e;
  EXPECT_NE(e.find("only an estimator goes blind (this service is a controller)"), std::string::npos) << e;
  EXPECT_EQ(e.find('\n'), std::string::npos) << e;  // one line
}

// clock.priority: every loop's SCHED_FIFO priority unless its robot or service sets its own.
TEST(ScenarioLoader, LoopPriorityDefault) {
  const std::string rfid = std::string(PLEXUS_SOURCE_DIR) + "/deploy/scenarios/wmr_output_feedback_rfid.yaml";
  auto priority = [](const Scenario& sc, const std::string& name) {
    for (const auto& c : sc.components)
      if (c.component->name() == name) return c.priority;
    throw std::runtime_error("no component " + name);
  };
  const Scenario plain = load_scenario(rfid);
  EXPECT_EQ(plain.loop_priority, 0);
  EXPECT_EQ(priority(plain, "observer"), 0);
  const Scenario all = load_scenario(rfid, {parse_override("clock.mode=realtime"), parse_override("clock.priority=60"),
                                            parse_override("services.controller.priority=70")});
  EXPECT_EQ(priority(all, "observer"), 60);
  EXPECT_EQ(priority(all, "r1/plant"), 60);    // the robot's plant-side process
  EXPECT_EQ(priority(all, "controller"), 70);  // its own
  const Scenario off = load_scenario(rfid, {parse_override("clock.mode=realtime"), parse_override("clock.priority=60"),
                                            parse_override("robots.r1.priority=0")});
  EXPECT_EQ(priority(off, "r1/plant"), 0);  // 0 of its own: normal scheduling
  const std::string e = error_of([&] {
    load_scenario(rfid, {parse_override("clock.mode=realtime"), parse_override("clock.priority=100")});
  });
  EXPECT_NE(e.find("clock.priority"), std::string::npos) << e;
  EXPECT_NE(e.find("must be in 0..99"), std::string::npos) << e;
  EXPECT_EQ(e.find('\n'), std::string::npos) << e;  // one line
}

TEST(ScenarioLoader, BuiltInScenarioLoads) {
  const Scenario sc = load_scenario(std::string(PLEXUS_SOURCE_DIR) + "/deploy/scenarios/unicycle_circle.yaml");
  EXPECT_EQ(sc.name, "unicycle_circle");
  EXPECT_EQ(sc.metrics.size(), 5u);
}

struct BadCase {
  const char* label;
  std::string text;
  std::string expected;  ///< the message, or its beginning (lists of registered types grow)
};

class ScenarioLoaderErrors : public ::testing::TestWithParam<BadCase> {};

TEST_P(ScenarioLoaderErrors, NameFileLineAndKey) {
  const std::string message = load_error(GetParam().text);
  EXPECT_EQ(message.substr(0, GetParam().expected.size()), GetParam().expected) << message;
}

INSTANTIATE_TEST_SUITE_P(
    EveryErrorPath, ScenarioLoaderErrors,
    ::testing::Values(
        BadCase{"unknown_top_key", with("seed: 5\n", "seed: 5\ncolour: red\n"), "t.yaml:5: colour: unknown key"},
        BadCase{"missing_name", with("name: t\n", "description: x\n"), "t.yaml:1: name: required key is missing"},
        BadCase{"bad_name", with("name: t\n", "name: a b\n"),
                "t.yaml:1: name: letters, digits, '_' and '-' only, at most 64 characters"},
        BadCase{"duration_type", with("duration: 1.0", "duration: long"),
                "t.yaml:2: duration: expected a finite number, got 'long'"},
        BadCase{"duration_range", with("duration: 1.0", "duration: -1"), "t.yaml:2: duration: must be > 0 s"},
        BadCase{"step_range", with("step: 0.1", "step: 0"), "t.yaml:3: step: must be at least 1e-6 s"},
        // Below 0.5 ns the step was 0 ns in a distributed run, and every process divided by it.
        BadCase{"step_below_1us", with("step: 0.1", "step: 1e-10"), "t.yaml:3: step: must be at least 1e-6 s"},
        BadCase{"step_longer", with("step: 0.1", "step: 2"), "t.yaml:3: step: must not exceed the duration"},
        BadCase{"duration_not_whole", with("step: 0.1", "step: 0.3"),
                "t.yaml:2: duration: must be a whole number of steps (duration / step = 3.333333)"},
        BadCase{"seed_type", with("seed: 5", "seed: five"), "t.yaml:4: seed: expected an integer, got 'five'"},
        BadCase{"seed_range", with("seed: 5", "seed: -5"), "t.yaml:4: seed: must be >= 0"},
        BadCase{"clock_mode", with("seed: 5\n", "seed: 5\nclock: {mode: fast}\n"),
                "t.yaml:5: clock.mode: expected lockstep or realtime, got 'fast'"},
        BadCase{"clock_unknown", with("seed: 5\n", "seed: 5\nclock: {mode: lockstep, rate: 1}\n"),
                "t.yaml:5: clock.rate: unknown key"},
        BadCase{"dds_vendor", with("seed: 5\n", "seed: 5\ndds: {vendor: rti}\n"),
                "t.yaml:5: dds.vendor: expected fast or cyclone, got 'rti'"},
        BadCase{"dds_domain", with("seed: 5\n", "seed: 5\ndds: {domain: 300}\n"),
                "t.yaml:5: dds.domain: must be in 0..232"},
        BadCase{"host_unknown_key", with("seed: 5\n", "seed: 5\nhosts: {a: {adress: x}}\n"),
                "t.yaml:5: hosts.a.adress: unknown key"},
        BadCase{"robots_missing", "name: t\nduration: 1\nstep: 0.1\nseed: 1\n",
                "t.yaml:1: robots: required key is missing"},
        BadCase{"robots_not_map", "name: t\nduration: 1\nstep: 0.1\nseed: 1\nrobots: [a]\n",
                "t.yaml:5: robots: expected a mapping, got a list"},
        BadCase{"robots_empty", "name: t\nduration: 1\nstep: 0.1\nseed: 1\nrobots: {}\n",
                "t.yaml:5: robots: needs at least one robot"},
        BadCase{"robot_unknown_key", with("    sensors:", "    wheels: 2\n    sensors:"),
                "t.yaml:10: robots.r1.wheels: unknown key"},
        BadCase{"plant_missing", with("    plant:\n      type: unicycle\n      y0: -1.0\n", ""),
                "t.yaml:7: robots.r1.plant: required key is missing"},
        BadCase{"type_unknown", with("type: unicycle", "type: bicycle"),
                "t.yaml:8: robots.r1.plant.type: unknown component type 'bicycle' (known: "},
        BadCase{"type_wrong_kind", with("type: unicycle", "type: measurement"),
                "t.yaml:8: robots.r1.plant.type: 'measurement' is a sensor and cannot be used in a robot's plant"},
        BadCase{"service_plant", with("type: constant_command", "type: unicycle"),
                "t.yaml:18: services.driver.type: 'unicycle' is a plant and cannot be used in services"},
        BadCase{"param_unknown", with("y0: -1.0", "y0: -1.0\n      z0: 3"),
                "t.yaml:10: robots.r1.plant.z0: unknown key"},
        BadCase{"param_type", with("y0: -1.0", "y0: [1]"),
                "t.yaml:9: robots.r1.plant.y0: expected a finite number, got a list"},
        BadCase{"param_missing", with("    v: 1.0\n", ""), "t.yaml:18: services.driver.v: required key is missing"},
        BadCase{"param_range", with("noise_std: 0.1", "noise_std: -0.1"),
                "t.yaml:15: robots.r1.sensors.gps.noise_std: must be >= 0"},
        BadCase{"rate_zero", with("rate: 5", "rate: 0"), "t.yaml:13: robots.r1.sensors.gps.rate: must be > 0 Hz"},
        BadCase{"rate_too_fast", with("rate: 5", "rate: 20"),
                "t.yaml:13: robots.r1.sensors.gps.rate: is faster than the base rate 10.000000 Hz (1 / step)"},
        BadCase{"rate_not_divisor", with("rate: 5", "rate: 3"),
                "t.yaml:13: robots.r1.sensors.gps.rate: must divide the base rate 10.000000 Hz: the period must be a "
                "whole number of steps"},
        BadCase{"sensor_seed", with("rate: 5", "rate: 5\n        seed: -1"),
                "t.yaml:14: robots.r1.sensors.gps.seed: must be >= 0"},
        BadCase{"service_robot", with("robot: r1", "robot: r2"),
                "t.yaml:19: services.driver.robot: no robot 'r2' in robots"},
        BadCase{"service_host", with("robot: r1", "robot: r1\n    host: pc"),
                "t.yaml:20: services.driver.host: no host 'pc' in hosts"},
        BadCase{"service_qos", with("robot: r1", "robot: r1\n    qos: ''"),
                "t.yaml:20: services.driver.qos: must name a QoS profile"},
        BadCase{"remap_unknown_port", with("robot: r1", "robot: r1\n    remap: {command: r1/cmd2}"),
                "t.yaml:20: services.driver.remap: 'constant_command' has no port 'command'"},
        // A remap that takes a signal away from its reader is named, not the reader it starves.
        BadCase{"input_unbound", with("robot: r1", "robot: r1\n    remap: {cmd: r1/cmd2}"),
                "t.yaml:20: services.driver.remap.cmd: sends driver's output 'cmd' to 'r1/cmd2', so nothing produces "
                "'r1/cmd', read by t.yaml:8: robots.r1.plant (port 'cmd')"},
        BadCase{
            "input_remapped_to_nothing", with("y0: -1.0", "y0: -1.0\n      remap: {cmd: r1/nothing}"),
            "t.yaml:10: robots.r1.plant.remap.cmd: reads port 'cmd' from 'r1/nothing', which no component produces"},
        BadCase{"input_without_producer",
                with("type: constant_command\n    robot: r1\n    v: 1.0\n    omega: 0.0",
                     "type: circle_reference\n    robot: r1\n    radius: 1.0\n    speed: 0.5"),
                "t.yaml:8: robots.r1.plant: input 'r1/cmd' (port 'cmd') is produced by no component; remap the port "
                "or add its producer"},
        BadCase{"input_field", with("fields: [x, y]", "fields: [x, z]"),
                "t.yaml:12: robots.r1.sensors.gps: input 'r1/truth/state' has no field 'z' (it has: x, y, theta)"},
        BadCase{"output_twice", with("robot: r1", "robot: r1\n    remap: {cmd: r1/truth/state}"),
                "t.yaml:20: services.driver.remap.cmd: sends driver's output 'cmd' to 'r1/truth/state', which r1/plant "
                "already produces"},
        BadCase{"sensor_name", with("      gps:", "      g.ps:"),
                "t.yaml:12: robots.r1.sensors.g.ps: invalid sensor name (letters, digits, '_' and '-', at most 64)"},
        BadCase{"metrics_not_list",
                with("metrics:\n  - {name: final_x, type: value_final, signal: r1/truth/state, field: x}",
                     "metrics: {a: 1}"),
                "t.yaml:22: metrics: expected a list, got a mapping"},
        BadCase{"metric_type", with("type: value_final", "type: value_last"),
                "t.yaml:23: metrics.0.type: unknown metric type 'value_last' (known: "},
        BadCase{"metric_signal", with("signal: r1/truth/state", "signal: r1/pose"),
                "t.yaml:23: metrics.0.signal: no signal 'r1/pose' in this scenario (signals: r1/truth/state, r1/gps, "
                "r1/cmd)"},
        BadCase{"metric_field", with("field: x}", "field: q}"),
                "t.yaml:23: metrics.0.field: signal 'r1/truth/state' has no field 'q'"},
        BadCase{"metric_window", with("field: x}", "field: x, from: 2}"),
                "t.yaml:23: metrics.0.from: must be in [0, duration]"},
        BadCase{"metric_unknown_key", with("field: x}", "field: x, form: 0}"),
                "t.yaml:23: metrics.0.form: unknown key"},
        BadCase{
            "metric_twice",
            with("metrics:\n", "metrics:\n  - {name: final_x, type: value_max, signal: r1/truth/state, field: x}\n"),
            "t.yaml:24: metrics.1.name: metric 'final_x' is defined twice (or is 'digest')"},
        BadCase{"metric_digest", with("name: final_x, type", "name: digest, type"),
                "t.yaml:23: metrics.0.name: metric 'digest' is defined twice (or is 'digest')"},
        BadCase{"error_fields",
                with("  - {name: final_x",
                     "  - {name: e, type: error_max, signal: r1/gps, reference: r1/truth/state, fields: [x, "
                     "theta]}\n  - {name: final_x"),
                "t.yaml:23: metrics.0.fields: signal 'r1/gps' has no field 'theta'"},
        BadCase{"expectation_metric", with("final_x: \"<= 2\"", "final_y: \"<= 2\""),
                "t.yaml:25: expectations.final_y: no metric 'final_y' in metrics"},
        BadCase{
            "expectation_syntax", with("\"<= 2\"", "\"about 2\""),
            "t.yaml:25: expectations.final_x: expected '<op> <number>' with op one of <=, >=, <, >, ==; got 'about 2'"},
        BadCase{
            "expectation_number", with("\"<= 2\"", "\"<= two\""),
            "t.yaml:25: expectations.final_x: expected '<op> <number>' with op one of <=, >=, <, >, ==; got '<= two'"},
        BadCase{"inconsistent_without_expectation",
                with("  final_x: \"<= 2\"\n", "  final_x: \"<= 2\"\npaper_inconsistent:\n  final_y: docs/x.md\n"),
                "t.yaml:27: paper_inconsistent.final_y: no expectation on 'final_y' in expectations (an entry here "
                "marks one; "
                "one removed from expectations, with --set say, goes from paper_inconsistent too: --set "
                "paper_inconsistent={})"},
        BadCase{"inconsistent_without_evidence",
                with("  final_x: \"<= 2\"\n", "  final_x: \"<= 2\"\npaper_inconsistent:\n  final_x: \"\"\n"),
                "t.yaml:27: paper_inconsistent.final_x: must name the evidence (a docs page and section)"},
        BadCase{"yaml_syntax", "name: [t\n", "t.yaml:2: YAML syntax error: end of sequence flow not found"}),
    [](const ::testing::TestParamInfo<BadCase>& param_info) { return std::string(param_info.param.label); });

TEST(ScenarioLoader, MissingFileIsAnInputError) {
  EXPECT_EQ(error_of([] { load_scenario("/nonexistent/s.yaml"); }), "/nonexistent/s.yaml: cannot open file");
}

}  // namespace
}  // namespace plexus::scenario
