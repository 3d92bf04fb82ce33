#include "plexus/runtime/qos.hpp"

#include <gtest/gtest.h>

#include "plexus/base/input_error.hpp"
#include "plexus/runtime/vendor.hpp"

namespace plexus::rt {
namespace {

std::string error_of(auto&& fn) {
  try {
    fn();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(QosProfiles, ParsesEveryPolicy) {
  const auto p = QosProfiles::parse(
      "profiles:\n  a:\n    reliability: best_effort\n    durability: transient_local\n    history: keep_all\n"
      "    depth: 4\n    deadline_s: 0.5\n    liveliness: manual_by_topic\n    liveliness_lease_s: 2\n"
      "    lifespan_s: 3\n    latency_budget_s: 0.001\n    max_blocking_time_s: 0.2\n",
      "q.yaml");
  const auto& a = p.get("a");
  EXPECT_EQ(a.reliability, QosProfile::Reliability::best_effort);
  EXPECT_EQ(a.durability, QosProfile::Durability::transient_local);
  EXPECT_EQ(a.history, QosProfile::History::keep_all);
  EXPECT_EQ(a.depth, 4);
  EXPECT_DOUBLE_EQ(a.deadline_s, 0.5);
  EXPECT_EQ(a.liveliness, QosProfile::Liveliness::manual_by_topic);
  EXPECT_DOUBLE_EQ(a.liveliness_lease_s, 2);
  EXPECT_DOUBLE_EQ(a.lifespan_s, 3);
  EXPECT_DOUBLE_EQ(a.latency_budget_s, 0.001);
  EXPECT_DOUBLE_EQ(a.max_blocking_time_s, 0.2);
}

TEST(QosProfiles, ErrorsNameFileLineAndKey) {
  EXPECT_EQ(error_of([] { QosProfiles::parse("profiles:\n  a:\n    reliability: sometimes\n", "q.yaml"); }),
            "q.yaml:3: profiles.a.reliability: unknown value 'sometimes' (expected best_effort, reliable)");
  EXPECT_EQ(error_of([] { QosProfiles::parse("profiles:\n  a:\n    deadline_s: -1\n", "q.yaml"); }),
            "q.yaml:3: profiles.a.deadline_s: must be >= 0 seconds (0 means infinite/none), got -1.000000");
  // Beyond what the vendors hold (Fast DDS: int32 seconds; below 1 ns: 0): the deadline
  // reached an undefined float-to-int32 conversion in the Fast DDS back end.
  EXPECT_EQ(error_of([] { QosProfiles::parse("profiles:\n  a:\n    deadline_s: 1e10\n", "q.yaml"); }),
            "q.yaml:3: profiles.a.deadline_s: must be 0 (infinite/none) or within [1e-9, 1e9] seconds, got 1e+10");
  EXPECT_EQ(error_of([] { QosProfiles::parse("profiles:\n  a:\n    lifespan_s: 1e-12\n", "q.yaml"); }),
            "q.yaml:3: profiles.a.lifespan_s: must be 0 (infinite/none) or within [1e-9, 1e9] seconds, got 1e-12");
  EXPECT_NO_THROW(QosProfiles::parse("profiles:\n  a:\n    liveliness_lease_s: 1e9\n    lifespan_s: 1e-9\n", "q.yaml"));
  EXPECT_EQ(error_of([] { QosProfiles::parse("profile:\n  a: {}\n", "q.yaml"); }),
            "q.yaml:1: profiles: required key is missing");
  EXPECT_EQ(error_of([] { QosProfiles::parse("profiles:\n  a:\n    depth: x\n", "q.yaml"); }),
            "q.yaml:3: profiles.a.depth: expected an integer, got 'x'");
  EXPECT_EQ(error_of([] { QosProfiles::parse("profiles:\n  a: {}\n", "q.yaml").get("b"); }),
            "q.yaml: unknown QoS profile 'b' (known: a)");
}

TEST(QosProfiles, RepositoryFileIsValid) {
  const auto p = QosProfiles::load(PLEXUS_SOURCE_DIR "/deploy/qos.yaml");
  for (const char* name : {"sensor", "command", "state", "latched", "health", "latency"}) EXPECT_TRUE(p.contains(name));
}

TEST(Vendor, ParsesKnownNamesAndRejectsOthers) {
  EXPECT_EQ(parse_vendor("fast"), Vendor::fast);
  EXPECT_EQ(parse_vendor("cyclonedds"), Vendor::cyclone);
  EXPECT_EQ(error_of([] { parse_vendor("rti", "scenario.yaml:3: dds.vendor"); }),
            "scenario.yaml:3: dds.vendor: unknown DDS vendor 'rti' (expected fast or cyclone)");
}

}  // namespace
}  // namespace plexus::rt
