// A plexus recording as MCAP (recording.hpp, common/mcap):
//   header        profile "" (no well-known profile), library "plexus <version>"
//   metadata      "plexus": recorder, version, and what the recorder adds (domain, vendor, ...)
//   schema        per message type: encoding `omgidl`, name `plexus::msg::Type`, data the
//                 type's self-contained IDL (msg::TypeSupport::schema)
//   channel       per topic: its name, message encoding `cdr`, metadata {"qos": the QoS its
//                 writers offered, as JSON (qos_to_json)}
//   message       sequence = the header's seq_num (low 32 bits), log_time = receive time,
//                 publish_time = the header's publish time, data = the CDR as received
//                 (encapsulation header included, nothing transcoded)
// Chunks of up to 1 MiB, zstd by default; a recorder hands a chunk to the file at least
// once a second (RecordingWriter::flush), so a recorder killed loses at most that second.
#pragma once

#include <memory>
#include <string>

#include "plexus/mcap/reader.hpp"
#include "plexus/mcap/writer.hpp"
#include "recording.hpp"

namespace plexus::cli {

class McapRecordingWriter final : public RecordingWriter {
 public:
  /// Checks now that `path` can be created; the file is created (replacing one there) when
  /// the first topic is added.
  McapRecordingWriter(const std::string& path, const RecordingOptions& options);
  /// A recording not committed is closed as far as it got (summary and footer written).
  ~McapRecordingWriter() override = default;
  int64_t add_topic(const std::string& name, const msg::TypeSupport& type, const std::string& qos_json) override;
  /// A topic of a type this build may not know, with its schema text given (tests, fuzz seeds).
  int64_t add_topic(const std::string& name, const std::string& type, const std::string& schema_text,
                    const std::string& qos_json);
  void insert(const SampleBatch& batch) override;
  void flush() override;
  void commit() override;

 private:
  void start();
  std::string path_;
  RecordingOptions options_;
  std::unique_ptr<mcap::Writer> file_;
};

class McapRecordingReader final : public RecordingReader {
 public:
  /// InputError naming the file for an MCAP file that is not a plexus recording: a channel
  /// without a topic, a topic twice, a message encoding other than cdr, no schema.
  explicit McapRecordingReader(const std::string& path);
  int64_t message_count() const override;
  void for_each(const std::function<bool(const RecordedMessage&)>& fn) const override;
  std::string cut_short() const override { return file_.cut_short(); }
  RecordingInfo info() const override;

 private:
  std::string path_;
  mcap::Reader file_;
};

}  // namespace plexus::cli
