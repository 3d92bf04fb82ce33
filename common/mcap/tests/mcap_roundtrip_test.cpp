// The MCAP writer and reader together (writer.hpp, reader.hpp), and the layout the
// specification asks for (https://mcap.dev/spec), checked on the bytes.
#include <algorithm>
#include <cstring>

#include "byte_io.hpp"
#include "codec.hpp"
#include "mcap_test_support.hpp"

namespace plexus::mcap::test {
namespace {

class McapRoundTrip : public ::testing::TestWithParam<Compression> {
 protected:
  void TearDown() override { std::filesystem::remove(path_); }
  std::string path_ = temp_path(compression_name(GetParam()));
};

TEST_P(McapRoundTrip, EveryMessageComesBackWithItsChannelTimesAndBytes) {
  const Statistics written = write_sample(path_, 500, GetParam());
  const Reader r(path_);
  EXPECT_TRUE(r.cut_short().empty()) << r.cut_short();
  EXPECT_TRUE(r.from_summary());
  ASSERT_EQ(r.channels().size(), 2u);
  EXPECT_EQ(r.channels().at(0).topic, "r1/pose");
  EXPECT_EQ(r.channels().at(0).metadata.at("qos"), "{\"reliability\":\"reliable\"}");
  EXPECT_EQ(r.schemas().at(r.channels().at(0).schema_id).name, "plexus::msg::Pose2D");
  EXPECT_EQ(r.schemas().at(1).encoding, "omgidl");
  EXPECT_EQ(r.statistics().message_count, 500u);
  EXPECT_EQ(r.statistics().channel_message_counts.at(1), 167u);  // i % 3 == 0
  EXPECT_EQ(r.statistics().chunk_count, written.chunk_count);
  EXPECT_GT(written.chunk_count, 5u);  // small chunks: the merge across chunks is exercised
  ASSERT_EQ(r.metadata().size(), 1u);
  EXPECT_EQ(r.metadata()[0].entries.at("recorder"), "test");
  const auto all = read_all(r);
  ASSERT_EQ(all.size(), 500u);
  for (uint32_t i = 0; i < 500; ++i) {
    EXPECT_EQ(all[i].sequence, i);
    EXPECT_EQ(all[i].topic, i % 3 == 0 ? "r2/pose" : "r1/pose");
    EXPECT_EQ(all[i].log_time, 1000 + 10ull * i);
    EXPECT_EQ(all[i].publish_time, 1000 + 10ull * i - 3);
    EXPECT_EQ(all[i].data, payload(i));
  }
}

INSTANTIATE_TEST_SUITE_P(Compressions, McapRoundTrip,
                         ::testing::Values(Compression::zstd, Compression::lz4, Compression::none), [](const auto& p) {
                           return std::string(p.param == Compression::none ? "none" : compression_name(p.param));
                         });

TEST(Mcap, TopicsAndCountsComeFromTheSummaryWithoutReadingAChunk) {
  const std::string path = temp_path("a");
  write_sample(path, 300);
  const Reader r(path);
  EXPECT_TRUE(r.from_summary());
  EXPECT_EQ(r.chunks_read(), 0u);
  EXPECT_EQ(r.statistics().message_count, 300u);
  EXPECT_EQ(r.channels().size(), 2u);
  std::filesystem::remove(path);
}

TEST(Mcap, ATimeRangeReadsOnlyTheChunksThatOverlapIt) {
  const std::string path = temp_path("a");
  const Statistics st = write_sample(path, 1000);
  const Reader r(path);
  const auto some = read_all(r, 1000 + 10 * 400, 1000 + 10 * 420);
  ASSERT_EQ(some.size(), 21u);
  EXPECT_EQ(some.front().sequence, 400u);
  EXPECT_EQ(some.back().sequence, 420u);
  EXPECT_LT(r.chunks_read(), 4u) << "of " << st.chunk_count;
  std::filesystem::remove(path);
}

TEST(Mcap, MessagesOutOfOrderAcrossChunksComeOutInLogTimeOrder) {
  const std::string path = temp_path("a");
  {
    WriterOptions o;
    o.chunk_size = 1024;
    Writer w(path, o);
    const uint16_t c = w.add_channel(0, "t", "cdr", {});
    // Two interleaved time series written one after the other: chunks overlap in time.
    for (uint32_t i = 0; i < 200; ++i) w.write(c, i, 100 + 2ull * i, 0, nullptr, 0);
    for (uint32_t i = 0; i < 200; ++i) w.write(c, 1000 + i, 101 + 2ull * i, 0, nullptr, 0);
  }
  const Reader r(path);
  const auto all = read_all(r);
  ASSERT_EQ(all.size(), 400u);
  EXPECT_TRUE(
      std::is_sorted(all.begin(), all.end(), [](const Read& a, const Read& b) { return a.log_time < b.log_time; }));
  EXPECT_EQ(all[0].sequence, 0u);
  EXPECT_EQ(all[1].sequence, 1000u);
  std::filesystem::remove(path);
}

TEST(Mcap, AFileWithoutMessagesIsComplete) {
  const std::string path = temp_path("a");
  write_sample(path, 0);
  const Reader r(path);
  EXPECT_TRUE(r.cut_short().empty());
  EXPECT_EQ(r.statistics().message_count, 0u);
  EXPECT_EQ(r.channels().size(), 2u);
  EXPECT_TRUE(read_all(r).empty());
  std::filesystem::remove(path);
}

TEST(Mcap, TheSameSchemaTwiceIsOneSchema) {
  const std::string path = temp_path("a");
  Writer w(path);
  EXPECT_EQ(w.add_schema("a", "omgidl", "x"), 1);
  EXPECT_EQ(w.add_schema("b", "omgidl", "x"), 2);
  EXPECT_EQ(w.add_schema("a", "omgidl", "x"), 1);
  w.close();
  std::filesystem::remove(path);
}

TEST(Mcap, BadWriterOptionsAreRefusedByName) {
  WriterOptions o;
  o.zstd_level = 30;
  EXPECT_EQ(error_of([&] { validate(o); }), "zstd level: must be in 1..19, got 30");
  o = {};
  o.chunk_size = 10;
  EXPECT_EQ(error_of([&] { validate(o); }), "chunk size: must be in 1 KiB..64 MiB, got 10 bytes");
  EXPECT_EQ(error_of([] { Writer w("/nonexistent/dir/x.mcap"); }),
            "/nonexistent/dir/x.mcap: cannot create recording (No such file or directory)");
}

// The layout on the bytes, as the specification describes it.
TEST(Mcap, TheFileHasTheLayoutOfTheSpecification) {
  const std::string path = temp_path("a");
  write_sample(path, 200, Compression::zstd);
  const auto f = read_bytes(path);
  ASSERT_GT(f.size(), 100u);
  EXPECT_EQ(std::memcmp(f.data(), kMagic, 8), 0);
  EXPECT_EQ(std::memcmp(f.data() + f.size() - 8, kMagic, 8), 0);
  EXPECT_EQ(f[8], static_cast<uint8_t>(Op::header));
  // Footer: the last record, 20 bytes: summary start, summary offset start, CRC.
  const std::size_t footer = f.size() - 8 - 29;
  detail::Cursor fc(f.data() + footer, 29, footer, "footer");
  ASSERT_EQ(fc.u8(), static_cast<uint8_t>(Op::footer));
  ASSERT_EQ(fc.u64(), 20u);
  const uint64_t summary_start = fc.u64(), summary_offset_start = fc.u64();
  const uint32_t crc = fc.u32();
  EXPECT_EQ(crc, detail::crc32_update(0, f.data() + summary_start, footer + 1 + 8 + 16 - summary_start));
  // Data End right before the summary, its CRC over everything before it.
  ASSERT_EQ(f[summary_start - 13], static_cast<uint8_t>(Op::data_end));
  detail::Cursor de(f.data() + summary_start - 12, 12, 0, "data end");
  EXPECT_EQ(de.u64(), 4u);
  EXPECT_EQ(de.u32(), detail::crc32_update(0, f.data(), summary_start - 13));
  // Walk the data section: every chunk is followed by one message index per channel in it,
  // each entry pointing at a message record of that channel and time in the decompressed chunk.
  std::size_t at = 8 + 9 + (f[9] | (f[10] << 8));  // header length fits one byte here
  int chunks = 0, indexes = 0;
  std::vector<unsigned char> records;
  while (f[at] != static_cast<uint8_t>(Op::data_end)) {
    detail::Cursor c(f.data() + at, f.size() - at, at, "record");
    const uint8_t op = c.u8();
    const uint64_t len = c.u64();
    detail::Cursor body(c.take(len, "body"), len, at + 9, "record");
    if (op == static_cast<uint8_t>(Op::chunk)) {
      ++chunks;
      body.u64();
      body.u64();
      const uint64_t size = body.u64();
      const uint32_t ccrc = body.u32();
      EXPECT_EQ(body.str("compression"), "zstd");
      const uint64_t n = body.u64();
      records.resize(size);
      detail::decompress("zstd", body.take(n, "records"), n, records.data(), size);
      EXPECT_EQ(ccrc, detail::crc32_update(0, records.data(), size));
    } else if (op == static_cast<uint8_t>(Op::message_index)) {
      ++indexes;
      const uint16_t channel = body.u16();
      const uint32_t bytes = body.u32();
      for (uint32_t k = 0; k < bytes / 16; ++k) {
        const uint64_t time = body.u64(), off = body.u64();
        ASSERT_LT(off + 9 + 18, records.size());
        detail::Cursor m(records.data() + off, records.size() - off, off, "message");
        EXPECT_EQ(m.u8(), static_cast<uint8_t>(Op::message));
        m.u64();
        EXPECT_EQ(m.u16(), channel);
        m.u32();
        EXPECT_EQ(m.u64(), time);
      }
    }
    at += 9 + len;
  }
  EXPECT_GT(chunks, 3);
  EXPECT_EQ(indexes, 2 * chunks);  // both channels in every chunk
  // Summary: grouped by opcode, then one summary offset per group pointing at it.
  std::vector<uint8_t> ops;
  at = summary_start;
  while (at < summary_offset_start) {
    ops.push_back(f[at]);
    detail::Cursor c(f.data() + at + 1, 8, at, "record");
    at += 9 + c.u64();
  }
  EXPECT_TRUE(std::is_sorted(ops.begin(), ops.end(), [](uint8_t a, uint8_t b) {
    auto rank = [](uint8_t o) { return o == 3 ? 0 : o == 4 ? 1 : o == 11 ? 2 : o == 8 ? 3 : 4; };
    return rank(a) < rank(b);
  }));
  int groups = 0;
  while (at < footer) {
    detail::Cursor c(f.data() + at, footer - at, at, "summary offset");
    ASSERT_EQ(c.u8(), static_cast<uint8_t>(Op::summary_offset));
    ASSERT_EQ(c.u64(), 17u);
    const uint8_t op = c.u8();
    const uint64_t start = c.u64();
    EXPECT_EQ(f[start], op);
    c.u64();
    at += 26;
    ++groups;
  }
  EXPECT_EQ(groups, 5);  // schema, channel, statistics, chunk index, metadata index
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace plexus::mcap::test
