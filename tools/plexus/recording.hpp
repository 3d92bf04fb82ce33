// A plexus recording: SQLite file written by `plexus record`, read by `plexus replay` and
// `plexus latency pipeline`.
//
//   topics(id, name, type, qos)   qos: the recorded writer's discovered QoS as JSON
//   messages(id, topic_id, receive_time_ns, seq_num, data_time_ns, origin_time_ns,
//            publish_time_ns, cdr BLOB)   cdr: XCDR1 with encapsulation header
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

struct sqlite3;
struct sqlite3_stmt;

namespace plexus::cli {

struct RecordedTopic {
  int64_t id = 0;
  std::string name, type, qos_json;
};

struct RecordedMessage {
  int64_t topic_id = 0;
  int64_t receive_time_ns = 0;
  int64_t seq_num = 0, data_time_ns = 0, origin_time_ns = 0, publish_time_ns = 0;
  std::vector<unsigned char> cdr;
};

class RecordingWriter {
 public:
  /// Records into `path`.partial (InputError if it cannot be created); commit() renames it
  /// over `path`. Without commit() (a failed recording) the partial file is removed and an
  /// existing `path` is left as it was.
  explicit RecordingWriter(const std::string& path);
  ~RecordingWriter();
  /// Indexes the recording, closes it and renames it to `path` (replacing an existing file).
  void commit();
  int64_t add_topic(const std::string& name, const std::string& type, const std::string& qos_json);
  /// Inserts a batch in one transaction.
  void insert(const std::vector<RecordedMessage>& batch);

 private:
  sqlite3* db_ = nullptr;
  sqlite3_stmt* insert_ = nullptr;
  std::string path_;
  std::string partial_;
};

class RecordingReader {
 public:
  /// Opens `path` read-only. InputError "<path>: no such file" / "not a plexus recording".
  explicit RecordingReader(const std::string& path);
  ~RecordingReader();
  const std::vector<RecordedTopic>& topics() const { return topics_; }
  int64_t message_count() const;
  /// Every message in receive-time order (ties: insertion order); stop early by returning false.
  void for_each(const std::function<bool(const RecordedMessage&)>& fn) const;

 private:
  sqlite3* db_ = nullptr;
  std::string path_;
  std::vector<RecordedTopic> topics_;
};

}  // namespace plexus::cli
