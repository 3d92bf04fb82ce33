// A small MCAP reader (https://mcap.dev/spec).
//
// A complete file is read through its summary: the footer gives the summary, which lists
// the schemas, the channels, the statistics and where every chunk is, so topics and counts
// come without reading the data section, and messages are read chunk by chunk, skipping
// chunks outside a requested time range. A file without a summary, or cut short (no
// footer: its writer was killed), is scanned forward from the header and read up to the
// last complete record; cut_short() then says where and why.
//
// Bad input (not MCAP, a record that runs past its parent, a chunk whose CRC, size or
// compression does not check, an index pointing at something else) is an InputError with
// one line naming the file, the byte offset and what is wrong; never a crash.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "plexus/mcap/records.hpp"

namespace plexus::mcap {

/// True if `path` starts with the MCAP magic (false if it cannot be read).
bool is_mcap_file(const std::string& path);

class Reader {
 public:
  /// Opens `path` and reads its summary, or scans it. InputError "<path>: no such file",
  /// "<path>: not an MCAP file (...)" or "<path>: corrupt MCAP: <what> at byte N".
  explicit Reader(const std::string& path);
  ~Reader();
  Reader(const Reader&) = delete;
  Reader& operator=(const Reader&) = delete;

  const Header& header() const { return header_; }
  const std::map<uint16_t, Schema>& schemas() const { return schemas_; }
  const std::map<uint16_t, Channel>& channels() const { return channels_; }
  /// From the summary's Statistics record, or counted by the scan.
  const Statistics& statistics() const { return stats_; }
  const std::vector<Metadata>& metadata() const { return metadata_; }
  /// True when schemas, channels and statistics came from the summary (no scan).
  bool from_summary() const { return from_summary_; }
  /// Empty for a file that ends with its footer and magic; else one line: where the file
  /// ends early and why ("no footer: cut short at byte N of M, inside a chunk record").
  const std::string& cut_short() const { return cut_short_; }
  /// The chunks' compression: "zstd", "lz4", "none", "mixed", or "" (no chunks).
  const std::string& compression() const { return compression_; }
  /// Chunks this reader has read (decompressed) so far: opening an indexed file reads none.
  uint64_t chunks_read() const { return chunks_read_; }

  /// Every message with start <= log_time <= end, in log_time order (ties in file order),
  /// until `fn` returns false. Chunks whose time range lies outside are not read.
  void for_each_message(const std::function<bool(const MessageView&)>& fn, uint64_t start = 0,
                        uint64_t end = std::numeric_limits<uint64_t>::max()) const;

  /// Where messages are: a chunk, or one message record outside any chunk.
  struct Block {
    uint64_t offset = 0;  ///< of the record (Chunk or Message)
    uint64_t length = 0;  ///< of the whole record
    bool chunk = true;
    uint64_t start_time = 0, end_time = 0;
    bool has_messages = true;  ///< false for a chunk whose index says it holds none
  };

 private:
  void read_summary(uint64_t summary_start, uint64_t footer_offset, uint32_t summary_crc);
  void scan();
  void note_compression(const std::string& c);
  std::string where(uint64_t offset) const;

  struct File;
  std::unique_ptr<File> file_;
  std::string path_;
  Header header_;
  uint64_t data_start_ = 0;  // first record after the header
  std::map<uint16_t, Schema> schemas_;
  std::map<uint16_t, Channel> channels_;
  Statistics stats_;
  std::vector<Metadata> metadata_;
  std::vector<Block> blocks_;
  bool from_summary_ = false;
  std::string cut_short_;
  std::string compression_;
  mutable uint64_t chunks_read_ = 0;
};

}  // namespace plexus::mcap
