// Realtime mode, stale inputs, over DDS (loopback, in process), on both vendors: a
// RealtimeHost runs one component of the scenario of dds_test_support.hpp while the test
// plays the other process, publishing the component's input (stamped now, as a native
// producer does) and reading its output.
//
//  - a controller uses a fresh input; with a stale one (never received, or older than
//    clock.input_deadline_periods periods) it runs hold(): its safe output, all zero; it
//    recovers once the input is fresh again; every hold is counted in the report;
//  - a plant whose command is stale gets the zero command (and does not hold);
//  - an estimator with no fresh measurement is blind: it publishes nothing, and a controller
//    reading it in the same process holds (so a dead plant stops every loop);
//  - an estimator whose samples arrive after its tick computes each step from the sample of
//    that step (it runs once the sample has arrived), not from the one before.
//
// The deadline is 10 periods of 10 ms, far above a loaded machine's scheduling hiccups;
// every wait is on a condition with a generous bound, never on a duration.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <string>
#include <thread>

#include "dds_test_support.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/distributed/lockstep.hpp"
#include "plexus/distributed/realtime.hpp"
#include "plexus/distributed/wire.hpp"

namespace plexus::distributed::testing {
namespace {

const std::string kRealtime = "clock: {mode: realtime, input_deadline_periods: 10}\n";

/// The other process's output: publishes {a, b} on a signal every 2 ms while it is on,
/// stamped with the wall clock (the host's grid puts it on the current step).
class Feeder {
 public:
  Feeder(rt::Participant& p, const scenario::SignalSpec& spec, int64_t step_ns)
      : pub_(p, spec, step_ns, profiles().get("state")), thread_([this] { loop(); }) {}
  ~Feeder() {
    quit_ = true;
    thread_.join();
  }
  void send(double a, double b) {
    a_ = a;
    b_ = b;
    on_ = true;
  }
  /// Stops publishing: the input goes stale at the host.
  void pause() { on_ = false; }

 private:
  void loop() {
    scenario::SignalSample s;
    while (!quit_) {
      if (on_) {
        s.values[0] = a_;
        s.values[1] = b_;
        pub_.publish_at(s, wall_time_ns(), 0);
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
  }
  WirePublisher pub_;
  std::atomic<bool> on_{false}, quit_{false};
  std::atomic<double> a_{0}, b_{0};
  std::thread thread_;  // last: starts once the rest is built
};

/// The latest sample the host published on a signal.
class Latest {
 public:
  Latest(rt::Participant& p, const scenario::SignalSpec& spec, int64_t step_ns)
      : sub_(p, spec, step_ns, profiles().get("state")) {}
  /// True when the latest sample so far has fields 0 and 1 equal to {a, b}.
  bool is(double a, double b) {
    drain();
    return last_.step >= 0 && last_.values[0] == a && last_.values[1] == b;
  }
  /// True when nothing has arrived for `seconds` (the host stopped publishing).
  bool silent_for(double seconds) {
    drain();
    return monotonic_ns() - received_ns_ > static_cast<int64_t>(seconds * 1e9);
  }
  void drain() {
    while (const void* m = sub_.take()) {
      std::size_t bad = 0;
      scenario::SignalSample s;
      received_ns_ = monotonic_ns();
      if (sub_.wire().decode(m, s, bad) == Rejection::none) last_ = s;
    }
  }
  std::string describe() const {
    return last_.step < 0 ? "nothing received"
                          : "{" + std::to_string(last_.values[0]) + ", " + std::to_string(last_.values[1]) + "}";
  }

 private:
  WireSubscriber sub_;
  scenario::SignalSample last_;
  int64_t received_ns_ = 0;
};

class RealtimeHold : public ::testing::TestWithParam<rt::Vendor> {
 protected:
  rt::Vendor vendor() const { return GetParam(); }
  std::unique_ptr<rt::Participant> make(const std::string& name) {
    return participant(vendor(), kRealtimeDomain, name);
  }
};

/// Runs `host` on a thread until stopped; the report and any error afterwards.
class HostThread {
 public:
  explicit HostThread(RealtimeHost& host)
      : thread_([this, &host] { error_ = error_of<InputError>([&] { report_ = host.run(stop_); }); }) {}
  ~HostThread() { join(); }
  void join() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
  }
  const RealtimeReport& report() const { return report_; }
  const std::string& error() const { return error_; }

 private:
  std::atomic<bool> stop_{false};
  RealtimeReport report_;
  std::string error_;
  std::thread thread_;  // last
};

TEST_P(RealtimeHold, ControllerHoldsItsSafeOutputWhileItsInputIsStale) {
  const std::string robot = unique_robot("rt_ctl", vendor());
  auto sc_host = two_component_scenario(robot, kRealtime);
  auto sc_peer = two_component_scenario(robot, kRealtime);
  auto p_host = make("host follower");
  auto p_peer = make("plant");
  RealtimeOptions opt;
  opt.service = "rt_ctl_" + std::string(rt::to_string(vendor()));
  RealtimeHost host(sc_host, hosting(sc_host, "follower"), *p_host, profiles(), opt);
  ASSERT_EQ(sc_peer.signals[0].name, robot + "/truth/state");
  ASSERT_EQ(sc_peer.signals[1].name, robot + "/cmd");
  Feeder state(*p_peer, sc_peer.signals[0], step_ns(sc_peer));
  Latest cmd(*p_peer, sc_peer.signals[1], step_ns(sc_peer));
  HostThread run(host);

  // Never received: stale, the controller holds (follower's step() would give omega 0.5).
  EXPECT_TRUE(eventually([&] { return cmd.is(0.0, 0.0); })) << cmd.describe();
  // Fresh: used (v = the plant's x).
  state.send(2.5, 0.0);
  EXPECT_TRUE(eventually([&] { return cmd.is(2.5, 0.5); })) << cmd.describe();
  // Older than 10 periods: held again, not computed from the last sample.
  state.pause();
  EXPECT_TRUE(eventually([&] { return cmd.is(0.0, 0.0); })) << cmd.describe();
  // Fresh again: recovers by itself.
  state.send(4.0, 0.0);
  EXPECT_TRUE(eventually([&] { return cmd.is(4.0, 0.5); })) << cmd.describe();

  run.join();
  EXPECT_EQ(run.error(), "no error");
  EXPECT_GT(run.report().ticks, 0);
  EXPECT_GT(run.report().holds, 0u);
  // One input: every stale read made that step a hold.
  EXPECT_EQ(run.report().holds, run.report().stale_inputs);
}

TEST_P(RealtimeHold, PlantGetsTheZeroCommandWhileItsCommandIsStale) {
  const std::string robot = unique_robot("rt_plant", vendor());
  auto sc_host = two_component_scenario(robot, kRealtime);
  auto sc_peer = two_component_scenario(robot, kRealtime);
  auto p_host = make("host plant");
  auto p_peer = make("controller");
  RealtimeOptions opt;
  opt.service = "rt_plant_" + std::string(rt::to_string(vendor()));
  RealtimeHost host(sc_host, hosting(sc_host, robot + "/plant"), *p_host, profiles(), opt);
  Feeder cmd(*p_peer, sc_peer.signals[1], step_ns(sc_peer));
  Latest state(*p_peer, sc_peer.signals[0], step_ns(sc_peer));
  HostThread run(host);

  // The echo plant's state is its command: fresh, it is the one sent.
  cmd.send(1.5, -0.25);
  EXPECT_TRUE(eventually([&] { return state.is(1.5, -0.25); })) << state.describe();
  // Stale: the zero command (a motor controller's watchdog), not the last one received.
  cmd.pause();
  EXPECT_TRUE(eventually([&] { return state.is(0.0, 0.0); })) << state.describe();
  cmd.send(-1.0, 0.75);
  EXPECT_TRUE(eventually([&] { return state.is(-1.0, 0.75); })) << state.describe();

  run.join();
  EXPECT_EQ(run.error(), "no error");
  EXPECT_GT(run.report().stale_inputs, 0u);
  EXPECT_EQ(run.report().holds, 0u);  // only controllers hold
}

/// An estimator hosted alone, fed a measurement that then stops: its estimate must fall
/// silent (it is blind) and come back with the measurement. `clock` and `estimator_keys` as
/// for estimator_chain_scenario.
void expect_blind_estimator_falls_silent(rt::Vendor v, const std::string& tag, const std::string& clock,
                                         const std::string& estimator_keys) {
  const std::string robot = unique_robot(tag, v);
  auto sc_host = estimator_chain_scenario(robot, clock, estimator_keys);
  auto sc_peer = estimator_chain_scenario(robot, clock);
  auto p_host = participant(v, kRealtimeDomain, "host estimator");
  auto p_peer = participant(v, kRealtimeDomain, "plant and controller");
  RealtimeOptions opt;
  opt.service = tag + "_" + std::string(rt::to_string(v));
  RealtimeHost host(sc_host, hosting(sc_host, "estimator"), *p_host, profiles(), opt);
  ASSERT_EQ(sc_peer.signals[1].name, robot + "/estimate");
  Feeder state(*p_peer, sc_peer.signals[0], step_ns(sc_peer));
  Latest estimate(*p_peer, sc_peer.signals[1], step_ns(sc_peer));
  HostThread run(host);

  state.send(2.5, 1.0);
  EXPECT_TRUE(eventually([&] { return estimate.is(2.5, 1.0); })) << estimate.describe();
  state.pause();
  EXPECT_TRUE(eventually([&] { return estimate.silent_for(0.5); })) << "still publishing: " << estimate.describe();
  state.send(-3.0, 2.0);
  EXPECT_TRUE(eventually([&] { return estimate.is(-3.0, 2.0); })) << estimate.describe();

  run.join();
  EXPECT_EQ(run.error(), "no error");
  EXPECT_GT(run.report().blind_steps, 0u);
  EXPECT_EQ(run.report().holds, 0u);  // an estimator does not hold
}

// The measurement goes stale (10 periods) and, after the clock's grace (0.3 s), the estimator
// stops publishing. Before blind estimators it went on publishing its last estimate, and the
// stream never fell silent.
TEST_P(RealtimeHold, EstimatorWithoutFreshMeasurementPublishesNothing) {
  expect_blind_estimator_falls_silent(vendor(), "rt_est", kRealtime, "");
}

// An estimator's own blind_after_s overrides the scenario's: with the clock's grace of 60 s
// the estimator would go on publishing its prediction for a minute (longer than `eventually`
// waits); its own grace of 0 makes it silent once its measurement is stale (issue 33, item 5).
TEST_P(RealtimeHold, EstimatorsOwnBlindGraceOverridesTheClocks) {
  expect_blind_estimator_falls_silent(vendor(), "rt_grace",
                                      "clock: {mode: realtime, input_deadline_periods: 10, blind_after_s: 60}\n",
                                      ", blind_after_s: 0");
}

TEST_P(RealtimeHold, ControllerHoldsBehindABlindEstimatorInItsProcess) {
  const std::string robot = unique_robot("rt_chain", vendor());
  auto sc_host = estimator_chain_scenario(robot, kRealtime);
  auto sc_peer = estimator_chain_scenario(robot, kRealtime);
  auto p_host = make("host estimator and follower");
  auto p_peer = make("plant");
  RealtimeOptions opt;
  opt.service = "rt_chain_" + std::string(rt::to_string(vendor()));
  std::vector<bool> both = hosting(sc_host, "estimator");
  const std::vector<bool> follower = hosting(sc_host, "follower");
  for (std::size_t i = 0; i < both.size(); ++i) both[i] = both[i] || follower[i];
  RealtimeHost host(sc_host, both, *p_host, profiles(), opt);
  ASSERT_EQ(sc_peer.signals[2].name, robot + "/cmd");
  Feeder state(*p_peer, sc_peer.signals[0], step_ns(sc_peer));
  Latest cmd(*p_peer, sc_peer.signals[2], step_ns(sc_peer));
  HostThread run(host);

  state.send(2.5, 0.0);
  EXPECT_TRUE(eventually([&] { return cmd.is(2.5, 0.5); })) << cmd.describe();
  // The plant goes silent: the estimate, passed in memory, is blind, so the controller holds
  // instead of following the last estimate for ever.
  state.pause();
  EXPECT_TRUE(eventually([&] { return cmd.is(0.0, 0.0); })) << cmd.describe();
  state.send(4.0, 0.0);
  EXPECT_TRUE(eventually([&] { return cmd.is(4.0, 0.5); })) << cmd.describe();

  run.join();
  EXPECT_EQ(run.error(), "no error");
  EXPECT_GT(run.report().blind_steps, 0u);
  EXPECT_GT(run.report().holds, 0u);
}

/// A producer whose samples arrive `delay` after their own time: every 1 ms it publishes a
/// sample stamped `delay` ago, carrying that data time (ns modulo 1000 s, in seconds) in x.
class DelayedFeeder {
 public:
  DelayedFeeder(rt::Participant& p, const scenario::SignalSpec& spec, int64_t step_ns, int64_t delay_ns)
      : pub_(p, spec, step_ns, profiles().get("state")), delay_ns_(delay_ns), thread_([this] { loop(); }) {}
  ~DelayedFeeder() {
    quit_ = true;
    thread_.join();
  }

 private:
  void loop() {
    scenario::SignalSample s;
    while (!quit_) {
      const int64_t taken = wall_time_ns() - delay_ns_;
      s.values[0] = static_cast<double>(taken % kWrapNs) * 1e-9;
      pub_.publish_at(s, taken, 0);
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  }
  static constexpr int64_t kWrapNs = 1'000'000'000'000;
  WirePublisher pub_;
  int64_t delay_ns_;
  std::atomic<bool> quit_{false};
  std::thread thread_;  // last
};

TEST_P(RealtimeHold, EstimatorUsesALateSampleAtItsOwnStep) {
  // Every sample arrives 8.5 ms (0.85 periods) after its time, so at the estimator's tick
  // (a quarter period after its step's time) the sample of that step has not arrived: a read
  // of the newest sample would give the one of the step before, at every step. The host runs
  // the estimator's step once its sample has arrived (the next tick), so the estimate of each
  // step is computed from the sample of that step: its x (the sample's data time) lies within
  // one period of the estimate's own data time (the first sample that rounds to the step, half
  // a period before it), where the sample of the step before lies 1.5 periods away.
  const std::string robot = unique_robot("rt_late", vendor());
  auto sc_host = estimator_chain_scenario(robot, kRealtime);
  auto sc_peer = estimator_chain_scenario(robot, kRealtime);
  auto p_host = make("host estimator");
  auto p_peer = make("late plant");
  RealtimeOptions opt;
  opt.service = "rt_late_" + std::string(rt::to_string(vendor()));
  RealtimeHost host(sc_host, hosting(sc_host, "estimator"), *p_host, profiles(), opt);
  WireSubscriber estimate(*p_peer, sc_peer.signals[1], step_ns(sc_peer), profiles().get("state"));
  DelayedFeeder state(*p_peer, sc_peer.signals[0], step_ns(sc_peer), 8'500'000);
  HostThread run(host);

  int own = 0, other = 0;
  const int64_t period = step_ns(sc_peer);
  EXPECT_TRUE(eventually([&] {
    while (const void* m = estimate.take()) {
      scenario::SignalSample s;
      std::size_t bad = 0;
      if (estimate.wire().decode(m, s, bad) != Rejection::none || s.values[0] == 0.0) continue;
      const int64_t at = estimate.header().data_time_ns() % 1'000'000'000'000;
      const int64_t used = std::llround(s.values[0] * 1e9);
      ++(std::abs(at - used) < period ? own : other);  // own step's sample: 4-5 ms apart; the one before: 14-15 ms
    }
    return own + other >= 200;
  })) << own
      << " estimates from their own step's sample, " << other << " from another";
  run.join();
  EXPECT_EQ(run.error(), "no error");
  // A loaded machine may delay a sample past the next tick too (then read late): most are not.
  EXPECT_GE(own, 4 * other) << own << " estimates from their own step's sample, " << other << " from another";
  EXPECT_GT(run.report().deferred_steps, 0u);
}

// A process grouped by type hosts many components and is named after all of them: its
// heartbeat topic is cut to the discovery limit, and the cut name must still be a topic
// Cyclone DDS creates (a '~' in it stopped a 50-robot fleet by type at start: "cannot create
// topic 'health/component_host_r1_reference...~8c18...': Bad Parameter"). Domain 154.
TEST_P(RealtimeHold, HeartbeatTopicOfAProcessWithManyComponentsIsCreated) {
  std::string service = "component_host ";
  for (int r = 1; r <= 50; ++r) service += "r" + std::to_string(r) + "_reference,";
  const std::string topic = health_topic(service);
  EXPECT_LE(topic.size() + rt::kRos2TopicPrefix.size(), rt::Participant::kMaxDiscoveryName);
  auto p = participant(GetParam(), 154, service);
  EXPECT_NO_THROW(p->publisher<msg::Heartbeat>(topic, profiles().get("health"))) << topic;
}

INSTANTIATE_TEST_SUITE_P(Dds, RealtimeHold, ::testing::Values(rt::Vendor::fast, rt::Vendor::cyclone), vendor_name);

}  // namespace
}  // namespace plexus::distributed::testing
