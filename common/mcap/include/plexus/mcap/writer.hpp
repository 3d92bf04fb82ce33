// A small MCAP writer (https://mcap.dev/spec): magic and header; schema, channel and
// metadata records in the data section as they are added; messages in chunks compressed
// with zstd (default) or lz4, each chunk followed by its message indexes; at close() a
// Data End record, the summary (schemas, channels, statistics, chunk indexes, metadata
// indexes, grouped by opcode), summary offsets, the footer and the closing magic.
//
// What reaches the file: the header at once; schemas, channels and metadata when added; a
// chunk when it holds `chunk_size` bytes or when flush() is called. Everything written is
// in the kernel's hands at once (write(2), no user-space buffer), so a process killed
// mid-recording leaves a file that ends after its last complete chunk: Reader reads it up
// to there (reader.hpp, "cut short").
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "plexus/mcap/records.hpp"

namespace plexus::mcap {

struct WriterOptions {
  Compression compression = Compression::zstd;
  int zstd_level = 3;                 ///< 1..19 (zstd's own default is 3)
  std::size_t chunk_size = 1u << 20;  ///< uncompressed bytes of records before a chunk is closed
  std::string profile;                ///< Header.profile ("" : no well-known profile)
  std::string library = "plexus";     ///< Header.library
};
/// InputError naming the option for a level outside 1..19 or a chunk size outside 1 KiB..64 MiB.
void validate(const WriterOptions& o);

class Writer {
 public:
  /// Creates (or truncates) `path` and writes the magic and the header. InputError
  /// "<path>: cannot create recording (<reason>)" when it cannot.
  Writer(const std::string& path, WriterOptions options = {});
  /// Closes the file (close()) if that was not done; errors are swallowed here.
  ~Writer();
  Writer(const Writer&) = delete;
  Writer& operator=(const Writer&) = delete;

  /// A schema id (1, 2, ...). The same name, encoding and data given again returns its id.
  uint16_t add_schema(const std::string& name, const std::string& encoding, std::string_view data);
  /// A channel id (0, 1, ...). std::length_error past 65536 channels.
  uint16_t add_channel(uint16_t schema_id, const std::string& topic, const std::string& message_encoding,
                       const std::map<std::string, std::string>& metadata);
  void add_metadata(const std::string& name, const std::map<std::string, std::string>& entries);

  /// Appends a message to the open chunk; the chunk is written once it holds chunk_size bytes.
  void write(uint16_t channel_id, uint32_t sequence, uint64_t log_time, uint64_t publish_time,
             const unsigned char* data, std::size_t size);
  /// Writes the open chunk (if it holds anything) and its message indexes now.
  void flush();
  /// flush(), then the Data End record, the summary, the footer and the magic. Idempotent.
  void close();

  const Statistics& statistics() const { return stats_; }
  /// Bytes in the file so far (the open chunk not included).
  uint64_t file_size() const { return offset_; }
  const std::string& path() const { return path_; }

 private:
  void put(const void* data, std::size_t size);  // to the file; throws std::runtime_error naming the path
  void put_data_record(const std::vector<unsigned char>& record);

  std::string path_;
  WriterOptions opt_;
  int fd_ = -1;
  uint64_t offset_ = 0;
  uint32_t data_crc_ = 0;  // running CRC-32 of the data section (from the leading magic on)
  bool closed_ = false;

  std::vector<Schema> schemas_;
  std::vector<Channel> channels_;
  std::vector<std::pair<std::string, std::pair<uint64_t, uint64_t>>> metadata_index_;  // name, (offset, length)
  std::vector<ChunkIndex> chunk_indexes_;
  Statistics stats_;

  // The open chunk: its uncompressed records, time range and per-channel (log_time, offset) index.
  std::vector<unsigned char> chunk_;
  uint64_t chunk_start_ = 0, chunk_end_ = 0;
  bool chunk_has_messages_ = false;
  std::map<uint16_t, std::vector<std::pair<uint64_t, uint64_t>>> chunk_index_;
  std::vector<unsigned char> scratch_, compressed_;
  void* zstd_ = nullptr;  // ZSTD_CCtx, reused chunk after chunk
};

}  // namespace plexus::mcap
