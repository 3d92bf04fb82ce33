// The decode and print paths of every message type on input a remote writer controls, apart
// from codec_test.cpp: Fast DDS's headers and Cyclone DDS's (its PID_* macros) do not mix in
// one file.
#include <fastdds/rtps/common/SerializedPayload.h>
#include <gtest/gtest.h>
#include <fastdds/dds/topic/TopicDataType.hpp>

#include <nlohmann/json.hpp>

#include <cstring>
#include <deque>
#include <memory>
#include <string>
#include <vector>

#include "plexus/msg/checked_fast_type.hpp"
#include "plexus/msg/messages.hpp"
#include "plexus/runtime/participant.hpp"

namespace plexus::rt {
namespace {

// The generated Fast DDS decoder lets Fast CDR's BadParamException out (an encapsulation that
// does not start with a zero byte), through DataReader::take_next_sample into the service; and
// Fast DDS hands a sample whose decode failed to the reader as valid (both found by fuzzing the
// subscriber edge: tests/fuzz, cdr_decode). So every type's Fast DDS decoder fails without
// throwing and flags the failure for the reader (checked_fast_type.hpp).
TEST(MessageCodec, FastDecoderFailsWithoutThrowingAndFlagsTheFailure) {
  const auto decode = [](const msg::TypeSupport& ts, std::vector<unsigned char> bytes) {
    const std::unique_ptr<eprosima::fastdds::dds::TopicDataType> type(ts.make_fast_type());
    eprosima::fastrtps::rtps::SerializedPayload_t payload(static_cast<uint32_t>(bytes.size()));
    std::memcpy(payload.data, bytes.data(), bytes.size());
    payload.length = static_cast<uint32_t>(bytes.size());
    void* sample = ts.create();
    bool ok = false;
    EXPECT_NO_THROW(ok = type->deserialize(&payload, sample)) << ts.type_name;
    ts.destroy(sample);
    return ok;
  };
  for (const msg::TypeSupport* ts : msg::all_type_supports()) {
    msg::take_fast_decode_failure();
    EXPECT_FALSE(decode(*ts, {0x01, 0x00, 0x00, 0x00, 0, 0, 0, 0})) << ts->type_name;  // not a CDR encapsulation
    EXPECT_TRUE(msg::take_fast_decode_failure()) << ts->type_name;
    EXPECT_FALSE(msg::take_fast_decode_failure()) << ts->type_name;              // taking it clears it
    EXPECT_FALSE(decode(*ts, {0x00, 0x01, 0x00, 0x00, 1, 2})) << ts->type_name;  // truncated
    EXPECT_TRUE(msg::take_fast_decode_failure()) << ts->type_name;
    void* good = ts->create();
    std::vector<unsigned char> bytes(ts->max_cdr_size);
    bytes.resize(ts->serialize(good, bytes.data(), bytes.size()));
    ts->destroy(good);
    EXPECT_TRUE(decode(*ts, bytes)) << ts->type_name;
    EXPECT_FALSE(msg::take_fast_decode_failure()) << ts->type_name;
  }
}

// Found by fuzzing: a char[N] member holding bytes that are not UTF-8 made the sample's JSON
// throw when printed, which ended `plexus topic echo`.
TEST(MessageCodec, TextMembersAlwaysPrintAsJson) {
  msg::Heartbeat hb;
  hb.service()[0] = 'a';
  hb.service()[1] = static_cast<char>(0xff);
  hb.service()[2] = 'b';
  std::string text;
  ASSERT_NO_THROW(text = msg::to_json(hb).dump());
  EXPECT_NE(text.find("\"service\":\"a\xEF\xBF\xBD"
                      "b\""),
            std::string::npos)
      << text;  // U+FFFD
}

// Both vendors decode in place: a malformed sample that follows the newest valid one left
// take_latest's output half overwritten by it. The reader below does what they do.
TEST(Subscriber, TakeLatestKeepsTheNewestValidSample) {
  struct Reader final : ReaderBackend {
    std::deque<std::pair<double, bool>> queue;  // x written into the sample, decoded whole?
    bool take(void* sample, SampleMeta*) override {
      while (!queue.empty()) {
        const auto [x, whole] = queue.front();
        queue.pop_front();
        static_cast<msg::Pose2D*>(sample)->x(x);  // decoded in place, even when it then fails
        if (whole) return true;
      }
      return false;
    }
    bool take_raw(void* sample, std::vector<unsigned char>&, SampleMeta* meta) override { return take(sample, meta); }
    bool wait(int64_t) override { return !queue.empty(); }
    int matched_count() const override { return 1; }
    uint64_t malformed_count() const override { return 0; }
    void set_data_callback(std::function<void()>) override {}
  };
  auto reader = std::make_unique<Reader>();
  reader->queue = {{1.0, true}, {2.0, true}, {99.0, false}};
  Subscriber<msg::Pose2D> sub(std::move(reader));
  msg::Pose2D out;
  ASSERT_TRUE(sub.take_latest(out));
  EXPECT_EQ(out.x(), 2.0);
}

}  // namespace
}  // namespace plexus::rt
