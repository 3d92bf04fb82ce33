#include "plexus/mcap/writer.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "byte_io.hpp"
#include "codec.hpp"
#include "plexus/base/input_error.hpp"

namespace plexus::mcap {

using detail::Builder;

void validate(const WriterOptions& o) {
  if (o.zstd_level < 1 || o.zstd_level > 19)
    throw InputError("zstd level: must be in 1..19, got " + std::to_string(o.zstd_level));
  if (o.chunk_size < 1024 || o.chunk_size > (64u << 20))
    throw InputError("chunk size: must be in 1 KiB..64 MiB, got " + std::to_string(o.chunk_size) + " bytes");
}

Writer::Writer(const std::string& path, WriterOptions options) : path_(path), opt_(std::move(options)) {
  validate(opt_);
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0) throw InputError(path + ": cannot create recording (" + std::strerror(errno) + ")");
  std::vector<unsigned char> rec(kMagic, kMagic + sizeof kMagic);
  Builder b(rec);
  const auto at = b.begin_record(Op::header);
  b.str(opt_.profile);
  b.str(opt_.library);
  b.end_record(at);
  put_data_record(rec);
  chunk_.reserve(opt_.chunk_size + 4096);
}

Writer::~Writer() {
  try {
    close();
  } catch (const std::exception&) {}
  if (fd_ >= 0) ::close(fd_);
  if (zstd_) detail::free_zstd(zstd_);
}

void Writer::put(const void* data, std::size_t size) {
  const auto* p = static_cast<const unsigned char*>(data);
  while (size > 0) {
    const ssize_t n = ::write(fd_, p, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw std::runtime_error(path_ + ": cannot write the recording (" + std::strerror(errno) + ")");
    p += n;
    size -= static_cast<std::size_t>(n);
    offset_ += static_cast<uint64_t>(n);
  }
}

void Writer::put_data_record(const std::vector<unsigned char>& record) {
  data_crc_ = detail::crc32_update(data_crc_, record.data(), record.size());
  put(record.data(), record.size());
}

uint16_t Writer::add_schema(const std::string& name, const std::string& encoding, std::string_view data) {
  for (const auto& s : schemas_)
    if (s.name == name && s.encoding == encoding && s.data == data) return s.id;
  if (schemas_.size() >= 65535) throw std::length_error(path_ + ": more than 65535 schemas");
  Schema s{static_cast<uint16_t>(schemas_.size() + 1), name, encoding, std::string(data)};
  std::vector<unsigned char> rec;
  Builder b(rec);
  const auto at = b.begin_record(Op::schema);
  b.u16(s.id);
  b.str(s.name);
  b.str(s.encoding);
  b.u32(static_cast<uint32_t>(s.data.size()));
  b.raw(s.data.data(), s.data.size());
  b.end_record(at);
  put_data_record(rec);
  schemas_.push_back(std::move(s));
  stats_.schema_count = static_cast<uint16_t>(schemas_.size());
  return schemas_.back().id;
}

uint16_t Writer::add_channel(uint16_t schema_id, const std::string& topic, const std::string& message_encoding,
                             const std::map<std::string, std::string>& metadata) {
  if (channels_.size() >= 65536) throw std::length_error(path_ + ": more than 65536 channels");
  if (schema_id > schemas_.size()) throw std::logic_error(path_ + ": channel '" + topic + "' names no schema it added");
  Channel c{static_cast<uint16_t>(channels_.size()), schema_id, topic, message_encoding, metadata};
  std::vector<unsigned char> rec;
  Builder b(rec);
  const auto at = b.begin_record(Op::channel);
  b.u16(c.id);
  b.u16(c.schema_id);
  b.str(c.topic);
  b.str(c.message_encoding);
  b.string_map(c.metadata);
  b.end_record(at);
  put_data_record(rec);
  channels_.push_back(std::move(c));
  stats_.channel_count = static_cast<uint32_t>(channels_.size());
  return channels_.back().id;
}

void Writer::add_metadata(const std::string& name, const std::map<std::string, std::string>& entries) {
  std::vector<unsigned char> rec;
  Builder b(rec);
  const auto at = b.begin_record(Op::metadata);
  b.str(name);
  b.string_map(entries);
  b.end_record(at);
  metadata_index_.push_back({name, {offset_, rec.size()}});
  put_data_record(rec);
  ++stats_.metadata_count;
}

void Writer::write(uint16_t channel_id, uint32_t sequence, uint64_t log_time, uint64_t publish_time,
                   const unsigned char* data, std::size_t size) {
  if (closed_) throw std::logic_error(path_ + ": message written after close()");
  if (channel_id >= channels_.size()) throw std::logic_error(path_ + ": message on a channel it never added");
  const uint64_t at = chunk_.size();
  Builder b(chunk_);
  b.u8(static_cast<uint8_t>(Op::message));
  b.u64(2 + 4 + 8 + 8 + static_cast<uint64_t>(size));
  b.u16(channel_id);
  b.u32(sequence);
  b.u64(log_time);
  b.u64(publish_time);
  b.raw(data, size);
  chunk_index_[channel_id].emplace_back(log_time, at);
  if (!chunk_has_messages_ || log_time < chunk_start_) chunk_start_ = log_time;
  if (!chunk_has_messages_ || log_time > chunk_end_) chunk_end_ = log_time;
  if (stats_.message_count == 0 || log_time < stats_.message_start_time) stats_.message_start_time = log_time;
  if (stats_.message_count == 0 || log_time > stats_.message_end_time) stats_.message_end_time = log_time;
  chunk_has_messages_ = true;
  ++stats_.message_count;
  ++stats_.channel_message_counts[channel_id];
  if (chunk_.size() >= opt_.chunk_size) flush();
}

void Writer::flush() {
  if (closed_ || chunk_.empty()) return;
  detail::compress(opt_.compression, opt_.zstd_level, zstd_, chunk_.data(), chunk_.size(), compressed_);
  const std::string compression = compression_name(opt_.compression);
  ChunkIndex ci;
  ci.message_start_time = chunk_has_messages_ ? chunk_start_ : 0;
  ci.message_end_time = chunk_has_messages_ ? chunk_end_ : 0;
  ci.chunk_start_offset = offset_;
  ci.compression = compression;
  ci.compressed_size = compressed_.size();
  ci.uncompressed_size = chunk_.size();
  // The chunk record: its fixed fields, then the compressed records (put straight from
  // their buffer, not copied into the record).
  scratch_.clear();
  Builder b(scratch_);
  b.u8(static_cast<uint8_t>(Op::chunk));
  b.u64(8 + 8 + 8 + 4 + 4 + compression.size() + 8 + compressed_.size());
  b.u64(ci.message_start_time);
  b.u64(ci.message_end_time);
  b.u64(chunk_.size());
  b.u32(detail::crc32_update(0, chunk_.data(), chunk_.size()));
  b.str(compression);
  b.u64(compressed_.size());
  // Message indexes follow the chunk: one per channel with messages in it.
  std::vector<unsigned char> indexes;
  Builder ib(indexes);
  const uint64_t indexes_at = offset_ + scratch_.size() + compressed_.size();
  for (auto& [channel, entries] : chunk_index_) {
    if (entries.empty()) continue;
    ci.message_index_offsets[channel] = indexes_at + indexes.size();
    const auto rec = ib.begin_record(Op::message_index);
    ib.u16(channel);
    ib.u32(static_cast<uint32_t>(entries.size() * 16));
    for (const auto& [time, at] : entries) {
      ib.u64(time);
      ib.u64(at);
    }
    ib.end_record(rec);
    entries.clear();
  }
  ci.chunk_length = scratch_.size() + compressed_.size();
  ci.message_index_length = indexes.size();
  data_crc_ = detail::crc32_update(data_crc_, scratch_.data(), scratch_.size());
  data_crc_ = detail::crc32_update(data_crc_, compressed_.data(), compressed_.size());
  put(scratch_.data(), scratch_.size());
  put(compressed_.data(), compressed_.size());
  put_data_record(indexes);
  chunk_indexes_.push_back(std::move(ci));
  ++stats_.chunk_count;
  chunk_.clear();
  chunk_has_messages_ = false;
}

void Writer::close() {
  if (closed_ || fd_ < 0) return;
  flush();
  closed_ = true;
  std::vector<unsigned char> rec;
  Builder d(rec);
  const auto end_at = d.begin_record(Op::data_end);
  d.u32(data_crc_);
  d.end_record(end_at);
  put(rec.data(), rec.size());

  // The summary, grouped by opcode, each group's place noted for the summary offsets.
  const uint64_t summary_start = offset_;
  std::vector<unsigned char> summary;
  Builder b(summary);
  std::vector<std::pair<Op, std::pair<uint64_t, uint64_t>>> groups;
  auto group = [&](Op op, auto&& write_records) {
    const std::size_t before = summary.size();
    write_records();
    if (summary.size() > before) groups.push_back({op, {summary_start + before, summary.size() - before}});
  };
  group(Op::schema, [&] {
    for (const auto& s : schemas_) {
      const auto at = b.begin_record(Op::schema);
      b.u16(s.id);
      b.str(s.name);
      b.str(s.encoding);
      b.u32(static_cast<uint32_t>(s.data.size()));
      b.raw(s.data.data(), s.data.size());
      b.end_record(at);
    }
  });
  group(Op::channel, [&] {
    for (const auto& c : channels_) {
      const auto at = b.begin_record(Op::channel);
      b.u16(c.id);
      b.u16(c.schema_id);
      b.str(c.topic);
      b.str(c.message_encoding);
      b.string_map(c.metadata);
      b.end_record(at);
    }
  });
  group(Op::statistics, [&] {
    const auto at = b.begin_record(Op::statistics);
    b.u64(stats_.message_count);
    b.u16(stats_.schema_count);
    b.u32(stats_.channel_count);
    b.u32(stats_.attachment_count);
    b.u32(stats_.metadata_count);
    b.u32(stats_.chunk_count);
    b.u64(stats_.message_start_time);
    b.u64(stats_.message_end_time);
    const auto map_at = b.begin_u32();
    for (const auto& [channel, n] : stats_.channel_message_counts) {
      b.u16(channel);
      b.u64(n);
    }
    b.end_u32(map_at);
    b.end_record(at);
  });
  group(Op::chunk_index, [&] {
    for (const auto& ci : chunk_indexes_) {
      const auto at = b.begin_record(Op::chunk_index);
      b.u64(ci.message_start_time);
      b.u64(ci.message_end_time);
      b.u64(ci.chunk_start_offset);
      b.u64(ci.chunk_length);
      const auto map_at = b.begin_u32();
      for (const auto& [channel, off] : ci.message_index_offsets) {
        b.u16(channel);
        b.u64(off);
      }
      b.end_u32(map_at);
      b.u64(ci.message_index_length);
      b.str(ci.compression);
      b.u64(ci.compressed_size);
      b.u64(ci.uncompressed_size);
      b.end_record(at);
    }
  });
  group(Op::metadata_index, [&] {
    for (const auto& [name, where] : metadata_index_) {
      const auto at = b.begin_record(Op::metadata_index);
      b.u64(where.first);
      b.u64(where.second);
      b.str(name);
      b.end_record(at);
    }
  });
  const uint64_t summary_offset_start = summary_start + summary.size();
  for (const auto& [op, where] : groups) {
    const auto at = b.begin_record(Op::summary_offset);
    b.u8(static_cast<uint8_t>(op));
    b.u64(where.first);
    b.u64(where.second);
    b.end_record(at);
  }
  // Footer; its CRC covers the summary and the footer up to the CRC itself.
  b.u8(static_cast<uint8_t>(Op::footer));
  b.u64(8 + 8 + 4);
  b.u64(summary_start);
  b.u64(groups.empty() ? 0 : summary_offset_start);
  b.u32(detail::crc32_update(0, summary.data(), summary.size()));
  b.raw(kMagic, sizeof kMagic);
  put(summary.data(), summary.size());
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) throw std::runtime_error(path_ + ": cannot write the recording (" + std::strerror(errno) + ")");
}

}  // namespace plexus::mcap
