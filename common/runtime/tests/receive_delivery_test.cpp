// Receive-thread delivery (Subscriber::on_sample) on both vendors and mixed: every sample,
// in order, on a vendor thread (across processes or vendors), never two calls at once;
// samples that arrived before the callback was set are delivered too. No timing asserts.
#include <gtest/gtest.h>

#include "eventually.hpp"

#include <atomic>
#include <chrono>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include "plexus/base/clock.hpp"
#include "plexus/runtime/participant.hpp"

namespace plexus::rt {
namespace {

struct Pair {
  Vendor pub, sub;
  int domain;  // each pair its own (151-154: no other test uses them), so ctest -j is safe
};

class ReceiveDelivery : public ::testing::TestWithParam<Pair> {
 protected:
  std::unique_ptr<Participant> make(Vendor v, const std::string& name) {
    ParticipantOptions o;
    o.vendor = v;
    o.domain_id = GetParam().domain;
    o.name = name;
    return Participant::create(o);
  }
  static QosProfile reliable() {
    QosProfile q;
    q.name = "t";
    q.reliability = QosProfile::Reliability::reliable;
    q.history = QosProfile::History::keep_all;
    q.depth = 100;
    return q;
  }
  static bool eventually(const std::function<bool()>& cond, double seconds = 15) {
    return testing::eventually(cond, seconds);
  }
};

TEST_P(ReceiveDelivery, EverySampleInOrderOnAVendorThread) {
  auto pp = make(GetParam().pub, "delivery_pub");
  auto sp = make(GetParam().sub, "delivery_sub");
  auto pub = pp->publisher<msg::Pose2D>("delivery/order", reliable());
  auto sub = sp->subscriber<msg::Pose2D>("delivery/order", reliable());
  std::mutex mu;
  std::vector<double> got;
  bool other_thread = true, stamped = true;
  std::atomic<int> inside{0}, overlapped{0};
  const auto test_thread = std::this_thread::get_id();
  sub.on_sample([&](msg::Pose2D& m, const SampleMeta& meta) {
    if (inside.fetch_add(1) != 0) ++overlapped;
    {
      std::lock_guard lk(mu);
      got.push_back(m.x());
      if (std::this_thread::get_id() == test_thread) other_thread = false;
      if (meta.receive_time_ns == 0) stamped = false;
    }
    inside.fetch_sub(1);
  });
  ASSERT_TRUE(eventually([&] { return pub.matched_count() > 0 && sub.matched_count() > 0; }));
  constexpr int kCount = 50;
  for (int i = 1; i <= kCount; ++i) {
    msg::Pose2D m;
    m.x(i);
    ASSERT_TRUE(pub.publish(m));
  }
  ASSERT_TRUE(eventually([&] {
    std::lock_guard lk(mu);
    return got.size() >= kCount;
  }));
  std::lock_guard lk(mu);
  ASSERT_EQ(got.size(), static_cast<std::size_t>(kCount));
  for (int i = 0; i < kCount; ++i) EXPECT_EQ(got[static_cast<std::size_t>(i)], i + 1);
  EXPECT_TRUE(stamped);
  // Across vendors the sample comes over UDP: a receive thread delivers it. Within one
  // vendor in one process, both deliver locally on the writer's thread (inside publish()).
  if (GetParam().pub != GetParam().sub) {
    EXPECT_TRUE(other_thread) << "delivered on the test thread";
  }
  EXPECT_EQ(overlapped, 0);
}

TEST_P(ReceiveDelivery, SamplesQueuedBeforeTheCallbackAreDelivered) {
  auto pp = make(GetParam().pub, "queued_pub");
  auto sp = make(GetParam().sub, "queued_sub");
  auto pub = pp->publisher<msg::Pose2D>("delivery/queued", reliable());
  auto sub = sp->subscriber<msg::Pose2D>("delivery/queued", reliable());
  ASSERT_TRUE(eventually([&] { return pub.matched_count() > 0 && sub.matched_count() > 0; }));
  for (int i = 1; i <= 3; ++i) {
    msg::Pose2D m;
    m.x(i);
    ASSERT_TRUE(pub.publish(m));
  }
  ASSERT_TRUE(pub.wait_for_acks(5'000'000'000));
  std::mutex mu;
  std::vector<double> got;
  sub.on_sample([&](msg::Pose2D& m, const SampleMeta&) {
    std::lock_guard lk(mu);
    got.push_back(m.x());
  });
  msg::Pose2D m;
  m.x(4);
  ASSERT_TRUE(pub.publish(m));
  ASSERT_TRUE(eventually([&] {
    std::lock_guard lk(mu);
    return got.size() >= 4;
  }));
  std::lock_guard lk(mu);
  EXPECT_EQ(got, (std::vector<double>{1, 2, 3, 4}));
}

INSTANTIATE_TEST_SUITE_P(Vendors, ReceiveDelivery,
                         ::testing::Values(Pair{Vendor::fast, Vendor::fast, 151},
                                           Pair{Vendor::cyclone, Vendor::cyclone, 152},
                                           Pair{Vendor::fast, Vendor::cyclone, 153},
                                           Pair{Vendor::cyclone, Vendor::fast, 154}),
                         [](const ::testing::TestParamInfo<Pair>& p) {
                           return std::string(to_string(p.param.pub)) + "_to_" + to_string(p.param.sub);
                         });

}  // namespace
}  // namespace plexus::rt
