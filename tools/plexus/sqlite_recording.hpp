// A SQLite recording, plexus's format before MCAP (recording.hpp): still read, and written
// with `plexus record --format sqlite`.
//
//   meta(key, value)              format = plexus-recording-1
//   topics(id, name, type, qos)   qos: the recorded writer's discovered QoS as JSON
//   messages(id, topic_id, receive_time_ns, seq_num, data_time_ns, origin_time_ns,
//            publish_time_ns, cdr BLOB)   cdr: XCDR1 with encapsulation header
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "recording.hpp"

struct sqlite3;
struct sqlite3_stmt;

namespace plexus::cli {

class SqliteRecordingWriter final : public RecordingWriter {
 public:
  /// Records into `path`.partial (InputError if it cannot be created); commit() renames it
  /// over `path`. Without commit() (a failed recording) the partial file is removed and an
  /// existing `path` is left as it was.
  explicit SqliteRecordingWriter(const std::string& path);
  ~SqliteRecordingWriter() override;
  /// Indexes the recording, closes it and renames it to `path` (replacing an existing file).
  void commit() override;
  /// `type`: the scoped IDL name, whatever it is (tests write unknown ones).
  int64_t add_topic(const std::string& name, const std::string& type, const std::string& qos_json);
  int64_t add_topic(const std::string& name, const msg::TypeSupport& type, const std::string& qos_json) override {
    return add_topic(name, std::string(type.type_name), qos_json);
  }
  /// Inserts a batch in one transaction.
  void insert(const std::vector<RecordedMessage>& batch);
  void insert(const SampleBatch& batch) override;
  void flush() override {}  // every insert is its own transaction already

 private:
  sqlite3* db_ = nullptr;
  sqlite3_stmt* insert_ = nullptr;
  std::string path_;
  std::string partial_;
};

class SqliteRecordingReader final : public RecordingReader {
 public:
  /// Opens `path` read-only. InputError "<path>: no such file" / "not a plexus recording".
  explicit SqliteRecordingReader(const std::string& path);
  ~SqliteRecordingReader() override;
  int64_t message_count() const override;
  /// Every message in receive-time order (ties: insertion order); stop early by returning false.
  void for_each(const std::function<bool(const RecordedMessage&)>& fn) const override;
  RecordingInfo info() const override;

 private:
  sqlite3* db_ = nullptr;
  std::string path_;
};

}  // namespace plexus::cli
