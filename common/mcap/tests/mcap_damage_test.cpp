// Files cut short (a recorder killed mid-recording) and damaged: read up to the cut, or
// refused with one line naming the file, the byte and what is wrong; never a crash.
#include <sys/wait.h>

#include <csignal>
#include <cstring>

#include "byte_io.hpp"
#include "codec.hpp"
#include "mcap_test_support.hpp"

namespace plexus::mcap::test {
namespace {

class McapDamage : public ::testing::Test {
 protected:
  void SetUp() override {
    write_sample(whole_, 120, Compression::zstd, 1024);
    bytes_ = read_bytes(whole_);
  }
  void TearDown() override {
    std::filesystem::remove(whole_);
    std::filesystem::remove(damaged_);
  }
  /// Opens and reads the damaged copy: the messages read, or the error.
  std::string open_damaged(std::size_t& messages, std::string& cut) {
    messages = 0;
    cut.clear();
    return error_of([&] {
      const Reader r(damaged_);
      cut = r.cut_short();
      r.for_each_message([&](const MessageView&) { return ++messages, true; });
    });
  }
  std::string whole_ = temp_path("whole"), damaged_ = temp_path("damaged");
  std::vector<unsigned char> bytes_;
};

TEST_F(McapDamage, CutAtEveryByteReadsUpToTheCutOrSaysItIsEmpty) {
  std::size_t last = 0;
  for (std::size_t n = 0; n < bytes_.size(); ++n) {
    write_bytes(damaged_, bytes_, n);
    std::size_t messages = 0;
    std::string cut;
    const std::string error = open_damaged(messages, cut);
    if (n < 8 + 9 + 14) {  // before the header ends: nothing to read
      EXPECT_NE(error, "no error") << n;
      EXPECT_EQ(error.find('\n'), std::string::npos);
      continue;
    }
    ASSERT_EQ(error, "no error") << "cut at " << n;
    EXPECT_FALSE(cut.empty()) << "cut at " << n;
    EXPECT_GE(messages, last) << "cut at " << n;  // a longer prefix never loses a message
    last = messages;
  }
  EXPECT_EQ(last, 120u);  // the data section was complete before the summary started
  std::size_t messages = 0;
  std::string cut;
  write_bytes(damaged_, bytes_, bytes_.size());
  EXPECT_EQ(open_damaged(messages, cut), "no error");
  EXPECT_TRUE(cut.empty());
  EXPECT_EQ(messages, 120u);
}

TEST_F(McapDamage, AKilledWriterLeavesItsFlushedChunks) {
  const std::string path = temp_path("killed");
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {  // writes 100 messages, flushes, writes 7 more, waits to be killed
    WriterOptions o;
    Writer w(path, o);
    const uint16_t c = w.add_channel(0, "t", "cdr", {});
    for (uint32_t i = 0; i < 100; ++i) w.write(c, i, 10 + i, 10 + i, nullptr, 0);
    w.flush();
    for (uint32_t i = 100; i < 107; ++i) w.write(c, i, 10 + i, 10 + i, nullptr, 0);
    std::printf("ready\n");
    std::fflush(stdout);
    ::pause();
    ::_exit(0);
  }
  for (int i = 0; i < 500 && !std::filesystem::exists(path); ++i) ::usleep(10'000);
  // Wait for the flush: the file grows past its header and channel.
  for (int i = 0; i < 500 && std::filesystem::file_size(path) < 200; ++i) ::usleep(10'000);
  ::usleep(100'000);
  ::kill(child, SIGKILL);
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status));
  const Reader r(path);
  EXPECT_NE(r.cut_short().find("no footer"), std::string::npos) << r.cut_short();
  EXPECT_FALSE(r.from_summary());
  EXPECT_EQ(r.statistics().message_count, 100u);
  EXPECT_EQ(read_all(r).size(), 100u);
  std::filesystem::remove(path);
}

TEST_F(McapDamage, AFlippedByteAnywhereIsReadOrRefusedInOneLine) {
  for (std::size_t i = 0; i < bytes_.size(); ++i) {
    auto b = bytes_;
    b[i] ^= 0x5a;
    write_bytes(damaged_, b, b.size());
    std::size_t messages = 0;
    std::string cut;
    const std::string error = open_damaged(messages, cut);
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
    if (error != "no error") {
      EXPECT_EQ(error.rfind(damaged_ + ": ", 0), 0u) << error;
    }
  }
}

/// Replaces the bytes at `at` in a copy and returns the error of opening and reading it.
std::string damage(const std::string& whole, const std::string& damaged, std::size_t at,
                   std::vector<unsigned char> with) {
  auto b = read_bytes(whole);
  std::copy(with.begin(), with.end(), b.begin() + static_cast<std::ptrdiff_t>(at));
  write_bytes(damaged, b, b.size());
  return error_of([&] {
    const Reader r(damaged);
    r.for_each_message([](const MessageView&) { return true; });
  });
}

std::size_t first_record(const std::vector<unsigned char>& f, Op op) {
  std::size_t at = 8;
  while (at + 9 <= f.size() && f[at] != static_cast<uint8_t>(op)) {
    detail::Cursor c(f.data() + at + 1, 8, at, "record");
    at += 9 + c.u64();
  }
  return at;
}

TEST_F(McapDamage, NamedRefusals) {
  // Not MCAP at all; another major version.
  EXPECT_EQ(damage(whole_, damaged_, 0, {'S', 'Q', 'L'}),
            damaged_ + ": not an MCAP file (it does not start with the MCAP magic)");
  EXPECT_EQ(damage(whole_, damaged_, 5, {'1'}), damaged_ + ": MCAP major version '1' is not supported (0)");
  // A chunk's records changed: its CRC says so.
  const std::size_t chunk = first_record(bytes_, Op::chunk);
  const std::size_t inside = chunk + 9 + 8 + 8 + 8 + 4 + 4 + 4 + 8 + 20;  // inside its compressed records
  EXPECT_EQ(damage(whole_, damaged_, inside, {0x00, 0x00, 0x00}).rfind(damaged_ + ": corrupt MCAP: ", 0), 0u);
  // The summary changed: its CRC says so, on open.
  const std::size_t summary = first_record(bytes_, Op::data_end) + 13;
  EXPECT_EQ(damage(whole_, damaged_, summary + 12, {'X'}),
            damaged_ + ": corrupt MCAP: summary CRC mismatch (the summary changed since it was written) at byte " +
                std::to_string(summary));
  // An uncompressed chunk whose records no longer match its CRC.
  const std::string none = temp_path("none");
  {
    WriterOptions o;
    o.compression = Compression::none;
    Writer w(none, o);
    const uint16_t c = w.add_channel(0, "t", "cdr", {});
    w.write(c, 0, 1, 1, nullptr, 0);
  }
  auto b = read_bytes(none);
  const std::size_t c = first_record(b, Op::chunk);
  b[c + 9 + 24] ^= 0xff;  // the uncompressed CRC (after the start, end and size fields)
  write_bytes(damaged_, b, b.size());
  EXPECT_EQ(error_of([&] {
              const Reader r(damaged_);
              r.for_each_message([](const MessageView&) { return true; });
            }),
            damaged_ + ": corrupt MCAP: chunk CRC mismatch (its records changed since they were written) at byte " +
                std::to_string(c));
  std::filesystem::remove(none);
}

TEST_F(McapDamage, AChannelNamingAMissingSchemaIsRefused) {
  // Written by hand: header, a channel naming schema 7 that no record defines, no footer.
  std::vector<unsigned char> f(kMagic, kMagic + 8);
  detail::Builder b(f);
  auto at = b.begin_record(Op::header);
  b.str("");
  b.str("hand");
  b.end_record(at);
  const std::size_t channel = f.size();
  at = b.begin_record(Op::channel);
  b.u16(0);
  b.u16(7);
  b.str("t");
  b.str("cdr");
  b.u32(0);
  b.end_record(at);
  write_bytes(damaged_, f, f.size());
  EXPECT_EQ(error_of([&] { const Reader r(damaged_); }),
            damaged_ + ": corrupt MCAP: channel 0 ('t') names schema 7 before any schema record of that id at byte " +
                std::to_string(channel));
}

TEST_F(McapDamage, AChunkOfAnUnknownCompressionIsRefusedByName) {
  std::vector<unsigned char> f(kMagic, kMagic + 8);
  detail::Builder b(f);
  auto at = b.begin_record(Op::header);
  b.str("");
  b.str("hand");
  b.end_record(at);
  const std::size_t chunk = f.size();
  at = b.begin_record(Op::chunk);
  b.u64(1);
  b.u64(1);
  b.u64(4);
  b.u32(0);
  b.str("bz2");
  b.u64(4);
  b.u32(0);
  b.end_record(at);
  write_bytes(damaged_, f, f.size());
  EXPECT_EQ(error_of([&] { const Reader r(damaged_); }),
            damaged_ + ": corrupt MCAP: chunk compression 'bz2' is not supported (zstd, lz4 or none) at byte " +
                std::to_string(chunk));
}

TEST_F(McapDamage, AnEmptyOrMissingFileSaysSo) {
  write_bytes(damaged_, bytes_, 0);
  EXPECT_EQ(error_of([&] { const Reader r(damaged_); }), damaged_ + ": not an MCAP file (0 bytes, no MCAP magic)");
  write_bytes(damaged_, bytes_, 12);
  EXPECT_EQ(error_of([&] { const Reader r(damaged_); }),
            damaged_ + ": cut short before its header (12 bytes): an empty recording");
  EXPECT_EQ(error_of([] { const Reader r("/nonexistent/x.mcap"); }), "/nonexistent/x.mcap: no such file");
}

}  // namespace
}  // namespace plexus::mcap::test
