// naming: ros2 (naming.hpp, docs/ros2.md): the wire names, and endpoints of either vendor that
// meet under them while a default-named endpoint on the same domain does not.
#include <gtest/gtest.h>

#include "eventually.hpp"

#include <algorithm>
#include <chrono>
#include <string>
#include <thread>

#include "plexus/base/clock.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/msg/messages.hpp"
#include "plexus/runtime/naming.hpp"
#include "plexus/runtime/participant.hpp"

namespace plexus::rt {
namespace {

TEST(Naming, Ros2WireNamesAreRmwsMapping) {
  const auto& ts = msg::type_support<msg::PositionMeasurement>();
  const DdsNames n = dds_names(Naming::ros2, ts, "r1/position");
  EXPECT_EQ(n.topic, "rt/r1/position");
  EXPECT_EQ(n.type, "plexus_msgs::msg::dds_::PositionMeasurement_");
  const DdsNames p = dds_names(Naming::plexus, ts, "r1/position");
  EXPECT_EQ(p.topic, "r1/position");
  EXPECT_EQ(p.type, "plexus::msg::PositionMeasurement");
}

TEST(Naming, DiscoveredNamesMapBack) {
  EXPECT_EQ(plexus_topic(Naming::ros2, "rt/r1/position"), "r1/position");
  EXPECT_EQ(plexus_type(Naming::ros2, "plexus_msgs::msg::dds_::PositionMeasurement_"),
            "plexus::msg::PositionMeasurement");
  // Not of the naming's form (another naming's endpoint on the domain): left as it is.
  EXPECT_EQ(plexus_topic(Naming::ros2, "r1/position"), "r1/position");
  EXPECT_EQ(plexus_type(Naming::ros2, "plexus::msg::Pose2D"), "plexus::msg::Pose2D");
  EXPECT_EQ(plexus_topic(Naming::plexus, "rt/r1/position"), "rt/r1/position");
}

TEST(Naming, EveryTypeRoundTrips) {
  for (const msg::TypeSupport* ts : msg::all_type_supports())
    EXPECT_EQ(plexus_type(Naming::ros2, dds_names(Naming::ros2, *ts, "t").type), ts->type_name);
}

TEST(Naming, UnknownNamingIsOneLine) {
  try {
    parse_naming("ros", "dds.naming");
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "dds.naming: unknown naming 'ros' (expected plexus or ros2)");
  }
  EXPECT_EQ(parse_naming("ros2"), Naming::ros2);
  EXPECT_STREQ(to_string(Naming::plexus), "plexus");
}

struct NamingPair {
  Vendor pub, sub;
  int domain;  // each pair its own (167-170: no other test uses them), so ctest -j is safe
};

class NamingOnTheWire : public ::testing::TestWithParam<NamingPair> {
 protected:
  static std::unique_ptr<Participant> make(Vendor v, int domain, Naming naming, const std::string& name) {
    ParticipantOptions o;
    o.vendor = v;
    o.domain_id = domain;
    o.name = name;
    o.naming = naming;
    return Participant::create(o);
  }
  static bool eventually(const std::function<bool()>& cond, double seconds = 15) {
    return testing::eventually(cond, seconds);
  }
};

TEST_P(NamingOnTheWire, Ros2NamedEndpointsMeetAndMapBackWhileDefaultNamedOnesDoNot) {
  const NamingPair pr = GetParam();
  QosProfile q;
  q.name = "t";
  q.reliability = QosProfile::Reliability::reliable;
  auto pp = make(pr.pub, pr.domain, Naming::ros2, "ros2_pub");
  auto sp = make(pr.sub, pr.domain, Naming::ros2, "ros2_sub");
  auto plain = make(pr.sub, pr.domain, Naming::plexus, "plexus_sub");
  auto pub = pp->publisher<msg::Pose2D>("r9/pose", q);
  auto sub = sp->subscriber<msg::Pose2D>("r9/pose", q);
  auto other = plain->subscriber<msg::Pose2D>("r9/pose", q);
  ASSERT_TRUE(eventually([&] { return pub.matched_count() == 1 && sub.matched_count() == 1; }));
  msg::Pose2D m;
  m.x(4.25);
  ASSERT_TRUE(eventually([&] {
    pub.publish(m);
    msg::Pose2D got;
    return sub.take(got) && got.x() == 4.25;
  }));
  EXPECT_EQ(other.matched_count(), 0) << "a default-named reader matched a ROS 2-named writer";
  // The default-named participant sees the wire names; the ROS 2-named one plexus's.
  auto has = [](const std::vector<DiscoveredEndpoint>& eps, const std::string& topic, const std::string& type) {
    return std::any_of(eps.begin(), eps.end(), [&](const DiscoveredEndpoint& e) {
      return e.is_writer && !e.local && e.topic == topic && e.type_name == type;
    });
  };
  EXPECT_TRUE(
      eventually([&] { return has(plain->discovered_endpoints(), "rt/r9/pose", "plexus_msgs::msg::dds_::Pose2D_"); }));
  EXPECT_TRUE(eventually([&] { return has(sp->discovered_endpoints(), "r9/pose", "plexus::msg::Pose2D"); }));
}

// A name discovery cannot carry between the vendors (Fast DDS 2.9 drops announcements with
// names over 251 bytes): a participant's is cut, a topic's refused with the reason. Domains 152-153.
TEST(DiscoveryNames, LongTopicRefusedAndLongParticipantNameCut) {
  for (const auto& [vendor, domain] : {std::pair{Vendor::fast, 152}, std::pair{Vendor::cyclone, 153}}) {
    ParticipantOptions o;
    o.vendor = vendor;
    o.domain_id = domain;
    o.name = std::string(300, 'p');
    auto p = Participant::create(o);
    EXPECT_EQ(p->options().name.size(), Participant::kMaxDiscoveryName);
    QosProfile q;
    q.name = "t";
    const std::string ok(Participant::kMaxDiscoveryName, 't');
    EXPECT_NO_THROW(p->publisher<msg::Pose2D>(ok, q));
    try {
      p->publisher<msg::Pose2D>(ok + "t", q);
      ADD_FAILURE() << "a 252-byte topic name was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("is 252 bytes; DDS discovery between the vendors carries at most 251"),
                std::string::npos)
          << e.what();
    }
  }
}

// A topic name one vendor refuses (Cyclone DDS takes letters, digits, '_' and '/') is refused
// on both with one line, so a name never works with one vendor and fails in a mixed deployment.
TEST(DiscoveryNames, TopicNameWithACharacterOneVendorRefusesIsRefusedOnBoth) {
  for (const auto& [vendor, domain] : {std::pair{Vendor::fast, 152}, std::pair{Vendor::cyclone, 153}}) {
    ParticipantOptions o;
    o.vendor = vendor;
    o.domain_id = domain;
    auto p = Participant::create(o);
    QosProfile q;
    q.name = "t";
    EXPECT_NO_THROW(p->publisher<msg::Pose2D>("r_1/pose_2D", q));
    for (const std::string bad : {"r1/pose~x", "r1/pose-x", "r1.pose", "1r/pose", "r1 pose"}) {
      try {
        p->publisher<msg::Pose2D>(bad, q);
        ADD_FAILURE() << "topic name '" << bad << "' was accepted";
      } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("topic name '" + bad + "': DDS topic names between the vendors"),
                  std::string::npos)
            << e.what();
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    Vendors, NamingOnTheWire,
    ::testing::Values(NamingPair{Vendor::fast, Vendor::fast, 167}, NamingPair{Vendor::cyclone, Vendor::cyclone, 168},
                      NamingPair{Vendor::fast, Vendor::cyclone, 169}, NamingPair{Vendor::cyclone, Vendor::fast, 170}),
    [](const auto& pair) { return std::string(to_string(pair.param.pub)) + "_to_" + to_string(pair.param.sub); });

}  // namespace
}  // namespace plexus::rt
