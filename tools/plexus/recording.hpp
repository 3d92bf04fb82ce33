// A plexus recording: what `plexus record` and `plexus launch --record` write, and what
// `plexus replay`, `plexus latency pipeline`, `plexus topic echo --recording` and
// `plexus record info` read. Two formats behind one interface:
//   - MCAP (the default; mcap_recording.hpp): one channel per topic, its type an `omgidl`
//     schema, its messages the CDR as received; readable by Foxglove and the MCAP tools;
//   - SQLite (sqlite_recording.hpp), plexus's format before MCAP: still read, and written
//     with `--format sqlite` or a file named *.sqlite / *.db / *.db3.
// open_recording() tells them apart by the file's first bytes.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "plexus/mcap/records.hpp"
#include "plexus/msg/messages.hpp"

namespace plexus::cli {

struct RecordedTopic {
  int64_t id = 0;  ///< SQLite: the topics table's id; MCAP: the channel id
  std::string name, type, qos_json;
};

struct RecordedMessage {
  int64_t topic_id = 0;
  int64_t receive_time_ns = 0;
  int64_t seq_num = 0, data_time_ns = 0, origin_time_ns = 0, publish_time_ns = 0;
  std::vector<unsigned char> cdr;
};

/// Samples on their way to a file, in flat storage: filling a batch again after clear()
/// does not allocate once it has grown to a batch's size.
struct SampleBatch {
  struct Entry {
    int64_t topic_id, receive_time_ns, seq_num, data_time_ns, origin_time_ns, publish_time_ns;
    std::size_t offset, size;  ///< of its CDR in `bytes`
  };
  std::vector<Entry> entries;
  std::vector<unsigned char> bytes;

  /// `header`: the sample's StampHeader (nullptr: header times 0).
  void add(int64_t topic_id, int64_t receive_time_ns, const msg::StampHeader* header, const unsigned char* cdr,
           std::size_t size);
  void clear() {
    entries.clear();
    bytes.clear();
  }
  bool empty() const { return entries.empty(); }
  const unsigned char* cdr(const Entry& e) const { return bytes.data() + e.offset; }
};

enum class RecordingFormat { mcap, sqlite };

struct RecordingOptions {
  RecordingFormat format = RecordingFormat::mcap;
  mcap::Compression compression = mcap::Compression::zstd;
  /// MCAP: the header's library ("plexus <version>") and the "plexus" metadata record
  /// (recorder, version, ...).
  std::string library = "plexus";
  std::map<std::string, std::string> metadata;
};

/// The format to write `path` in: `option` ("mcap", "sqlite"; InputError naming --format
/// for anything else), or, when it is empty, by the file name: *.sqlite, *.db, *.db3 are
/// SQLite, anything else MCAP.
RecordingFormat recording_format(const std::string& path, const std::string& option);
/// --compression: "zstd", "lz4" or "none"; InputError naming the option otherwise.
mcap::Compression recording_compression(const std::string& option);

class RecordingWriter {
 public:
  virtual ~RecordingWriter() = default;
  /// A topic of `type` whose writers offered `qos_json` (qos_to_json); returns its id.
  virtual int64_t add_topic(const std::string& name, const msg::TypeSupport& type, const std::string& qos_json) = 0;
  virtual void insert(const SampleBatch& batch) = 0;
  /// Hands what was inserted to the file now (MCAP: ends the open chunk), so a recorder
  /// killed after this leaves it readable (MCAP; a SQLite recording is renamed into place
  /// only by commit()).
  virtual void flush() = 0;
  /// Completes the file. Without it a failed recording leaves: MCAP, the file as far as it
  /// got, closed; SQLite, no file (an existing one at the path untouched).
  virtual void commit() = 0;
};

/// InputError "<path>: cannot create recording (...)" before anything is recorded when the
/// file cannot be created. An existing file at `path` is replaced only once the first topic
/// is recorded (MCAP) or at commit() (SQLite).
std::unique_ptr<RecordingWriter> make_recording_writer(const std::string& path, const RecordingOptions& options);

/// What `plexus record info` prints: counts and the time span, from the MCAP summary
/// (no scan of a complete file) or the SQLite tables.
struct RecordingInfo {
  struct Topic {
    std::string name, type, qos_json;
    uint64_t messages = 0;
  };
  std::string format;     ///< "mcap" or "sqlite"
  std::string cut_short;  ///< empty for a complete file
  bool from_summary = false;
  uint64_t messages = 0, chunks = 0, schemas = 0;
  int64_t start_ns = 0, end_ns = 0;             ///< receive times of the first and last message
  std::string compression;                      ///< MCAP: the chunks' ("zstd", "lz4", "" for none, "mixed")
  std::map<std::string, std::string> metadata;  ///< MCAP: the "plexus" metadata record
  std::vector<Topic> topics;
};

class RecordingReader {
 public:
  virtual ~RecordingReader() = default;
  const std::vector<RecordedTopic>& topics() const { return topics_; }
  virtual int64_t message_count() const = 0;
  /// Every message in receive-time order (ties: file order); stop early by returning false.
  virtual void for_each(const std::function<bool(const RecordedMessage&)>& fn) const = 0;
  /// Empty for a complete file; else one line saying where it ends early (a recorder that
  /// was killed): everything before that point is read.
  virtual std::string cut_short() const { return {}; }
  virtual RecordingInfo info() const = 0;

 protected:
  std::vector<RecordedTopic> topics_;
};

/// Opens an MCAP or SQLite recording, by its first bytes. InputError "<path>: no such file",
/// "<path>: not a plexus recording (...)" or the format's own refusal, one line.
std::unique_ptr<RecordingReader> open_recording(const std::string& path);

/// The StampHeader at the start of every plexus message, read from its XCDR1 bytes (either
/// endianness); false (and `h` untouched) for bytes too short or not plain CDR.
bool header_from_cdr(const unsigned char* cdr, std::size_t size, msg::StampHeader& h);

}  // namespace plexus::cli
