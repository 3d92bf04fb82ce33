// Reading a recording (recording.cpp) and what plexus replay decides from it before it
// publishes (replay_plan.cpp), on files plexus record did not write: rows another tool put
// there, values no clock gives. The refusals are the regressions of what the fuzz target
// tests/fuzz/recording_reader_fuzz.cpp found (docs/testing.md, "Fuzzing").
#include <gtest/gtest.h>
#include <sqlite3.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "plexus/base/input_error.hpp"
#include "replay_plan.hpp"
#include "sqlite_recording.hpp"
#include "tests/input_error_of.hpp"

namespace plexus::cli {
namespace {

using test_support::error_of;

class Recording : public ::testing::Test {
 protected:
  void SetUp() override {
    path_ = (std::filesystem::temp_directory_path() /
             ("plexus_recording_test_" + std::to_string(::getpid()) + "_" +
              ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".sqlite"))
                .string();
    std::filesystem::remove(path_);
  }
  void TearDown() override { std::filesystem::remove(path_); }

  /// A file written with SQL: untyped columns, no constraints (another tool's file).
  void sql(const std::string& statements) {
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open(path_.c_str(), &db), SQLITE_OK);
    const std::string all =
        "CREATE TABLE topics(id, name, type, qos);"
        "CREATE TABLE messages(id INTEGER PRIMARY KEY, topic_id, receive_time_ns, seq_num,"
        " data_time_ns, origin_time_ns, publish_time_ns, cdr);" +
        statements;
    EXPECT_EQ(sqlite3_exec(db, all.c_str(), nullptr, nullptr, nullptr), SQLITE_OK) << sqlite3_errmsg(db);
    sqlite3_close(db);
  }

  std::string read_all() {
    return error_of([&] {
      SqliteRecordingReader r(path_);
      r.for_each([](const RecordedMessage&) { return true; });
    });
  }

  std::string path_;
};

TEST_F(Recording, WrittenMessagesReadBackInReceiveOrder) {
  {
    SqliteRecordingWriter w(path_);
    const int64_t id = w.add_topic("r1/position", "plexus::msg::PositionMeasurement", "");
    RecordedMessage a, b;
    a.topic_id = b.topic_id = id;
    a.receive_time_ns = 20;
    b.receive_time_ns = 10;
    a.cdr = {0, 1, 0, 0, 7};
    b.cdr = {0, 1, 0, 0, 8};
    w.insert({a, b});
    w.commit();
  }
  SqliteRecordingReader r(path_);
  ASSERT_EQ(r.topics().size(), 1u);
  EXPECT_EQ(r.topics()[0].name, "r1/position");
  EXPECT_EQ(r.message_count(), 2);
  std::vector<int64_t> order;
  r.for_each([&](const RecordedMessage& m) {
    order.push_back(m.receive_time_ns);
    return true;
  });
  EXPECT_EQ(order, (std::vector<int64_t>{10, 20}));
  const auto summary = summarize_recording(r);
  ASSERT_EQ(summary.size(), 1u);
  EXPECT_EQ(summary[0].count, 2u);
  EXPECT_EQ(summary[0].first_ns, 10);
  EXPECT_EQ(summary[0].last_ns, 20);
}

// A NULL name must not be read as a null char* into std::string (a crash).
TEST_F(Recording, TopicWithoutANameOrTypeIsRefused) {
  sql("INSERT INTO topics VALUES(1, NULL, 'plexus::msg::Pose2D', '');");
  EXPECT_EQ(error_of([&] { SqliteRecordingReader r(path_); }),
            path_ + ": not a plexus recording: topic 1 without a name or a type");
}

TEST_F(Recording, TopicTwiceIsRefused) {
  sql("INSERT INTO topics VALUES(1, 't', 'x', ''); INSERT INTO topics VALUES(2, 't', 'x', '');");
  EXPECT_EQ(error_of([&] { SqliteRecordingReader r(path_); }), path_ + ": not a plexus recording: topic 't' twice");
}

TEST_F(Recording, TopicIdTwiceIsRefused) {
  sql("INSERT INTO topics VALUES(1, 'a', 'x', ''); INSERT INTO topics VALUES(1, 'b', 'x', '');");
  EXPECT_EQ(error_of([&] { SqliteRecordingReader r(path_); }), path_ + ": not a plexus recording: topic id 1 twice");
}

TEST_F(Recording, MessageRowsAreChecked) {
  sql("INSERT INTO topics VALUES(1, 't', 'x', '');"
      "INSERT INTO messages VALUES(5, 1, -3, 0, 0, 0, 0, x'00010000');");
  EXPECT_EQ(read_all(), path_ + ": not a plexus recording: message 5: negative receive time -3");
}

TEST_F(Recording, MessageOfNoTopicIsRefused) {
  sql("INSERT INTO topics VALUES(1, 't', 'x', '');"
      "INSERT INTO messages VALUES(5, 2, 10, 0, 0, 0, 0, x'00010000');");
  EXPECT_EQ(read_all(), path_ + ": not a plexus recording: message 5: topic 2 is not in the topics table");
}

TEST_F(Recording, MessageColumnOfAnotherTypeIsRefused) {
  sql("INSERT INTO topics VALUES(1, 't', 'x', '');"
      "INSERT INTO messages VALUES(5, 1, 'soon', 0, 0, 0, 0, x'00010000');");
  EXPECT_EQ(read_all(), path_ + ": not a plexus recording: message 5: receive_time_ns is not an integer");
}

RecordedTopic topic(const std::string& qos_json) {
  return {1, "r1/position", "plexus::msg::PositionMeasurement", qos_json};
}

TEST(RecordedQos, WhatPlexusRecordWritesIsReplayedAsRecorded) {
  const auto q = recorded_qos(topic(R"({"reliability":"reliable","durability":"transient","history":"keep_last",)"
                                    R"("depth":5,"deadline_s":0.05,"liveliness":"manual_by_topic",)"
                                    R"("liveliness_lease_s":2.0,"lifespan_s":0.0,"latency_budget_s":1e9,)"
                                    R"("ownership":"shared","data_representation":[0]})"),
                              "f", 1);
  EXPECT_EQ(q.reliability, rt::QosProfile::Reliability::reliable);
  EXPECT_EQ(q.durability, rt::QosProfile::Durability::transient_local);
  EXPECT_EQ(q.depth, 5);
  EXPECT_DOUBLE_EQ(q.deadline_s, 0.05);
  EXPECT_EQ(q.liveliness, rt::QosProfile::Liveliness::manual_by_topic);
  EXPECT_DOUBLE_EQ(q.latency_budget_s, 1e9);
  // Not discovered when recorded: reliable, keep_last at the replay's depth.
  const auto d = recorded_qos(topic(""), "f", 64);
  EXPECT_EQ(d.reliability, rt::QosProfile::Reliability::reliable);
  EXPECT_EQ(d.depth, 64);
}

// Each of these would reach the vendors' QoS conversion (a depth or duration no vendor holds) or
// escape as a JSON exception (exit 1, "failed"); each is one line naming file, topic, key.
TEST(RecordedQos, ValuesNoVendorAppliesAreRefused) {
  const std::string at = "f: topic 'r1/position': recorded QoS: ";
  const std::string hint = " (replay with --profile PROFILE to publish with a profile instead)";
  EXPECT_EQ(error_of([&] { recorded_qos(topic("[1]"), "f", 1); }), at + "not a JSON object");
  EXPECT_EQ(error_of([&] { recorded_qos(topic("{\"depth\""), "f", 1); }), at + "not a JSON object");
  EXPECT_EQ(error_of([&] { recorded_qos(topic(R"({"history":"keep_last","depth":1e300})"), "f", 1); }),
            at + "depth: expected a 32-bit integer, got 1e+300" + hint);
  EXPECT_EQ(error_of([&] { recorded_qos(topic(R"({"history":"keep_last","depth":200000})"), "f", 1); }),
            at + "depth: a keep_last depth must be in 1..100000, got 200000" + hint);
  EXPECT_EQ(error_of([&] { recorded_qos(topic(R"({"deadline_s":5e9})"), "f", 1); }),
            at + "deadline_s: must be 0 (none) or within [1e-9, 1e9] s, got 5000000000.0" + hint);
  EXPECT_EQ(error_of([&] { recorded_qos(topic(R"({"lifespan_s":"1"})"), "f", 1); }),
            at + "lifespan_s: expected a number of seconds, got \"1\"" + hint);
  EXPECT_EQ(error_of([&] { recorded_qos(topic(R"({"reliability":1})"), "f", 1); }),
            at + "reliability: expected one of reliable, best_effort, got 1" + hint);
  // keep_all: the reported depth is not used, whatever it is.
  EXPECT_NO_THROW(recorded_qos(topic(R"({"history":"keep_all","depth":-1})"), "f", 1));
}

TEST(ReplayTimes, DueTimeSaturatesAndShiftsRefuseOverflow) {
  constexpr int64_t kMax = std::numeric_limits<int64_t>::max();
  EXPECT_EQ(replay_due_ns(3'000'000'000, 1'000'000'000, 2.0), 1'000'000'000);
  EXPECT_EQ(replay_due_ns(kMax, 0, 1e-3), kMax);  // 292 years at a thousandth of the speed
  EXPECT_EQ(replay_due_ns(5, 5, 1e-3), 0);
  int64_t out = 7;
  EXPECT_TRUE(shift_time(1'000, -400, out));
  EXPECT_EQ(out, 600);
  out = 7;
  EXPECT_FALSE(shift_time(kMax - 10, 11, out));
  EXPECT_FALSE(shift_time(std::numeric_limits<int64_t>::min(), -1, out));
  EXPECT_EQ(out, 7);
}

}  // namespace
}  // namespace plexus::cli
