// ReaderBackend::take_raw on both vendors and mixed: the sample and its CDR as received
// (encapsulation header included), which recorders write to MCAP untouched.
#include <gtest/gtest.h>

#include "eventually.hpp"

#include <chrono>
#include <cstring>
#include <functional>
#include <thread>
#include <vector>

#include <dds/dds.h>
#include <dds/ddsi/ddsi_serdata.h>

#include "cyclone/cdr_sertype.hpp"
#include "cyclone/cyclone_participant.hpp"
#include "plexus/base/clock.hpp"
#include "plexus/msg/messages.hpp"
#include "plexus/runtime/participant.hpp"

namespace plexus::rt {
namespace {

struct Pair {
  Vendor pub, sub;
  int domain;  // each pair its own (157-160; TakeRawBytes 161-162: no other test uses them), so ctest -j is safe
};

class TakeRaw : public ::testing::TestWithParam<Pair> {};

static bool eventually(const std::function<bool()>& cond, double seconds = 15) {
  return testing::eventually(cond, seconds);
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
  // Transient-local: a Cyclone volatile reader may miss what a Fast DDS writer writes right
  // after both sides report the match (Cyclone keeps its first-sample guarantee for Cyclone
  // writers only: eclipse-cyclonedds/cyclonedds PR #188; one CI run lost sample 1 of
  // fast_to_cyclone that way). With the writer's history kept, the reader fetches it.
  q.durability = QosProfile::Durability::transient_local;
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

// A writer whose bytes a re-encoding would change: a Pose2D whose encapsulation options (bytes
// 2-3, which decoders do not read; plexus writes 0) are not 0. take_raw hands over the bytes
// as written, on either reader vendor; a recorder that re-encoded the decoded sample would
// write other ones. (Bytes past the type's maximum size cannot be the test: Fast DDS drops a
// payload larger than its history's.)
class TakeRawBytes : public ::testing::TestWithParam<std::pair<Vendor, int>> {};

TEST_P(TakeRawBytes, AreTheWritersNotARencoding) {
  auto make = [&](Vendor v, const char* name) {
    ParticipantOptions o;
    o.vendor = v;
    o.domain_id = GetParam().second;
    o.name = name;
    return Participant::create(o);
  };
  // The writer: a raw Cyclone DDS writer on plexus's own Cyclone participant (its loopback
  // configuration) and sertype, writing CDR bytes as given.
  auto wp = make(Vendor::cyclone, "raw_bytes_pub");
  const dds_entity_t participant = dynamic_cast<CycloneParticipant&>(*wp).handle();
  const auto& ts = msg::type_support<msg::Pose2D>();
  struct ddsi_sertype* st = detail::make_cdr_sertype(ts, ts.type_name);
  const dds_entity_t topic = dds_create_topic_sertype(participant, "raw/bytes", &st, nullptr, nullptr, nullptr);
  ASSERT_GT(topic, 0);
  dds_qos_t* qos = dds_create_qos();
  dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
  dds_qset_history(qos, DDS_HISTORY_KEEP_ALL, 0);
  const dds_data_representation_id_t xcdr1[] = {DDS_DATA_REPRESENTATION_XCDR1};
  dds_qset_data_representation(qos, 1, xcdr1);
  const dds_entity_t writer = dds_create_writer(participant, topic, qos, nullptr);
  dds_delete_qos(qos);
  ASSERT_GT(writer, 0);

  auto rp = make(GetParam().first, "raw_bytes_sub");
  QosProfile q;
  q.name = "t";
  q.reliability = QosProfile::Reliability::reliable;
  q.history = QosProfile::History::keep_all;
  auto reader = rp->make_reader(ts, "raw/bytes", q);
  dds_publication_matched_status_t matched{};
  ASSERT_TRUE(eventually([&] {
    dds_get_publication_matched_status(writer, &matched);
    return matched.current_count > 0 && reader->matched_count() > 0;
  }));

  msg::Pose2D m;
  m.header().seq_num(9);
  m.x(1.5);
  std::vector<unsigned char> wire(ts.max_cdr_size);
  wire.resize(ts.serialize(&m, wire.data(), wire.size()));
  wire[2] = 0x5a;  // options; the low 2 bits of byte 3 (XCDR1 padding) stay 0
  ddsrt_iovec_t iov{wire.data(), static_cast<ddsrt_iov_len_t>(wire.size())};
  struct ddsi_serdata* sd = ddsi_serdata_from_ser_iov(st, SDK_DATA, 1, &iov, wire.size());
  ASSERT_NE(sd, nullptr);
  ASSERT_GE(dds_writecdr(writer, sd), 0);

  msg::Pose2D got;
  std::vector<unsigned char> cdr;
  ASSERT_TRUE(eventually([&] { return reader->take_raw(&got, cdr, nullptr); }))
      << "malformed: " << reader->malformed_count();
  EXPECT_EQ(got.x(), 1.5);
  EXPECT_EQ(cdr, wire) << "take_raw did not hand over the bytes as received";
  dds_delete(writer);
}

INSTANTIATE_TEST_SUITE_P(Readers, TakeRawBytes,
                         ::testing::Values(std::pair{Vendor::cyclone, 161}, std::pair{Vendor::fast, 162}),
                         [](const ::testing::TestParamInfo<std::pair<Vendor, int>>& p) {
                           return std::string("cyclone_to_") + to_string(p.param.first);
                         });

INSTANTIATE_TEST_SUITE_P(Vendors, TakeRaw,
                         ::testing::Values(Pair{Vendor::fast, Vendor::fast, 157},
                                           Pair{Vendor::cyclone, Vendor::cyclone, 158},
                                           Pair{Vendor::fast, Vendor::cyclone, 159},
                                           Pair{Vendor::cyclone, Vendor::fast, 160}),
                         [](const ::testing::TestParamInfo<Pair>& p) {
                           return std::string(to_string(p.param.pub)) + "_to_" + to_string(p.param.sub);
                         });

}  // namespace
}  // namespace plexus::rt
