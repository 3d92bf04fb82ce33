#include "mcap_recording.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <limits>
#include <set>

#include "plexus/base/input_error.hpp"

namespace plexus::cli {

McapRecordingWriter::McapRecordingWriter(const std::string& path, const RecordingOptions& options)
    : path_(path), options_(options) {
  // Can it be created? Probed without touching a file already there.
  std::error_code ec;
  const bool existed = std::filesystem::exists(path, ec);
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) throw InputError(path + ": cannot create recording (" + std::strerror(errno) + ")");
  ::close(fd);
  if (!existed) std::filesystem::remove(path, ec);
}

void McapRecordingWriter::start() {
  if (file_) return;
  mcap::WriterOptions o;
  o.compression = options_.compression;
  o.library = options_.library;
  file_ = std::make_unique<mcap::Writer>(path_, o);
  file_->add_metadata("plexus", options_.metadata);
}

int64_t McapRecordingWriter::add_topic(const std::string& name, const msg::TypeSupport& type,
                                       const std::string& qos_json) {
  return add_topic(name, type.type_name, type.schema, qos_json);
}

int64_t McapRecordingWriter::add_topic(const std::string& name, const std::string& type, const std::string& schema_text,
                                       const std::string& qos_json) {
  start();
  const uint16_t schema = file_->add_schema(type, "omgidl", schema_text);
  std::map<std::string, std::string> meta;
  if (!qos_json.empty()) meta["qos"] = qos_json;
  return file_->add_channel(schema, name, "cdr", meta);
}

void McapRecordingWriter::insert(const SampleBatch& batch) {
  if (batch.empty()) return;
  start();
  for (const auto& e : batch.entries) {
    // MCAP times are unsigned; a wall-clock receive time is positive. The publish time is
    // the header's, or the receive time where the writer left it 0 (the spec's rule).
    const auto log_time = static_cast<uint64_t>(std::max<int64_t>(e.receive_time_ns, 0));
    const uint64_t publish_time = e.publish_time_ns > 0 ? static_cast<uint64_t>(e.publish_time_ns) : log_time;
    file_->write(static_cast<uint16_t>(e.topic_id), static_cast<uint32_t>(e.seq_num), log_time, publish_time,
                 batch.cdr(e), e.size);
  }
}

void McapRecordingWriter::flush() {
  if (file_) file_->flush();
}

void McapRecordingWriter::commit() {
  start();
  file_->close();
}

McapRecordingReader::McapRecordingReader(const std::string& path) : path_(path), file_(path) {
  const auto refuse = [&](const std::string& why) { throw InputError(path + ": not a plexus recording: " + why); };
  std::set<std::string> names;
  for (const auto& [id, ch] : file_.channels()) {
    const std::string which = "channel " + std::to_string(id) + " ('" + ch.topic + "')";
    if (ch.topic.empty()) refuse("channel " + std::to_string(id) + " has no topic");
    if (ch.message_encoding != "cdr") refuse(which + ": message encoding '" + ch.message_encoding + "', not cdr");
    if (ch.schema_id == 0) refuse(which + ": no schema, so no type");
    if (!names.insert(ch.topic).second) refuse("topic '" + ch.topic + "' twice");
    const auto& schema = file_.schemas().at(ch.schema_id);
    if (schema.name.empty()) refuse(which + ": its schema has no name, so no type");
    RecordedTopic t;
    t.id = id;
    t.name = ch.topic;
    t.type = schema.name;
    const auto qos = ch.metadata.find("qos");
    t.qos_json = qos == ch.metadata.end() ? "" : qos->second;
    topics_.push_back(std::move(t));
  }
}

int64_t McapRecordingReader::message_count() const {
  return static_cast<int64_t>(
      std::min<uint64_t>(file_.statistics().message_count, std::numeric_limits<int64_t>::max()));
}

void McapRecordingReader::for_each(const std::function<bool(const RecordedMessage&)>& fn) const {
  std::map<uint16_t, bool> has_header;  // by channel: its type has a StampHeader
  for (const auto& t : topics_) {
    const msg::TypeSupport* ts = msg::find_type_support(t.type);
    has_header[static_cast<uint16_t>(t.id)] = ts && ts->header;
  }
  RecordedMessage m;
  msg::StampHeader h;
  file_.for_each_message([&](const mcap::MessageView& v) {
    if (v.log_time > static_cast<uint64_t>(std::numeric_limits<int64_t>::max()))
      throw InputError(path_ + ": not a plexus recording: a message on '" + v.channel->topic + "' with log time " +
                       std::to_string(v.log_time) + " ns, beyond any receive time");
    m.topic_id = v.channel->id;
    m.receive_time_ns = static_cast<int64_t>(v.log_time);
    m.cdr.assign(v.data, v.data + v.size);
    h = msg::StampHeader();
    if (has_header[v.channel->id]) header_from_cdr(v.data, v.size, h);
    m.seq_num = static_cast<int64_t>(h.seq_num());
    m.data_time_ns = h.data_time_ns();
    m.origin_time_ns = h.origin_time_ns();
    m.publish_time_ns = h.publish_time_ns();
    return fn(m);
  });
}

RecordingInfo McapRecordingReader::info() const {
  const mcap::Statistics& st = file_.statistics();
  RecordingInfo info;
  info.format = "mcap";
  info.cut_short = file_.cut_short();
  info.from_summary = file_.from_summary();
  info.messages = st.message_count;
  info.chunks = st.chunk_count;
  info.schemas = st.schema_count;
  const auto clamp = [](uint64_t t) {
    return static_cast<int64_t>(std::min<uint64_t>(t, std::numeric_limits<int64_t>::max()));
  };
  info.start_ns = clamp(st.message_start_time);
  info.end_ns = clamp(st.message_end_time);
  info.compression = file_.compression();
  for (const auto& m : file_.metadata())
    if (m.name == "plexus") info.metadata = m.entries;
  for (const auto& t : topics_) {
    const auto n = st.channel_message_counts.find(static_cast<uint16_t>(t.id));
    info.topics.push_back({t.name, t.type, t.qos_json, n == st.channel_message_counts.end() ? 0 : n->second});
  }
  return info;
}

}  // namespace plexus::cli
