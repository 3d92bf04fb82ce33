#include "plexus/scenario/overrides.hpp"

#include <gtest/gtest.h>

#include "plexus/scenario/scenario.hpp"
#include "test_scenarios.hpp"

namespace plexus::scenario {
namespace {

using testing::error_of;
using testing::kValid;

Scenario load_with(std::initializer_list<const char*> sets) {
  std::vector<Override> o;
  for (const char* s : sets) o.push_back(parse_override(s));
  return load_scenario_text(kValid, "t.yaml", o);
}

std::string set_error(std::initializer_list<const char*> sets) {
  return error_of([&] { load_with(sets); });
}

TEST(Overrides, SetsTopLevelNestedListAndNewOptionalValues) {
  const Scenario sc = load_with({"duration=2", "services.driver.v=3.5", "robots.r1.sensors.gps.seed=9",
                                 "metrics.0.field=y", "clock.mode=realtime", "robots.r1.sensors.gps.fields=[x]"});
  EXPECT_EQ(sc.steps, 20);
  EXPECT_EQ(sc.resolved["services"]["driver"]["v"].as<double>(), 3.5);
  EXPECT_EQ(sc.resolved["robots"]["r1"]["sensors"]["gps"]["seed"].as<int>(), 9);
  EXPECT_EQ(sc.resolved["metrics"][0]["field"].as<std::string>(), "y");
  EXPECT_EQ(sc.clock, ClockMode::realtime);
  EXPECT_EQ(sc.signals[1].fields, std::vector<std::string>{"x"});
}

TEST(Overrides, LaterOverridesWin) { EXPECT_EQ(load_with({"duration=2", "duration=3"}).steps, 30); }

TEST(Overrides, ValidationIsTheSameAndNamesTheOverride) {
  EXPECT_EQ(set_error({"duration=abc"}), "t.yaml: --set duration=abc: duration: expected a finite number, got 'abc'");
  EXPECT_EQ(set_error({"duration=-1"}), "t.yaml: --set duration=-1: duration: must be > 0 s");
  EXPECT_EQ(set_error({"robots.r1.sensors.gps.rate=3"}).substr(0, 76),
            "t.yaml: --set robots.r1.sensors.gps.rate=3: robots.r1.sensors.gps.rate: must");
}

TEST(Overrides, KeysOutsideTheSchemaAreErrors) {
  EXPECT_EQ(set_error({"durration=2"}), "t.yaml: --set durration=2: durration: unknown key");
  EXPECT_EQ(set_error({"robots.r1.plant.z0=1"}), "t.yaml: --set robots.r1.plant.z0=1: robots.r1.plant.z0: unknown key");
  EXPECT_EQ(set_error({"robts.r1.plant.x0=1"}), "t.yaml: --set robts.r1.plant.x0=1: robts: unknown key");
  EXPECT_EQ(set_error({"duration.x=1"}),
            "--set duration.x=1: duration: not a mapping or a list (or no such list element)");
  EXPECT_EQ(set_error({"metrics.5.from=1"}), "--set metrics.5.from=1: metrics.5: no such list element");
}

TEST(Overrides, MalformedArguments) {
  EXPECT_EQ(error_of([] { parse_override("duration"); }), "--set duration: expected dotted.key=value");
  EXPECT_EQ(error_of([] { parse_override("=3"); }), "--set =3: expected dotted.key=value");
  EXPECT_EQ(error_of([] { parse_override("a..b=3"); }), "--set a..b=3: empty key in the dotted path");
  EXPECT_EQ(error_of([] { load_with({"duration=[1"}); }).substr(0, 35), "--set duration=[1:1: YAML syntax er");
}

}  // namespace
}  // namespace plexus::scenario
