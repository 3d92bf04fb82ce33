#include "recording.hpp"

#include <filesystem>

#include "mcap_recording.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/mcap/reader.hpp"
#include "sqlite_recording.hpp"

namespace plexus::cli {

void SampleBatch::add(int64_t topic_id, int64_t receive_time_ns, const msg::StampHeader* header,
                      const unsigned char* cdr, std::size_t size) {
  Entry e{topic_id, receive_time_ns, 0, 0, 0, 0, bytes.size(), size};
  if (header) {
    e.seq_num = static_cast<int64_t>(header->seq_num());
    e.data_time_ns = header->data_time_ns();
    e.origin_time_ns = header->origin_time_ns();
    e.publish_time_ns = header->publish_time_ns();
  }
  bytes.insert(bytes.end(), cdr, cdr + size);
  entries.push_back(e);
}

RecordingFormat recording_format(const std::string& path, const std::string& option) {
  if (option == "mcap") return RecordingFormat::mcap;
  if (option == "sqlite") return RecordingFormat::sqlite;
  if (!option.empty()) throw InputError("--format: '" + option + "' is not a recording format (mcap or sqlite)");
  const std::string ext = std::filesystem::path(path).extension().string();
  return ext == ".sqlite" || ext == ".db" || ext == ".db3" ? RecordingFormat::sqlite : RecordingFormat::mcap;
}

mcap::Compression recording_compression(const std::string& option) {
  if (option == "zstd") return mcap::Compression::zstd;
  if (option == "lz4") return mcap::Compression::lz4;
  if (option == "none") return mcap::Compression::none;
  throw InputError("--compression: '" + option + "' is not a chunk compression (zstd, lz4 or none)");
}

std::unique_ptr<RecordingWriter> make_recording_writer(const std::string& path, const RecordingOptions& options) {
  if (options.format == RecordingFormat::sqlite) return std::make_unique<SqliteRecordingWriter>(path);
  return std::make_unique<McapRecordingWriter>(path, options);
}

std::unique_ptr<RecordingReader> open_recording(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw InputError(path + ": no such file");
  if (mcap::is_mcap_file(path)) return std::make_unique<McapRecordingReader>(path);
  return std::make_unique<SqliteRecordingReader>(path);
}

bool header_from_cdr(const unsigned char* cdr, std::size_t size, msg::StampHeader& h) {
  // Encapsulation: 0x00 0x00 plain CDR big-endian, 0x00 0x01 little-endian; then the
  // header's four 8-byte members at offsets 0, 8, 16, 24 of the body (aligned: the body starts at 4).
  if (size < 4 + 32 || cdr[0] != 0x00 || cdr[1] > 0x01) return false;
  const bool little = cdr[1] == 0x01;
  const auto u64 = [&](std::size_t at) {
    uint64_t v = 0;
    for (int i = 0; i < 8; ++i) {
      const uint64_t b = cdr[4 + at + static_cast<std::size_t>(i)];
      v |= little ? b << (8 * i) : b << (8 * (7 - i));
    }
    return v;
  };
  h.seq_num(u64(0));
  h.data_time_ns(static_cast<int64_t>(u64(8)));
  h.origin_time_ns(static_cast<int64_t>(u64(16)));
  h.publish_time_ns(static_cast<int64_t>(u64(24)));
  return true;
}

}  // namespace plexus::cli
