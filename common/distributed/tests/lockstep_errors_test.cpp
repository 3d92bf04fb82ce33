// Lockstep error paths over DDS (loopback, in process), on both vendors: a run that cannot
// go on fails within its bounded wait with a LockstepError naming what is missing: the
// signal and its producer, the hosts, or the clock.
//
// The scenario (dds_test_support.hpp): <robot>/plant (test_echo_plant) produces signal 0
// <robot>/truth/state; 'follower' (test_follow_controller) produces signal 1 <robot>/cmd.
// Each test runs the clock and the hosts it needs, each on its own participant, with
// timeouts of 0.5 .. 1 s; waits on DDS discovery are generous (20 s) and never timed.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <limits>
#include <string>
#include <thread>

#include "dds_test_support.hpp"
#include "plexus/distributed/lockstep.hpp"
#include "plexus/distributed/wire.hpp"

namespace plexus::distributed::testing {
namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

class LockstepErrors : public ::testing::TestWithParam<rt::Vendor> {
 protected:
  rt::Vendor vendor() const { return GetParam(); }
  std::unique_ptr<rt::Participant> make(const std::string& name) {
    return participant(vendor(), lockstep_domain(vendor()), name);
  }
  static const rt::QosProfile& qos() { return profiles().get("lockstep"); }
};

// A signal whose producer runs nowhere: the clock, waiting for its sample of step 0, fails
// after its timeout naming the signal, the producer and the step.
TEST_P(LockstepErrors, ClockFailsNamingTheSignalNobodyProduces) {
  const std::string robot = unique_robot("ls_noplant", vendor());
  auto sc_clock = two_component_scenario(robot);
  auto sc_host = two_component_scenario(robot);
  auto p_clock = make("clock");
  auto p_host = make("host follower");
  // The follower's host runs; the plant (signal 0, the first the clock waits for) does not.
  LockstepHost host(sc_host, hosting(sc_host, "follower"), *p_host, qos(), {.timeout_s = 1.0});
  LockstepClock clock(sc_clock, *p_clock, qos(), {.timeout_s = 1.0});
  std::atomic<bool> stop{false};
  std::string host_error;
  std::thread host_thread([&] { host_error = error_of<LockstepError>([&] { host.run(stop); }); });
  const std::string clock_error = error_of<LockstepError>([&] { clock.run(stop); });
  stop = true;
  host_thread.join();
  EXPECT_TRUE(contains(clock_error, "no sample of '" + robot + "/truth/state' from '" + robot + "/plant' for step 0"))
      << clock_error;
  // The host either saw step 0 and timed out on the same input, or never got that far.
  EXPECT_TRUE(host_error == "no error" || contains(host_error, "'" + robot + "/truth/state'")) << host_error;
}

// A host whose remote input never comes fails naming it, its producer and the step it
// waited for (here the plant's command at step 1, the controller's sample of step 0).
TEST_P(LockstepErrors, HostFailsNamingTheInputThatNeverCame) {
  const std::string robot = unique_robot("ls_nocmd", vendor());
  auto sc_clock = two_component_scenario(robot);
  auto sc_host = two_component_scenario(robot);
  auto p_clock = make("clock");
  auto p_host = make("host plant");
  LockstepHost host(sc_host, hosting(sc_host, robot + "/plant"), *p_host, qos(), {.timeout_s = 1.0});
  // The clock waits longer than the host, so the host's own timeout is what fails the run.
  LockstepClock clock(sc_clock, *p_clock, qos(), {.timeout_s = 30.0});
  std::atomic<bool> stop{false};
  // Discovery first (the host gives up on a silent clock after 3 s): once the host and the
  // plant's writer have joined, wait_ready names the one producer that never will.
  std::string ready;
  ASSERT_TRUE(eventually([&] {
    ready = error_of<LockstepError>([&] { clock.wait_ready(1, 0.5, stop); });
    return contains(ready, "the producer of '" + robot + "/cmd'");
  })) << ready;
  std::string clock_error;
  std::thread clock_thread([&] { clock_error = error_of<LockstepError>([&] { clock.run(stop); }); });
  const std::string host_error = error_of<LockstepError>([&] { host.run(stop); });
  stop = true;  // the clock, still waiting for the command, gives up at once
  clock_thread.join();
  EXPECT_TRUE(contains(host_error, "no sample of '" + robot + "/cmd' (produced by 'follower') for step 0"))
      << host_error;
  EXPECT_TRUE(contains(clock_error, "'" + robot + "/cmd'")) << clock_error;
}

// Before the run: wait_ready names the producer that never joined, and the missing hosts.
TEST_P(LockstepErrors, WaitReadyNamesTheMissingProducerAndHosts) {
  const std::string robot = unique_robot("ls_ready", vendor());
  auto sc_clock = two_component_scenario(robot);
  auto sc_host = two_component_scenario(robot);
  auto p_clock = make("clock");
  auto p_host = make("host follower");
  LockstepHost host(sc_host, hosting(sc_host, "follower"), *p_host, qos(), {.timeout_s = 1.0});
  LockstepClock clock(sc_clock, *p_clock, qos(), {.timeout_s = 1.0});
  const std::atomic<bool> stop{false};
  // Until discovery has matched the one host, wait_ready says the host is missing; then it
  // names the plant, whose producer no process runs.
  std::string error;
  EXPECT_TRUE(eventually([&] {
    error = error_of<LockstepError>([&] { clock.wait_ready(1, 0.5, stop); });
    return !contains(error, "hosts did not join");
  })) << error;
  EXPECT_TRUE(contains(error, "the producer of '" + robot + "/truth/state' ('" + robot + "/plant') did not join"))
      << error;
  error = error_of<LockstepError>([&] { clock.wait_ready(2, 0.5, stop); });
  EXPECT_TRUE(contains(error, "1 of 2 hosts did not join")) << error;
}

// No clock at all: the host stops after 3 timeouts saying so, not that a clock "stopped".
TEST_P(LockstepErrors, HostWithoutAClockStopsSayingSo) {
  const std::string robot = unique_robot("ls_noclock", vendor());
  auto sc = two_component_scenario(robot);
  auto p = make("host all");
  LockstepHost host(sc, hosting(sc, ""), *p, qos(), {.timeout_s = 0.5});
  const std::atomic<bool> stop{false};
  const std::string error = error_of<LockstepError>([&] { host.run(stop); });
  EXPECT_TRUE(contains(error, "no clock")) << error;
  EXPECT_TRUE(contains(error, "lockstep/clock")) << error;
  EXPECT_FALSE(contains(error, "stopped")) << error;
}

// A clock that stepped and fell silent: the host stops naming the step it waits to run.
TEST_P(LockstepErrors, HostWhoseClockFallsSilentStops) {
  const std::string robot = unique_robot("ls_silent", vendor());
  auto sc = two_component_scenario(robot);
  auto p_host = make("host all");
  auto p_clock = make("one tick");
  LockstepHost host(sc, hosting(sc, ""), *p_host, qos(), {.timeout_s = 0.5, .lead_steps = 8});
  auto tick_pub = p_clock->publisher<msg::ClockStep>(kClockTopic, qos());
  ASSERT_TRUE(eventually([&] { return tick_pub.matched_count() > 0; }));
  msg::ClockStep tick;
  tick.step_index(0);
  tick.step_ns(step_ns(sc));
  ASSERT_TRUE(tick_pub.publish(tick));
  ASSERT_TRUE(tick_pub.wait_for_acks(20'000'000'000));  // in the host's reader before it runs
  const std::atomic<bool> stop{false};
  const std::string error = error_of<LockstepError>([&] { host.run(stop); });
  // ClockStep 0 with a lead of 8 allows steps 0..8: the host waits to run step 9.
  EXPECT_TRUE(contains(error, "the clock stopped at step 9")) << error;
}

// A sample refused at the edge (a NaN) fails the run at once, naming the signal, its
// producer and the step; so does a sample of another step than the clock's.
TEST_P(LockstepErrors, ClockRefusesANonFiniteSampleNamingItsSignal) {
  const std::string robot = unique_robot("ls_nan", vendor());
  auto sc_clock = two_component_scenario(robot);
  auto sc_peer = two_component_scenario(robot);
  auto p_clock = make("clock");
  auto p_peer = make("bad plant");
  LockstepClock clock(sc_clock, *p_clock, qos(), {.timeout_s = 30.0});
  ASSERT_EQ(sc_peer.signals[0].name, robot + "/truth/state");
  WirePublisher plant(*p_peer, sc_peer.signals[0], step_ns(sc_peer), qos());  // transient local: kept for the clock
  scenario::SignalSample s;
  s.step = 0;
  s.values[0] = 1.0;
  s.values[1] = std::numeric_limits<double>::quiet_NaN();
  ASSERT_TRUE(plant.publish(s, 0));
  const std::atomic<bool> stop{false};
  const std::string error = error_of<LockstepError>([&] { clock.run(stop); });
  EXPECT_TRUE(
      contains(error, "refused the sample of '" + robot + "/truth/state' from '" + robot + "/plant' for step 0"))
      << error;
}

TEST_P(LockstepErrors, ClockFailsOnASampleOfAnotherStep) {
  const std::string robot = unique_robot("ls_order", vendor());
  auto sc_clock = two_component_scenario(robot);
  auto sc_peer = two_component_scenario(robot);
  auto p_clock = make("clock");
  auto p_peer = make("early plant");
  LockstepClock clock(sc_clock, *p_clock, qos(), {.timeout_s = 30.0});
  WirePublisher plant(*p_peer, sc_peer.signals[0], step_ns(sc_peer), qos());
  scenario::SignalSample s;
  s.step = 3;  // the clock is at step 0
  ASSERT_TRUE(plant.publish(s, 0));
  const std::atomic<bool> stop{false};
  const std::string error = error_of<LockstepError>([&] { clock.run(stop); });
  EXPECT_TRUE(contains(error, "'" + robot + "/truth/state' sent step 3 while the clock is at step 0")) << error;
}

INSTANTIATE_TEST_SUITE_P(Dds, LockstepErrors, ::testing::Values(rt::Vendor::fast, rt::Vendor::cyclone), vendor_name);

}  // namespace
}  // namespace plexus::distributed::testing
