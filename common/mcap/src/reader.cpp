#include "plexus/mcap/reader.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <queue>

#include "byte_io.hpp"
#include "codec.hpp"
#include "plexus/base/input_error.hpp"

namespace plexus::mcap {

using detail::Cursor;
using detail::FormatError;
using detail::kMaxChunkBytes;

namespace {

constexpr uint64_t kRecordHead = 9;  // opcode + uint64 length
constexpr uint64_t kFooterRecord = kRecordHead + 20;
constexpr uint64_t kMaxSummaryBytes = 1ull << 30;  // a summary field claiming more is corrupt

const char* op_name(uint8_t op) {
  switch (static_cast<Op>(op)) {
    case Op::header: return "header";
    case Op::footer: return "footer";
    case Op::schema: return "schema";
    case Op::channel: return "channel";
    case Op::message: return "message";
    case Op::chunk: return "chunk";
    case Op::message_index: return "message index";
    case Op::chunk_index: return "chunk index";
    case Op::attachment: return "attachment";
    case Op::attachment_index: return "attachment index";
    case Op::statistics: return "statistics";
    case Op::metadata: return "metadata";
    case Op::metadata_index: return "metadata index";
    case Op::summary_offset: return "summary offset";
    case Op::data_end: return "data end";
  }
  return "unknown";
}

Schema parse_schema(Cursor& c) {
  Schema s;
  s.id = c.u16();
  s.name = c.str("name");
  s.encoding = c.str("encoding");
  const uint32_t n = c.u32();
  s.data.assign(reinterpret_cast<const char*>(c.take(n, "data")), n);
  return s;
}

Channel parse_channel(Cursor& c) {
  Channel ch;
  ch.id = c.u16();
  ch.schema_id = c.u16();
  ch.topic = c.str("topic");
  ch.message_encoding = c.str("message_encoding");
  ch.metadata = c.string_map("metadata");
  return ch;
}

struct ChunkHead {
  uint64_t start = 0, end = 0, uncompressed_size = 0;
  uint32_t crc = 0;
  std::string compression;
  uint64_t compressed_size = 0;
  const unsigned char* records = nullptr;  // compressed
};

ChunkHead parse_chunk_head(Cursor& c) {
  ChunkHead h;
  h.start = c.u64();
  h.end = c.u64();
  h.uncompressed_size = c.u64();
  h.crc = c.u32();
  h.compression = c.str("compression");
  h.compressed_size = c.u64();
  h.records = c.take(h.compressed_size, "records");
  return h;
}

}  // namespace

bool is_mcap_file(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  unsigned char head[sizeof kMagic];
  const bool yes = ::pread(fd, head, sizeof head, 0) == static_cast<ssize_t>(sizeof head) &&
                   std::memcmp(head, kMagic, sizeof kMagic) == 0;
  ::close(fd);
  return yes;
}

/// The open file: positioned reads of whole ranges.
struct Reader::File {
  int fd = -1;
  uint64_t size = 0;
  ~File() {
    if (fd >= 0) ::close(fd);
  }
  /// [offset, offset + n) into out; FormatError if the file does not hold it.
  void read(uint64_t offset, uint64_t n, std::vector<unsigned char>& out) const {
    if (offset > size || n > size - offset)
      throw FormatError("reads " + std::to_string(n) + " bytes past the end of the file", offset);
    out.resize(static_cast<std::size_t>(n));
    uint64_t done = 0;
    while (done < n) {
      const ssize_t r =
          ::pread(fd, out.data() + done, static_cast<std::size_t>(n - done), static_cast<off_t>(offset + done));
      if (r < 0 && errno == EINTR) continue;
      if (r <= 0)
        throw FormatError(std::string("cannot be read (") + (r < 0 ? std::strerror(errno) : "end of file") + ")",
                          offset + done);
      done += static_cast<uint64_t>(r);
    }
  }
};

void Reader::note_compression(const std::string& c) {
  const std::string name = c.empty() ? "none" : c;
  if (compression_.empty())
    compression_ = name;
  else if (compression_ != name)
    compression_ = "mixed";
}

std::string Reader::where(uint64_t offset) const { return " at byte " + std::to_string(offset); }

Reader::Reader(const std::string& path) : file_(std::make_unique<File>()), path_(path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) throw InputError(path + ": no such file");
  file_->fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (file_->fd < 0) throw InputError(path + ": cannot open (" + std::strerror(errno) + ")");
  file_->size = static_cast<uint64_t>(st.st_size);
  const uint64_t size = file_->size;
  std::vector<unsigned char> buf;
  try {
    if (size < sizeof kMagic)
      throw InputError(path + ": not an MCAP file (" + std::to_string(size) + " bytes, no MCAP magic)");
    file_->read(0, sizeof kMagic, buf);
    if (std::memcmp(buf.data(), kMagic, sizeof kMagic) != 0) {
      if (std::memcmp(buf.data(), kMagic, 5) == 0)
        throw InputError(path + ": MCAP major version '" + std::string(1, static_cast<char>(buf[5])) +
                         "' is not supported (0)");
      throw InputError(path + ": not an MCAP file (it does not start with the MCAP magic)");
    }
    // The header record comes first.
    if (size < sizeof kMagic + kRecordHead)
      throw InputError(path + ": cut short before its header (" + std::to_string(size) + " bytes): an empty recording");
    file_->read(sizeof kMagic, kRecordHead, buf);
    Cursor head(buf.data(), buf.size(), sizeof kMagic, "header");
    const uint8_t op = head.u8();
    const uint64_t len = head.u64();
    if (op != static_cast<uint8_t>(Op::header))
      throw FormatError(std::string("the first record is a ") + op_name(op) + " record, not the header", sizeof kMagic);
    if (len > size - sizeof kMagic - kRecordHead)
      throw InputError(path + ": cut short inside its header (" + std::to_string(size) + " bytes): an empty recording");
    if (len > kMaxSummaryBytes) throw FormatError("header record of " + std::to_string(len) + " bytes", sizeof kMagic);
    file_->read(sizeof kMagic + kRecordHead, len, buf);
    Cursor h(buf.data(), buf.size(), sizeof kMagic + kRecordHead, "header");
    header_.profile = h.str("profile");
    header_.library = h.str("library");
    data_start_ = sizeof kMagic + kRecordHead + len;

    // A complete file ends with the footer and the magic: the summary it points at lists
    // everything. Otherwise (no summary, or cut short) the data section is scanned.
    bool complete = false;
    if (size >= data_start_ + kFooterRecord + sizeof kMagic) {
      file_->read(size - kFooterRecord - sizeof kMagic, kFooterRecord + sizeof kMagic, buf);
      complete = std::memcmp(buf.data() + kFooterRecord, kMagic, sizeof kMagic) == 0 &&
                 buf[0] == static_cast<uint8_t>(Op::footer);
      if (complete) {
        const uint64_t footer_at = size - kFooterRecord - sizeof kMagic;
        Cursor f(buf.data(), kFooterRecord, footer_at, "footer");
        f.u8();
        if (f.u64() != 20) throw FormatError("footer record is not 20 bytes long", footer_at);
        const uint64_t summary_start = f.u64();
        f.u64();  // summary offsets: the whole summary is read, so they are not needed
        const uint32_t summary_crc = f.u32();
        if (summary_start != 0) {
          if (summary_start < data_start_ || summary_start > footer_at)
            throw FormatError(
                "footer points at a summary at byte " + std::to_string(summary_start) + ", outside the file's records",
                footer_at);
          read_summary(summary_start, footer_at, summary_crc);
        }
      }
    }
    if (!from_summary_) scan();
    if (!complete && cut_short_.empty())
      cut_short_ = "no footer: the file ends after its last complete record, at byte " + std::to_string(size);
  } catch (const FormatError& e) {
    throw InputError(path + ": corrupt MCAP: " + e.what() + where(e.offset()));
  }
}

Reader::~Reader() = default;

void Reader::read_summary(uint64_t summary_start, uint64_t footer_offset, uint32_t summary_crc) {
  const uint64_t n = footer_offset - summary_start;
  if (n > kMaxSummaryBytes) throw FormatError("summary of " + std::to_string(n) + " bytes", summary_start);
  std::vector<unsigned char> buf;
  file_->read(summary_start, n + kRecordHead + 16, buf);  // the summary and the footer up to its CRC
  if (summary_crc != 0 && detail::crc32_update(0, buf.data(), buf.size()) != summary_crc)
    throw FormatError("summary CRC mismatch (the summary changed since it was written)", summary_start);
  Cursor c(buf.data(), static_cast<std::size_t>(n), summary_start, "summary");
  bool have_stats = false;
  std::vector<ChunkIndex> chunks;
  std::vector<std::pair<uint64_t, uint64_t>> metadata_at;
  while (c.remaining() > 0) {
    const uint64_t at = c.offset();
    const uint8_t op = c.u8();
    const uint64_t len = c.u64();
    Cursor r(c.take(len, op_name(op)), static_cast<std::size_t>(len), at + kRecordHead, op_name(op));
    switch (static_cast<Op>(op)) {
      case Op::schema: {
        Schema s = parse_schema(r);
        if (s.id == 0) break;  // "invalid, ignored by readers"
        schemas_[s.id] = std::move(s);
        break;
      }
      case Op::channel: {
        Channel ch = parse_channel(r);
        channels_[ch.id] = std::move(ch);
        break;
      }
      case Op::statistics: {
        stats_.message_count = r.u64();
        stats_.schema_count = r.u16();
        stats_.channel_count = r.u32();
        stats_.attachment_count = r.u32();
        stats_.metadata_count = r.u32();
        stats_.chunk_count = r.u32();
        stats_.message_start_time = r.u64();
        stats_.message_end_time = r.u64();
        stats_.channel_message_counts = r.id_u64_map<uint16_t>("channel_message_counts");
        have_stats = true;
        break;
      }
      case Op::chunk_index: {
        ChunkIndex ci;
        ci.message_start_time = r.u64();
        ci.message_end_time = r.u64();
        ci.chunk_start_offset = r.u64();
        ci.chunk_length = r.u64();
        ci.message_index_offsets = r.id_u64_map<uint16_t>("message_index_offsets");
        ci.message_index_length = r.u64();
        ci.compression = r.str("compression");
        ci.compressed_size = r.u64();
        ci.uncompressed_size = r.u64();
        if (ci.chunk_start_offset < data_start_ || ci.chunk_start_offset > summary_start ||
            ci.chunk_length > summary_start - ci.chunk_start_offset || ci.chunk_length < kRecordHead ||
            ci.chunk_length > kMaxChunkBytes + 65536)
          throw FormatError("chunk index points at bytes " + std::to_string(ci.chunk_start_offset) + "+" +
                                std::to_string(ci.chunk_length) + ", outside the data section",
                            at);
        chunks.push_back(std::move(ci));
        break;
      }
      case Op::metadata_index: {
        const uint64_t off = r.u64(), length = r.u64();
        if (off < data_start_ || off > summary_start || length > summary_start - off || length < kRecordHead ||
            length > (64u << 20))
          throw FormatError("metadata index points outside the data section", at);
        metadata_at.emplace_back(off, length);
        break;
      }
      default:  // attachment indexes, summary offsets, records of later versions: not needed
        break;
    }
  }
  for (const auto& [id, ch] : channels_)
    if (ch.schema_id != 0 && !schemas_.count(ch.schema_id))
      throw FormatError("channel " + std::to_string(id) + " ('" + ch.topic + "') names schema " +
                            std::to_string(ch.schema_id) + ", which the summary does not hold",
                        summary_start);
  // Without chunk indexes the messages can only be found by a scan (a file written
  // without chunks), unless the statistics say there are none.
  if (chunks.empty() && !(have_stats && stats_.message_count == 0)) {
    schemas_.clear();
    channels_.clear();
    stats_ = {};
    return;
  }
  for (const auto& ci : chunks) {
    note_compression(ci.compression);
    Block b;
    b.offset = ci.chunk_start_offset;
    b.length = ci.chunk_length;
    b.start_time = ci.message_start_time;
    b.end_time = ci.message_end_time;
    // An empty message index map means "no indexing", not "no messages".
    b.has_messages = !(ci.message_start_time == 0 && ci.message_end_time == 0 && ci.message_index_offsets.empty() &&
                       ci.uncompressed_size == 0);
    blocks_.push_back(b);
  }
  for (const auto& [off, length] : metadata_at) {
    file_->read(off, length, buf);
    Cursor r(buf.data(), buf.size(), off, "metadata");
    if (r.u8() != static_cast<uint8_t>(Op::metadata) || r.u64() != length - kRecordHead)
      throw FormatError("metadata index points at a record that is not metadata", off);
    Metadata m;
    m.name = r.str("name");
    m.entries = r.string_map("metadata");
    metadata_.push_back(std::move(m));
  }
  if (!have_stats) {  // counts from the chunk indexes' channels are not available: count them
    stats_.schema_count = static_cast<uint16_t>(schemas_.size());
    stats_.channel_count = static_cast<uint32_t>(channels_.size());
    stats_.chunk_count = static_cast<uint32_t>(chunks.size());
    uint64_t count = 0;
    for_each_message([&](const MessageView& m) {
      if (count++ == 0) stats_.message_start_time = m.log_time;
      stats_.message_end_time = std::max(stats_.message_end_time, m.log_time);
      ++stats_.channel_message_counts[m.channel->id];
      return true;
    });
    stats_.message_count = count;
  }
  from_summary_ = true;
}

void Reader::scan() {
  const uint64_t size = file_->size;
  schemas_.clear();
  channels_.clear();
  metadata_.clear();
  blocks_.clear();
  stats_ = {};
  compression_.clear();
  std::vector<unsigned char> buf, records;
  uint64_t at = data_start_;
  bool data_end = false;
  const auto add_schema = [&](Schema s, uint64_t where_at) {
    if (s.id == 0) return;
    const auto [it, fresh] = schemas_.emplace(s.id, s);
    if (!fresh && (it->second.name != s.name || it->second.encoding != s.encoding || it->second.data != s.data))
      throw FormatError("schema " + std::to_string(s.id) + " defined twice, differently", where_at);
  };
  const auto add_channel = [&](Channel ch, uint64_t where_at) {
    if (ch.schema_id != 0 && !schemas_.count(ch.schema_id))
      throw FormatError("channel " + std::to_string(ch.id) + " ('" + ch.topic + "') names schema " +
                            std::to_string(ch.schema_id) + " before any schema record of that id",
                        where_at);
    const auto [it, fresh] = channels_.emplace(ch.id, ch);
    if (!fresh && (it->second.topic != ch.topic || it->second.schema_id != ch.schema_id ||
                   it->second.message_encoding != ch.message_encoding || it->second.metadata != ch.metadata))
      throw FormatError("channel " + std::to_string(ch.id) + " defined twice, differently", where_at);
  };
  const auto count_message = [&](Cursor& r, uint64_t where_at) {
    const uint16_t channel = r.u16();
    r.u32();
    const uint64_t log_time = r.u64();
    r.u64();
    if (!channels_.count(channel))
      throw FormatError("message on channel " + std::to_string(channel) + " before any channel record of that id",
                        where_at);
    if (stats_.message_count == 0 || log_time < stats_.message_start_time) stats_.message_start_time = log_time;
    if (stats_.message_count == 0 || log_time > stats_.message_end_time) stats_.message_end_time = log_time;
    ++stats_.message_count;
    ++stats_.channel_message_counts[channel];
    return log_time;
  };
  while (at < size) {
    if (size - at < kRecordHead) {
      cut_short_ = "cut short at byte " + std::to_string(at) + " of " + std::to_string(size) +
                   ", inside a record's opcode and length";
      break;
    }
    file_->read(at, kRecordHead, buf);
    Cursor head(buf.data(), buf.size(), at, "record");
    const uint8_t op = head.u8();
    const uint64_t len = head.u64();
    if (len > size - at - kRecordHead) {
      if (op == static_cast<uint8_t>(Op::footer) || data_end)
        break;  // the summary or footer was cut: the data is whole
      cut_short_ = "cut short at byte " + std::to_string(at) + " of " + std::to_string(size) + ", inside a " +
                   op_name(op) + " record of " + std::to_string(len) + " bytes";
      break;
    }
    const uint64_t body = at + kRecordHead;
    switch (static_cast<Op>(op)) {
      case Op::schema:
      case Op::channel:
      case Op::message:
      case Op::chunk:
      case Op::metadata: {
        if (data_end) break;  // summary copies
        if (len > kMaxChunkBytes + 65536)
          throw FormatError(std::string(op_name(op)) + " record of " + std::to_string(len) + " bytes", at);
        file_->read(body, len, buf);
        Cursor r(buf.data(), buf.size(), body, op_name(op));
        if (op == static_cast<uint8_t>(Op::schema)) {
          add_schema(parse_schema(r), at);
        } else if (op == static_cast<uint8_t>(Op::channel)) {
          add_channel(parse_channel(r), at);
        } else if (op == static_cast<uint8_t>(Op::metadata)) {
          Metadata m;
          m.name = r.str("name");
          m.entries = r.string_map("metadata");
          metadata_.push_back(std::move(m));
          ++stats_.metadata_count;
        } else if (op == static_cast<uint8_t>(Op::message)) {
          const uint64_t t = count_message(r, at);
          blocks_.push_back({at, kRecordHead + len, false, t, t, true});
        } else {  // a chunk: its schemas and channels join the file's, its messages are counted
          const ChunkHead ch = parse_chunk_head(r);
          note_compression(ch.compression);
          if (ch.uncompressed_size > kMaxChunkBytes)
            throw FormatError("chunk of " + std::to_string(ch.uncompressed_size) + " uncompressed bytes (more than " +
                                  std::to_string(kMaxChunkBytes >> 20) + " MiB)",
                              at);
          records.resize(static_cast<std::size_t>(ch.uncompressed_size));
          try {
            detail::decompress(ch.compression, ch.records, ch.compressed_size, records.data(), records.size());
          } catch (const FormatError& e) {
            throw FormatError(e.what(), at);
          }
          if (ch.crc != 0 && detail::crc32_update(0, records.data(), records.size()) != ch.crc)
            throw FormatError("chunk CRC mismatch (its records changed since they were written)", at);
          ++chunks_read_;
          Cursor rc(records.data(), records.size(), 0, "chunk");
          bool any = false;
          while (rc.remaining() > 0) {
            const uint64_t in = rc.offset();
            const uint8_t rop = rc.u8();
            const uint64_t rlen = rc.u64();
            Cursor rr(rc.take(rlen, op_name(rop)), static_cast<std::size_t>(rlen), in + kRecordHead, op_name(rop));
            try {
              if (rop == static_cast<uint8_t>(Op::schema)) {
                add_schema(parse_schema(rr), at);
              } else if (rop == static_cast<uint8_t>(Op::channel)) {
                add_channel(parse_channel(rr), at);
              } else if (rop == static_cast<uint8_t>(Op::message)) {
                count_message(rr, at);
                any = true;
              }
            } catch (const FormatError& e) {
              throw FormatError(std::string("in the chunk at byte ") + std::to_string(at) + ", byte " +
                                    std::to_string(e.offset()) + " of its records: " + e.what(),
                                at);
            }
          }
          ++stats_.chunk_count;
          blocks_.push_back({at, kRecordHead + len, true, ch.start, ch.end, any});
        }
        break;
      }
      case Op::data_end: data_end = true; break;
      case Op::footer:
        at = size;  // the end
        continue;
      case Op::header: throw FormatError("a second header record", at);
      default:  // message indexes, attachments, summary records, later versions' records
        break;
    }
    at = body + len;
  }
  stats_.schema_count = static_cast<uint16_t>(schemas_.size());
  stats_.channel_count = static_cast<uint32_t>(channels_.size());
}

void Reader::for_each_message(const std::function<bool(const MessageView&)>& fn, uint64_t start, uint64_t end) const {
  // Blocks in order of their first message; a heap of loaded messages is drained up to
  // the next block's start, so overlapping chunks come out merged by log time.
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < blocks_.size(); ++i)
    if (blocks_[i].has_messages && blocks_[i].end_time >= start && blocks_[i].start_time <= end) order.push_back(i);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return blocks_[a].start_time != blocks_[b].start_time ? blocks_[a].start_time < blocks_[b].start_time
                                                          : blocks_[a].offset < blocks_[b].offset;
  });
  struct Pending {
    uint64_t log_time;
    uint64_t seq;  // file order among equal times
    std::shared_ptr<const std::vector<unsigned char>> buffer;
    std::size_t at;  // of the message record's channel_id field in buffer
    std::size_t size;
    uint64_t record;  // where the record is, for errors
  };
  const auto later = [](const Pending& a, const Pending& b) {
    return a.log_time != b.log_time ? a.log_time > b.log_time : a.seq > b.seq;
  };
  std::priority_queue<Pending, std::vector<Pending>, decltype(later)> heap(later);
  uint64_t seq = 0;
  std::vector<unsigned char> raw;
  try {
    const auto load = [&](const Block& b) {
      file_->read(b.offset, b.length, raw);
      Cursor r(raw.data(), raw.size(), b.offset, "record");
      const uint8_t op = r.u8();
      if (r.u64() != b.length - kRecordHead || op != static_cast<uint8_t>(b.chunk ? Op::chunk : Op::message))
        throw FormatError(std::string("index points at a ") + op_name(op) + " record of another length, not a " +
                              (b.chunk ? "chunk" : "message"),
                          b.offset);
      auto buffer = std::make_shared<std::vector<unsigned char>>();
      uint64_t base = 0;
      if (b.chunk) {
        Cursor c(raw.data() + kRecordHead, raw.size() - kRecordHead, b.offset + kRecordHead, "chunk");
        const ChunkHead ch = parse_chunk_head(c);
        if (ch.uncompressed_size > kMaxChunkBytes)
          throw FormatError("chunk of " + std::to_string(ch.uncompressed_size) + " uncompressed bytes", b.offset);
        buffer->resize(static_cast<std::size_t>(ch.uncompressed_size));
        try {
          detail::decompress(ch.compression, ch.records, ch.compressed_size, buffer->data(), buffer->size());
        } catch (const FormatError& e) {
          throw FormatError(e.what(), b.offset);
        }
        if (ch.crc != 0 && detail::crc32_update(0, buffer->data(), buffer->size()) != ch.crc)
          throw FormatError("chunk CRC mismatch (its records changed since they were written)", b.offset);
        ++chunks_read_;
      } else {
        buffer->assign(raw.begin(), raw.end());
      }
      Cursor rc(buffer->data(), buffer->size(), base, "chunk");
      while (rc.remaining() > 0) {
        const uint64_t in = rc.offset();
        const uint8_t rop = rc.u8();
        const uint64_t rlen = rc.u64();
        const unsigned char* body = rc.take(rlen, op_name(rop));
        if (rop != static_cast<uint8_t>(Op::message)) continue;
        Cursor m(body, static_cast<std::size_t>(rlen), in + kRecordHead, "message");
        m.u16();
        m.u32();
        const uint64_t log_time = m.u64();
        m.u64();
        if (log_time < b.start_time || log_time > b.end_time)
          throw FormatError("message at log time " + std::to_string(log_time) + ", outside the time range [" +
                                std::to_string(b.start_time) + ", " + std::to_string(b.end_time) +
                                "] given for its chunk",
                            b.offset);
        if (log_time < start || log_time > end) continue;
        heap.push({log_time, seq++, buffer, static_cast<std::size_t>(body - buffer->data()),
                   static_cast<std::size_t>(rlen), b.offset});
      }
    };
    std::size_t next = 0;
    MessageView view;
    for (;;) {
      while (next < order.size() && (heap.empty() || blocks_[order[next]].start_time <= heap.top().log_time))
        load(blocks_[order[next++]]);
      if (heap.empty()) break;
      const Pending p = heap.top();
      heap.pop();
      Cursor m(p.buffer->data() + p.at, p.size, p.record, "message");
      const uint16_t channel = m.u16();
      const auto it = channels_.find(channel);
      if (it == channels_.end())
        throw FormatError("message on channel " + std::to_string(channel) + ", which the file does not define",
                          p.record);
      view.channel = &it->second;
      view.sequence = m.u32();
      view.log_time = m.u64();
      view.publish_time = m.u64();
      view.size = m.remaining();
      view.data = m.take(view.size, "data");
      if (!fn(view)) return;
    }
  } catch (const FormatError& e) {
    throw InputError(path_ + ": corrupt MCAP: " + e.what() + where(e.offset()));
  }
}

}  // namespace plexus::mcap
