// Helpers for the in-process DDS tests of plexus_distributed (lockstep_errors_test.cpp,
// realtime_hold_test.cpp): a two-component scenario built from the test components of
// test_components.cpp, participants on loopback, bounded waits.
//
// DDS domains (CMakeLists.txt gives each group its RESOURCE_LOCK):
//   230  lockstep tests on Fast DDS     (they share the topic lockstep/clock: one at a time)
//   231  lockstep tests on Cyclone DDS  (idem)
//   232  realtime tests, both vendors   (each test its own robot name, so its own topics)
#pragma once

#include <unistd.h>

#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "plexus/base/clock.hpp"
#include "plexus/runtime/participant.hpp"
#include "plexus/runtime/qos.hpp"
#include "plexus/scenario/scenario.hpp"

namespace plexus::distributed::testing {

inline int lockstep_domain(rt::Vendor v) { return v == rt::Vendor::fast ? 230 : 231; }
inline constexpr int kRealtimeDomain = 232;

/// "fast" / "cyclone", for parameterised test names.
inline std::string vendor_name(const ::testing::TestParamInfo<rt::Vendor>& info) { return rt::to_string(info.param); }

/// A robot name no other test (or other run of this binary) uses: its signals' topics are
/// this test's own. Letters, digits and '_' only (a DDS topic name).
inline std::string unique_robot(const std::string& tag, rt::Vendor v) {
  return tag + "_" + rt::to_string(v) + "_" + std::to_string(getpid());
}

/// A robot `robot` with the echo plant, and the follower controller driving it:
///   signal 0: <robot>/truth/state, produced by '<robot>/plant'
///   signal 1: <robot>/cmd,         produced by 'follower'
inline scenario::Scenario two_component_scenario(const std::string& robot, const std::string& clock_yaml = "") {
  const std::string text =
      "name: t\n"
      "duration: 30.0\n"
      "step: 0.01\n"
      "seed: 1\n" +
      clock_yaml +
      "robots:\n"
      "  " +
      robot +
      ":\n"
      "    plant: {type: test_echo_plant}\n"
      "services:\n"
      "  follower: {type: test_follow_controller, robot: " +
      robot + "}\n";
  return scenario::load_scenario_text(text, "test.yaml");
}

/// The plant, an estimator of its state (`estimator`: estimate = truth/state) and a controller
/// that follows the estimate (`follower`): the chain through which a dead plant must stop the
/// controller (the estimator goes blind).
/// `estimator_keys`: more keys of the estimator's section (", blind_after_s: 0").
inline scenario::Scenario estimator_chain_scenario(const std::string& robot, const std::string& clock_yaml = "",
                                                   const std::string& estimator_keys = "") {
  const std::string text =
      "name: t\n"
      "duration: 30.0\n"
      "step: 0.01\n"
      "seed: 1\n" +
      clock_yaml +
      "robots:\n"
      "  " +
      robot +
      ":\n"
      "    plant: {type: test_echo_plant}\n"
      "services:\n"
      "  estimator: {type: test_pass_estimator, robot: " +
      robot + estimator_keys +
      "}\n"
      "  follower: {type: test_follow_controller, robot: " +
      robot + ", remap: {truth/state: " + robot + "/estimate}}\n";
  return scenario::load_scenario_text(text, "test.yaml");
}

/// `hosted` for the one component named `name` ("<robot>/plant", "follower"); "" hosts all.
inline std::vector<bool> hosting(const scenario::Scenario& sc, const std::string& name) {
  std::vector<bool> hosted(sc.components.size(), false);
  bool found = false;
  for (std::size_t i = 0; i < sc.components.size(); ++i)
    if (name.empty() || sc.components[i].component->name() == name) hosted[i] = found = true;
  EXPECT_TRUE(found) << "no component " << name;
  return hosted;
}

inline std::unique_ptr<rt::Participant> participant(rt::Vendor v, int domain, const std::string& name) {
  rt::ParticipantOptions o;  // network: loopback only, unicast discovery (the default)
  o.vendor = v;
  o.domain_id = domain;
  o.name = name;
  return rt::Participant::create(o);
}

/// deploy/qos.yaml of this source tree: the profiles `plexus launch` uses.
inline const rt::QosProfiles& profiles() {
  static const rt::QosProfiles p = rt::QosProfiles::load(std::string(PLEXUS_SOURCE_DIR) + "/deploy/qos.yaml");
  return p;
}

/// Polls `cond` until it holds or `seconds` pass (generous bounds: a loaded machine is slow,
/// never wrong); returns the last answer.
inline bool eventually(const std::function<bool()>& cond, double seconds = 20.0) {
  const int64_t end = monotonic_ns() + static_cast<int64_t>(seconds * 1e9);
  while (monotonic_ns() < end) {
    if (cond()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return cond();
}

/// The message of the `E` that `fn` throws; "no error" if it returns, "unexpected ...: what"
/// for another exception (so a worker thread reports instead of terminating the test).
template <class E, class F>
std::string error_of(F&& fn) {
  try {
    fn();
  } catch (const E& e) {
    return e.what();
  } catch (const std::exception& e) {
    return std::string("unexpected exception: ") + e.what();
  }
  return "no error";
}

}  // namespace plexus::distributed::testing
