// A plexus recording as MCAP (mcap_recording.hpp): what each channel, schema and message
// carries, a file cut short, files that are MCAP but not plexus recordings, and the
// choice of format.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "mcap_recording.hpp"
#include "plexus/base/input_error.hpp"
#include "replay_plan.hpp"
#include "sqlite_recording.hpp"
#include "tests/input_error_of.hpp"

namespace plexus::cli {
namespace {

using test_support::error_of;

class McapRecording : public ::testing::Test {
 protected:
  void SetUp() override {
    path_ = (std::filesystem::temp_directory_path() /
             ("plexus_mcap_recording_" + std::to_string(::getpid()) + "_" +
              ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".mcap"))
                .string();
    std::filesystem::remove(path_);
  }
  void TearDown() override {
    std::filesystem::remove(path_);
    std::filesystem::remove(path_ + ".cut");
  }

  /// Pose2D sample k: its CDR and header (seq k, data time k ms, origin and publish times).
  static std::vector<unsigned char> pose_cdr(int k, msg::StampHeader& h) {
    msg::Pose2D m;
    m.header().seq_num(static_cast<uint64_t>(k) + (1ull << 32));  // past 32 bits: MCAP keeps the low ones
    m.header().data_time_ns(k * 1'000'000);
    m.header().origin_time_ns(1'700'000'000'000'000'000 + k);
    m.header().publish_time_ns(1'700'000'000'000'500'000 + k);
    m.x(k);
    h = m.header();
    const auto& ts = msg::type_support<msg::Pose2D>();
    std::vector<unsigned char> cdr(ts.max_cdr_size);
    cdr.resize(ts.serialize(&m, cdr.data(), cdr.size()));
    return cdr;
  }

  /// 10 samples of r1/pose, received 1 ms apart; flush() after the first `flushed` (all: commit).
  void write(int flushed = 10) {
    RecordingOptions o;
    o.metadata = {{"recorder", "test"}};
    McapRecordingWriter w(path_, o);
    const auto& ts = msg::type_support<msg::Pose2D>();
    const int64_t id = w.add_topic("r1/pose", ts, R"({"reliability":"reliable"})");
    for (int k = 0; k < 10; ++k) {
      SampleBatch b;
      msg::StampHeader h;
      const auto cdr = pose_cdr(k, h);
      b.add(id, 1'700'000'000'001'000'000 + k * 1'000'000, &h, cdr.data(), cdr.size());
      w.insert(b);
      if (k + 1 == flushed) {
        w.flush();
        const auto bytes = read_bytes(path_);  // what a killed recorder leaves
        std::ofstream(path_ + ".cut", std::ios::binary)
            .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
      }
    }
    w.commit();
  }
  static std::vector<unsigned char> read_bytes(const std::string& p) {
    std::ifstream f(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
  }
  std::string path_;
};

TEST_F(McapRecording, ChannelSchemaAndMessagesCarryTheTypeTheQosAndTheBytesAsReceived) {
  write();
  const mcap::Reader raw(path_);
  ASSERT_EQ(raw.channels().size(), 1u);
  const mcap::Channel& ch = raw.channels().begin()->second;
  EXPECT_EQ(ch.topic, "r1/pose");
  EXPECT_EQ(ch.message_encoding, "cdr");
  EXPECT_EQ(ch.metadata.at("qos"), R"({"reliability":"reliable"})");
  const mcap::Schema& s = raw.schemas().at(ch.schema_id);
  EXPECT_EQ(s.name, "plexus::msg::Pose2D");
  EXPECT_EQ(s.encoding, "omgidl");
  EXPECT_EQ(s.data, std::string(msg::type_support<msg::Pose2D>().schema));
  ASSERT_EQ(raw.metadata().size(), 1u);
  EXPECT_EQ(raw.metadata()[0].name, "plexus");
  int k = 0;
  raw.for_each_message([&](const mcap::MessageView& m) {
    msg::StampHeader h;
    const auto cdr = pose_cdr(k, h);
    EXPECT_EQ(std::vector<unsigned char>(m.data, m.data + m.size), cdr);
    EXPECT_EQ(m.sequence, static_cast<uint32_t>(k));
    EXPECT_EQ(m.log_time, 1'700'000'000'001'000'000ull + k * 1'000'000ull);
    EXPECT_EQ(m.publish_time, static_cast<uint64_t>(h.publish_time_ns()));
    ++k;
    return true;
  });
  EXPECT_EQ(k, 10);

  const auto rec = open_recording(path_);
  ASSERT_EQ(rec->topics().size(), 1u);
  EXPECT_EQ(rec->topics()[0].type, "plexus::msg::Pose2D");
  EXPECT_EQ(rec->topics()[0].qos_json, R"({"reliability":"reliable"})");
  EXPECT_EQ(rec->message_count(), 10);
  EXPECT_TRUE(rec->cut_short().empty());
  k = 0;
  rec->for_each([&](const RecordedMessage& m) {
    EXPECT_EQ(m.seq_num, static_cast<int64_t>(k + (1ll << 32))) << "the full seq_num, from the CDR";
    EXPECT_EQ(m.data_time_ns, k * 1'000'000);
    EXPECT_EQ(m.origin_time_ns, 1'700'000'000'000'000'000 + k);
    EXPECT_EQ(m.publish_time_ns, 1'700'000'000'000'500'000 + k);
    ++k;
    return true;
  });
  const RecordingInfo info = rec->info();
  EXPECT_TRUE(info.from_summary);
  EXPECT_EQ(info.compression, "zstd");
  EXPECT_EQ(info.metadata.at("recorder"), "test");
  EXPECT_EQ(info.topics.at(0).messages, 10u);
  EXPECT_EQ(info.end_ns - info.start_ns, 9'000'000);
}

TEST_F(McapRecording, ACutShortRecordingReplaysUpToTheCut) {
  write(6);
  const auto rec = open_recording(path_ + ".cut");
  EXPECT_NE(rec->cut_short().find("no footer"), std::string::npos) << rec->cut_short();
  EXPECT_EQ(rec->message_count(), 6);
  const auto plan = plan_replay_topics(*rec, path_ + ".cut", {}, nullptr, false);
  ASSERT_EQ(plan.size(), 1u);
  EXPECT_EQ(plan[0].qos.reliability, rt::QosProfile::Reliability::reliable);
  const auto summary = summarize_recording(*rec);
  EXPECT_EQ(summary.at(0).count, 6u);
}

TEST_F(McapRecording, AnMcapFileThatIsNotAPlexusRecordingIsRefusedByName) {
  {
    mcap::Writer w(path_);
    w.add_channel(0, "tf", "json", {});
  }
  EXPECT_EQ(error_of([&] { open_recording(path_); }),
            path_ + ": not a plexus recording: channel 0 ('tf'): message encoding 'json', not cdr");
  {
    mcap::Writer w(path_);
    w.add_channel(0, "tf", "cdr", {});
  }
  EXPECT_EQ(error_of([&] { open_recording(path_); }),
            path_ + ": not a plexus recording: channel 0 ('tf'): no schema, so no type");
  {
    mcap::Writer w(path_);
    const uint16_t s = w.add_schema("plexus::msg::Pose2D", "omgidl", "");
    w.add_channel(s, "a", "cdr", {});
    w.add_channel(s, "a", "cdr", {});
  }
  EXPECT_EQ(error_of([&] { open_recording(path_); }), path_ + ": not a plexus recording: topic 'a' twice");
}

TEST_F(McapRecording, CreatingTheWriterLeavesAnExistingFileUntilATopicIsRecorded) {
  std::ofstream(path_) << "precious";
  { McapRecordingWriter w(path_, {}); }
  std::ifstream in(path_);
  std::string s;
  in >> s;
  EXPECT_EQ(s, "precious");
  EXPECT_EQ(error_of([] { McapRecordingWriter w("/nonexistent/dir/x.mcap", {}); }),
            "/nonexistent/dir/x.mcap: cannot create recording (No such file or directory)");
  EXPECT_FALSE(std::filesystem::exists("/nonexistent/dir/x.mcap"));
}

TEST(RecordingFormat, ByOptionOrFileName) {
  EXPECT_EQ(recording_format("run.mcap", ""), RecordingFormat::mcap);
  EXPECT_EQ(recording_format("run", ""), RecordingFormat::mcap);
  EXPECT_EQ(recording_format("run.sqlite", ""), RecordingFormat::sqlite);
  EXPECT_EQ(recording_format("run.db3", ""), RecordingFormat::sqlite);
  EXPECT_EQ(recording_format("run.sqlite", "mcap"), RecordingFormat::mcap);
  EXPECT_EQ(error_of([] { recording_format("x", "bag"); }),
            "--format: 'bag' is not a recording format (mcap or sqlite)");
  EXPECT_EQ(error_of([] { recording_compression("bz2"); }),
            "--compression: 'bz2' is not a chunk compression (zstd, lz4 or none)");
}

TEST(HeaderFromCdr, EitherEndianness) {
  std::vector<unsigned char> le(36, 0), be(36, 0);
  le[1] = 0x01;
  le[4] = 7;          // seq_num 7
  le[12 + 1] = 0x01;  // data time 256
  be[4 + 7] = 7;
  be[12 + 6] = 0x01;
  msg::StampHeader a, b;
  ASSERT_TRUE(header_from_cdr(le.data(), le.size(), a));
  ASSERT_TRUE(header_from_cdr(be.data(), be.size(), b));
  EXPECT_EQ(a.seq_num(), 7u);
  EXPECT_EQ(a.data_time_ns(), 256);
  EXPECT_EQ(b.seq_num(), 7u);
  EXPECT_EQ(b.data_time_ns(), 256);
  EXPECT_FALSE(header_from_cdr(le.data(), 35, a));
  le[1] = 0x07;  // XCDR2: not plain CDR
  EXPECT_FALSE(header_from_cdr(le.data(), le.size(), a));
}

}  // namespace
}  // namespace plexus::cli
