// StepExecutor::step_from, as a distributed lockstep host drives it on the receive thread:
// a closed loop (plant and sensors in one "process", the observer, controller and reference
// in another) stepped in pieces, each resuming where the last stopped when an input had not
// arrived, with the samples crossing in an arbitrary (seeded) order. The result must be
// plexus sim's, bit for bit.
#include <gtest/gtest.h>

#include <map>
#include <random>

#include "plexus/scenario/digest.hpp"
#include "plexus/scenario/executor.hpp"
#include "plexus/scenario/scenario.hpp"
#include "plexus/scenario/step_executor.hpp"

namespace plexus::scenario {
namespace {

const std::string kFile = std::string(PLEXUS_SOURCE_DIR) + "/deploy/scenarios/wmr_output_feedback.yaml";

Scenario load() { return load_scenario(kFile, {parse_override("duration=3")}); }

/// One side of the split: its executor, the step it is at and the component it resumes at.
struct Side {
  Scenario sc;
  std::vector<bool> hosted;
  std::unique_ptr<StepExecutor> exec;
  int64_t k = 0;
  std::size_t cursor = 0;
};

TEST(StepFrom, ResumedStepsOfASplitClosedLoopGivePlexusSimsRun) {
  Scenario whole = load();
  const RunLog expected = run_scenario(whole);

  std::vector<Side> sides(2);
  for (std::size_t h = 0; h < 2; ++h) {
    sides[h].sc = load();
    for (const auto& c : sides[h].sc.components) {
      const bool plant_side = c.kind == ComponentKind::plant || c.kind == ComponentKind::sensor;
      sides[h].hosted.push_back(plant_side == (h == 0));
    }
    sides[h].exec = std::make_unique<StepExecutor>(sides[h].sc, sides[h].hosted);
  }
  ASSERT_FALSE(sides[0].exec->remote_inputs().empty());  // a closed loop: each side waits for the other
  ASSERT_FALSE(sides[1].exec->remote_inputs().empty());

  const auto& signals = sides[0].exec->signals();
  RunLog log;
  log.base_step = expected.base_step;
  log.steps = expected.steps;
  log.signals.resize(signals.size());
  for (std::size_t s = 0; s < signals.size(); ++s) log.signals[s].spec = signals[s];
  std::vector<std::pair<std::size_t, SignalSample>> in_flight;  // (signal, sample) published, not yet delivered
  std::vector<std::map<int64_t, SignalSample>> delivered(signals.size());  // by signal, by step
  std::mt19937 rng(7);
  const StepExecutor::OutputSink publish = [&](std::size_t signal, const SignalSample& sample) {
    log.record(signal, sample);
    in_flight.emplace_back(signal, sample);
  };
  const StepExecutor::RemoteInput read = [&](std::size_t signal, int64_t due, SignalSample& out) {
    out = delivered[signal].at(due);
  };
  int64_t stops = 0;
  const int64_t steps = whole.steps;
  while (sides[0].k <= steps || sides[1].k <= steps) {
    // Deliver some of what is in flight, in any order, or step a side as far as it can go.
    if (!in_flight.empty() && rng() % 3 == 0) {
      const std::size_t i = rng() % in_flight.size();
      const auto [signal, sample] = in_flight[i];
      in_flight.erase(in_flight.begin() + static_cast<std::ptrdiff_t>(i));
      delivered[signal][sample.step] = sample;
      continue;
    }
    Side& side = sides[rng() % 2];
    if (side.k > steps) continue;
    const auto have = [&](std::size_t signal, int64_t due) { return delivered[signal].count(due) != 0; };
    const std::size_t at = side.exec->step_from(side.k, side.cursor, have, read, publish);
    if (at < side.sc.components.size()) {
      side.cursor = at;
      ++stops;
    } else {
      side.cursor = 0;
      ++side.k;
    }
  }
  EXPECT_GT(stops, 0);  // the steps were indeed cut and resumed
  EXPECT_EQ(run_digest(log), run_digest(expected));
  for (std::size_t s = 0; s < signals.size(); ++s) {
    const SignalTrace* want = expected.find(signals[s].name);
    ASSERT_NE(want, nullptr) << signals[s].name;
    EXPECT_EQ(log.signals[s].steps, want->steps) << signals[s].name;
    EXPECT_EQ(log.signals[s].values, want->values) << signals[s].name;
  }
}

}  // namespace
}  // namespace plexus::scenario
