// The records of an MCAP file (https://mcap.dev/spec, major version 0) that plexus writes
// and reads. Integers are little-endian on disk; times are nanoseconds (plexus: since the
// Unix epoch, wall clock).
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>

namespace plexus::mcap {

/// The 8 bytes an MCAP file starts and ends with.
inline constexpr unsigned char kMagic[8] = {0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n'};

/// Record opcodes (the spec's "op").
enum class Op : uint8_t {
  header = 0x01,
  footer = 0x02,
  schema = 0x03,
  channel = 0x04,
  message = 0x05,
  chunk = 0x06,
  message_index = 0x07,
  chunk_index = 0x08,
  attachment = 0x09,
  attachment_index = 0x0A,
  statistics = 0x0B,
  metadata = 0x0C,
  metadata_index = 0x0D,
  summary_offset = 0x0E,
  data_end = 0x0F,
};

/// Chunk compression. MCAP names them "" (none), "zstd" and "lz4" (the LZ4 frame format).
enum class Compression { none, zstd, lz4 };
const char* compression_name(Compression c);

struct Header {
  std::string profile, library;
};

struct Schema {
  uint16_t id = 0;  ///< 1..65535 (0 means "no schema" and is never a record)
  std::string name, encoding, data;
};

struct Channel {
  uint16_t id = 0;
  uint16_t schema_id = 0;  ///< 0: no schema
  std::string topic, message_encoding;
  std::map<std::string, std::string> metadata;
};

/// One message as a reader hands it over: `data` points into the reader's buffer and is
/// valid during the callback only.
struct MessageView {
  const Channel* channel = nullptr;
  uint32_t sequence = 0;
  uint64_t log_time = 0, publish_time = 0;
  const unsigned char* data = nullptr;
  std::size_t size = 0;
};

struct Statistics {
  uint64_t message_count = 0;
  uint16_t schema_count = 0;
  uint32_t channel_count = 0, attachment_count = 0, metadata_count = 0, chunk_count = 0;
  uint64_t message_start_time = 0, message_end_time = 0;  ///< 0 and 0 without messages
  std::map<uint16_t, uint64_t> channel_message_counts;
};

struct ChunkIndex {
  uint64_t message_start_time = 0, message_end_time = 0;
  uint64_t chunk_start_offset = 0, chunk_length = 0;  ///< the whole Chunk record, opcode and length included
  std::map<uint16_t, uint64_t> message_index_offsets;
  uint64_t message_index_length = 0;
  std::string compression;
  uint64_t compressed_size = 0, uncompressed_size = 0;
};

struct Metadata {
  std::string name;
  std::map<std::string, std::string> entries;
};

}  // namespace plexus::mcap
