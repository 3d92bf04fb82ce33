// Lockstep semantics and determinism of the in-process executor.
#include "plexus/scenario/executor.hpp"

#include <gtest/gtest.h>

#include "plexus/scenario/digest.hpp"
#include "plexus/scenario/registry.hpp"
#include "test_scenarios.hpp"

namespace plexus::scenario {
namespace {

// Probe components: each reports the step of the input sample it saw.
class ProbePlant final : public Component {
 public:
  explicit ProbePlant(const ComponentConfig& c)
      : Component(c), cmd_(add_input("cmd", {"k"}, "")), out_(add_output("state", {"k", "cmd_step"}, "")) {}
  void step(int64_t k, double) override {
    out_[0] = static_cast<double>(k);
    out_[1] = static_cast<double>(cmd_.sample().step);
  }

 private:
  InputPort& cmd_;
  OutputPort& out_;
};

class ProbeSensor final : public Component {
 public:
  explicit ProbeSensor(const ComponentConfig& c)
      : Component(c), in_(add_input("state", {"k"}, "")), out_(add_output(c.key, {"state_k"}, "")) {}
  void step(int64_t, double) override { out_[0] = in_[0]; }

 private:
  InputPort& in_;
  OutputPort& out_;
};

class ProbeController final : public Component {
 public:
  explicit ProbeController(const ComponentConfig& c)
      : Component(c), in_(add_input("probe", {"state_k"}, "")), out_(add_output("cmd", {"k", "probe_k"}, "")) {}
  void step(int64_t k, double) override {
    out_[0] = static_cast<double>(k);
    out_[1] = in_.valid() ? in_[0] : -1.0;
  }

 private:
  InputPort& in_;
  OutputPort& out_;
};

const ComponentRegistration kProbePlant{"test_probe_plant", ComponentKind::plant, "test",
                                        [](const ComponentConfig& c) { return std::make_unique<ProbePlant>(c); }};
const ComponentRegistration kProbeSensor{"test_probe_sensor", ComponentKind::sensor, "test",
                                         [](const ComponentConfig& c) { return std::make_unique<ProbeSensor>(c); }};
const ComponentRegistration kProbeController{
    "test_probe_controller", ComponentKind::controller, "test",
    [](const ComponentConfig& c) { return std::make_unique<ProbeController>(c); }};

const std::string kProbe = R"(name: probe
duration: 1.0
step: 0.1
seed: 1
robots:
  r:
    plant: {type: test_probe_plant}
    sensors:
      probe: {type: test_probe_sensor, rate: 5}
services:
  ctl: {type: test_probe_controller, robot: r, rate: 10}
)";

RunLog run_text(const std::string& text, std::initializer_list<const char*> sets = {}) {
  std::vector<Override> o;
  for (const char* s : sets) o.push_back(parse_override(s));
  Scenario sc = load_scenario_text(text, "t.yaml", o);
  return run_scenario(sc);
}

TEST(Executor, SensorsSeeThisStepAndPlantsSeeThePreviousCommand) {
  const RunLog log = run_text(kProbe);
  const SignalTrace& state = *log.find("r/state");
  const SignalTrace& probe = *log.find("r/probe");
  const SignalTrace& cmd = *log.find("r/cmd");
  ASSERT_EQ(state.size(), 11u);  // steps 0..10
  ASSERT_EQ(probe.size(), 6u);   // 5 Hz on a 10 Hz base: steps 0, 2, .., 10
  ASSERT_EQ(cmd.size(), 11u);
  for (std::size_t i = 0; i < state.size(); ++i) {
    EXPECT_EQ(state.at(i, 1), static_cast<double>(i) - 1.0) << i;  // command of step k-1 (-1: none yet)
  }
  for (std::size_t i = 0; i < probe.size(); ++i) {
    EXPECT_EQ(probe.steps[i], static_cast<int64_t>(2 * i));
    EXPECT_EQ(probe.at(i, 0), static_cast<double>(2 * i));  // the plant state of the same step
  }
  for (std::size_t i = 0; i < cmd.size(); ++i)  // controller: latest probe sample at or before k
    EXPECT_EQ(cmd.at(i, 1), static_cast<double>(i - i % 2)) << i;
}

TEST(Executor, SlowProducerInALaterStageIsHeld) {
  // Base step 0.05 s, controller at 5 Hz: it runs every 4th step.
  const RunLog log = run_text(kProbe, {"step=0.05", "services.ctl.rate=5"});
  const SignalTrace& state = *log.find("r/state");
  ASSERT_EQ(state.size(), 21u);
  for (std::size_t k = 1; k < state.size(); ++k) {
    const int64_t expected = static_cast<int64_t>((k - 1) / 4 * 4);  // latest multiple of 4 at or before k-1
    EXPECT_EQ(state.at(k, 1), static_cast<double>(expected)) << k;
  }
}

TEST(Executor, SameSeedSameDigestDifferentSeedDifferentDigest) {
  const std::string file = std::string(PLEXUS_SOURCE_DIR) + "/deploy/scenarios/unicycle_circle.yaml";
  auto digest = [&](std::vector<Override> o) {
    Scenario sc = load_scenario(file, o);
    const RunLog log = run_scenario(sc);
    return std::make_pair(run_digest(log), log.find("r1/gps")->values);
  };
  const auto a = digest({});
  const auto b = digest({});
  EXPECT_EQ(a.first, b.first);
  EXPECT_EQ(a.second, b.second);  // sensor noise too
  const auto c = digest({parse_override("seed=43")});
  EXPECT_NE(a.second, c.second);  // new sensor noise; the open-loop plant state is unchanged
  EXPECT_EQ(a.first, c.first);
  // With actuation noise the seed reaches the plant state, and so the digest.
  const auto noisy = parse_override("robots.r1.plant.omega_noise_std=0.01");
  const auto n42 = digest({noisy});
  EXPECT_EQ(n42.first, digest({noisy}).first);
  EXPECT_NE(n42.first, digest({noisy, parse_override("seed=43")}).first);
  EXPECT_NE(n42.first, a.first);
}

TEST(Executor, ASensorSeedOnlyMovesThatSensor) {
  const std::string file = std::string(PLEXUS_SOURCE_DIR) + "/deploy/scenarios/unicycle_circle.yaml";
  auto run = [&](std::vector<Override> o) {
    Scenario sc = load_scenario(file, o);
    return run_scenario(sc);
  };
  const RunLog a = run({});
  const RunLog b = run({parse_override("robots.r1.sensors.gps.seed=7")});
  EXPECT_NE(a.find("r1/gps")->values, b.find("r1/gps")->values);
  EXPECT_EQ(a.find("r1/rfid")->values, b.find("r1/rfid")->values);
}

}  // namespace
}  // namespace plexus::scenario

namespace plexus::scenario {
namespace {

TEST(Executor, TheResolvedScenarioReproducesTheRun) {
  const std::string file = std::string(PLEXUS_SOURCE_DIR) + "/deploy/scenarios/unicycle_circle.yaml";
  const std::vector<Override> noisy{parse_override("robots.r1.plant.omega_noise_std=0.01")};
  Scenario a = load_scenario(file, noisy);
  YAML::Emitter em;
  em << a.resolved;
  Scenario b = load_scenario_text(em.c_str(), "resolved.yaml");
  const RunLog la = run_scenario(a);
  const RunLog lb = run_scenario(b);
  EXPECT_EQ(run_digest(la), run_digest(lb));
  EXPECT_EQ(la.find("r1/gps")->values, lb.find("r1/gps")->values);
}

}  // namespace
}  // namespace plexus::scenario
