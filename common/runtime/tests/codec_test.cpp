// Message round trips: every type through the Fast CDR codec and through the Cyclone
// serdata path, which must give back the same object and the same bytes.
#include <dds/dds.h>
#include <dds/ddsi/ddsi_serdata.h>
#include <gtest/gtest.h>

#include <cstring>
#include <tuple>
#include <vector>

#include "cyclone/cdr_sertype.hpp"
#include "plexus/msg/messages.hpp"

namespace plexus::rt {
namespace {

template <class T>
void round_trip() {
  const auto& ts = msg::type_support<T>();
  SCOPED_TRACE(ts.type_name);
  T a;
  // A non-trivial sample: every byte of the payload set (finite doubles).
  std::vector<unsigned char> buf(ts.max_cdr_size);
  const std::size_t n = ts.serialize(&a, buf.data(), buf.size());
  ASSERT_GT(n, 4u + 32u);
  for (std::size_t i = 4; i < n; ++i) buf[i] = static_cast<unsigned char>(0x31 + i % 50);
  ASSERT_TRUE(ts.deserialize(buf.data(), n, &a));

  // Fast CDR: T -> bytes -> T.
  T b;
  std::vector<unsigned char> b1(ts.max_cdr_size), b2(ts.max_cdr_size);
  const std::size_t n1 = ts.serialize(&a, b1.data(), b1.size());
  ASSERT_TRUE(ts.deserialize(b1.data(), n1, &b));
  EXPECT_TRUE(a == b);
  EXPECT_EQ(b1[0], 0x00);  // XCDR1 little-endian encapsulation: 00 01 00 00
  EXPECT_EQ(b1[1], 0x01);

  // Cyclone: T -> serdata -> wire bytes -> serdata -> T.
  struct ddsi_sertype* st = detail::make_cdr_sertype(ts, ts.type_name);
  struct ddsi_serdata* sd = detail::serdata_from_sample(st, &a);
  ASSERT_NE(sd, nullptr);
  const uint32_t size = ddsi_serdata_size(sd);
  ASSERT_EQ(size, n1);
  ddsi_serdata_to_ser(sd, 0, size, b2.data());
  EXPECT_EQ(0, std::memcmp(b1.data(), b2.data(), n1));
  ddsrt_iovec_t iov{b2.data(), static_cast<ddsrt_iov_len_t>(size)};
  struct ddsi_serdata* sd2 = ddsi_serdata_from_ser_iov(st, SDK_DATA, 1, &iov, size);
  T c;
  EXPECT_TRUE(detail::serdata_to_sample(sd2, &c));
  EXPECT_TRUE(a == c);
  ddsi_serdata_unref(sd);
  ddsi_serdata_unref(sd2);
  st->ops->free(st);

  // Truncated data is rejected, never half-decoded into a "valid" sample.
  T d;
  EXPECT_FALSE(ts.deserialize(b1.data(), n1 / 2, &d));
}

TEST(MessageCodec, EveryTypeRoundTripsThroughBothVendors) {
  std::apply([](auto... t) { (round_trip<decltype(t)>(), ...); }, msg::AllTopicTypes{});
}

TEST(MessageCodec, TypeNamesAreScopedAndMatchTheCycloneDescriptor) {
  const auto& ts = msg::type_support<msg::Pose2D>();
  EXPECT_STREQ(ts.type_name, "plexus::msg::Pose2D");
  EXPECT_STREQ(reinterpret_cast<const dds_topic_descriptor_t*>(ts.cyclone_descriptor)->m_typename, ts.type_name);
  EXPECT_EQ(reinterpret_cast<const dds_topic_descriptor_t*>(ts.cyclone_descriptor)->m_nkeys, 0u);
}

}  // namespace
}  // namespace plexus::rt
