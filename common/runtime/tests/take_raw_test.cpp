// ReaderBackend::take_raw on both vendors and mixed: the sample and its CDR as received
// (encapsulation header included), which recorders write to MCAP untouched.
#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <functional>
#include <thread>
#include <vector>

#include "plexus/base/clock.hpp"
#include "plexus/msg/messages.hpp"
#include "plexus/runtime/participant.hpp"

namespace plexus::rt {
namespace {

struct Pair {
  Vendor pub, sub;
  int domain;  // each pair its own (157-159, 172: no other test uses them), so ctest -j is safe
};

class TakeRaw : public ::testing::TestWithParam<Pair> {};

bool eventually(const std::function<bool()>& cond, double seconds = 15) {
  const int64_t end = monotonic_ns() + static_cast<int64_t>(seconds * 1e9);
  while (monotonic_ns() < end) {
    if (cond()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return cond();
}

TEST_P(TakeRaw, TheSampleAndItsBytesAsReceived) {
  auto make = [&](Vendor v, const char* name) {
    ParticipantOptions o;
    o.vendor = v;
    o.domain_id = GetParam().domain;
    o.name = name;
    return Participant::create(o);
  };
  auto pp = make(GetParam().pub, "raw_pub");
  auto sp = make(GetParam().sub, "raw_sub");
  QosProfile q;
  q.name = "t";
  q.reliability = QosProfile::Reliability::reliable;
  q.history = QosProfile::History::keep_all;
  auto pub = pp->publisher<msg::Pose2D>("raw/pose", q);
  const auto& ts = msg::type_support<msg::Pose2D>();
  auto reader = sp->make_reader(ts, "raw/pose", q);
  ASSERT_TRUE(eventually([&] { return pub.matched_count() > 0 && reader->matched_count() > 0; }));
  for (int i = 1; i <= 3; ++i) {
    msg::Pose2D m;
    m.x(i);
    m.y(-0.5 * i);
    m.theta(0.25);
    ASSERT_TRUE(pub.publish(m));
  }
  msg::Pose2D got;
  std::vector<unsigned char> cdr;
  cdr.reserve(ts.max_cdr_size);
  const unsigned char* storage = cdr.data();
  SampleMeta meta;
  for (int i = 1; i <= 3; ++i) {
    ASSERT_TRUE(eventually([&] { return reader->take_raw(&got, cdr, &meta); })) << "sample " << i;
    EXPECT_EQ(got.x(), i);
    EXPECT_GT(meta.receive_time_ns, 0);
    // XCDR1 little-endian (both vendors write it so), then the fields: the header's
    // sequence number first, and x at its aligned place after the 32-byte header.
    ASSERT_EQ(cdr.size(), 4u + 32u + 24u);
    EXPECT_EQ(cdr[0], 0x00);
    EXPECT_EQ(cdr[1], 0x01);
    EXPECT_EQ(cdr[4], static_cast<unsigned char>(i)) << "seq_num";
    double x = 0;
    std::memcpy(&x, cdr.data() + 4 + 32, 8);
    EXPECT_EQ(x, i);
    // The bytes decode to the sample take_raw handed over.
    msg::Pose2D again;
    ASSERT_TRUE(ts.deserialize(cdr.data(), cdr.size(), &again));
    EXPECT_EQ(again.header().publish_time_ns(), got.header().publish_time_ns());
    EXPECT_EQ(again.y(), got.y());
    EXPECT_EQ(cdr.data(), storage) << "take_raw allocated although the buffer had room";
  }
  EXPECT_FALSE(reader->take_raw(&got, cdr, &meta));
}

INSTANTIATE_TEST_SUITE_P(Vendors, TakeRaw,
                         ::testing::Values(Pair{Vendor::fast, Vendor::fast, 157}, Pair{Vendor::cyclone, Vendor::cyclone, 158},
                                           Pair{Vendor::fast, Vendor::cyclone, 159}, Pair{Vendor::cyclone, Vendor::fast, 172}),
                         [](const ::testing::TestParamInfo<Pair>& p) {
                           return std::string(to_string(p.param.pub)) + "_to_" + to_string(p.param.sub);
                         });

}  // namespace
}  // namespace plexus::rt
