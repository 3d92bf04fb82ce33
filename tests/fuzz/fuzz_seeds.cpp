// Writes the generated seeds of three fuzz targets (built in the fuzz build; the output is
// committed):
//
//   build-fuzz/bin/fuzz_seeds tests/fuzz/corpus
//
//   cdr_decode/<Type>[_<n>joints]   one valid sample of every message type, in the input layout
//                                   of cdr_decode_fuzz.cpp (type index, shape byte, XCDR1)
//   recording_reader/recording      a small valid recording (two topics, six samples) written by
//                                   SqliteRecordingWriter, its pages shrunk to 512 bytes, in the input
//                                   layout of recording_reader_fuzz.cpp (byte 0 = 0: the file)
//   mcap_reader/recording_<c>       the same samples as an MCAP recording (McapRecordingWriter),
//                                   zstd, lz4 or uncompressed chunks of one sample pair each;
//   mcap_reader/cut_short           the zstd one as a killed recorder leaves it (no summary, no
//                                   footer), all in the input layout of mcap_reader_fuzz.cpp
//
// The samples are deterministic (fixed values), so the files only change with the types.
#include <sqlite3.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "mcap_recording.hpp"
#include "plexus/distributed/wire.hpp"
#include "plexus/msg/messages.hpp"
#include "sqlite_recording.hpp"

namespace {

namespace msg = plexus::msg;
namespace dist = plexus::distributed;
namespace fs = std::filesystem;

void write(const fs::path& p, const std::vector<unsigned char>& bytes) {
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw std::runtime_error("cannot write " + p.string());
}

/// A sample of `ts`: header stamped; a signal type's fields within their ranges for `joints`.
std::vector<unsigned char> sample_cdr(const msg::TypeSupport& ts, int joints) {
  void* s = ts.create();
  const dist::WireType* wt = dist::find_wire_type(ts.type_name);
  if (wt && ts.header) {  // a type without a header (LinkStatus, nested) carries no signal
    plexus::scenario::SignalSpec spec;
    spec.name = "r1/seed";
    spec.producer = "seed";
    spec.message = wt->name;
    std::vector<const void*> places;
    for (const auto& slot : wt->slots) {
      if (static_cast<int>(slot.index) >= joints) continue;
      const void* place = static_cast<const char*>(slot.member(s)) + slot.index * sizeof(double);
      if (std::find(places.begin(), places.end(), place) != places.end()) continue;
      places.push_back(place);
      spec.fields.push_back(slot.field);
    }
    dist::WireSignal w(spec, 10'000'000);
    plexus::scenario::SignalSample v;
    v.step = 42;
    for (std::size_t i = 0; i < spec.fields.size(); ++i) {
      const auto& slot = *std::find_if(wt->slots.begin(), wt->slots.end(),
                                       [&](const dist::WireSlot& x) { return x.field == spec.fields[i]; });
      v.values[i] = std::clamp(0.25 * static_cast<double>(i + 1), slot.min, slot.max);
    }
    w.encode(v, s);
  }
  if (ts.header) {
    msg::StampHeader& h = *ts.header(s);
    h.seq_num(7);
    if (h.data_time_ns() == 0) h.data_time_ns(420'000'000);
    h.origin_time_ns(1'763'000'000'000'000'000);
    h.publish_time_ns(1'763'000'000'000'250'000);
  }
  std::vector<unsigned char> buf(ts.max_cdr_size);
  buf.resize(ts.serialize(s, buf.data(), buf.size()));
  ts.destroy(s);
  if (buf.empty()) throw std::runtime_error(std::string(ts.type_name) + ": does not serialize");
  return buf;
}

void cdr_seeds(const fs::path& dir) {
  fs::create_directories(dir);
  const auto& all = msg::all_type_supports();
  for (std::size_t i = 0; i < all.size(); ++i) {
    const msg::TypeSupport& ts = *all[i];
    const std::string name = std::string(ts.type_name).substr(std::string("plexus::msg::").size());
    const dist::WireType* wt = dist::find_wire_type(ts.type_name);
    const std::vector<int> shapes = wt && wt->count ? std::vector<int>{16, 3} : std::vector<int>{16};
    for (int joints : shapes) {
      // shape byte: joints - 1; lockstep; step 10 ms (bits 5-6 = 2)
      std::vector<unsigned char> in{static_cast<unsigned char>(i), static_cast<unsigned char>((joints - 1) | (2 << 5))};
      const auto cdr = sample_cdr(ts, joints);
      in.insert(in.end(), cdr.begin(), cdr.end());
      write(dir / (joints == 16 ? name : name + "_" + std::to_string(joints) + "joints"), in);
    }
  }
}

void recording_seed(const fs::path& dir) {
  fs::create_directories(dir);
  const fs::path file = fs::temp_directory_path() / "plexus_fuzz_seed.sqlite";
  fs::remove(file);
  {
    plexus::cli::SqliteRecordingWriter w(file.string());
    const auto& pos = msg::type_support<msg::PositionMeasurement>();
    const auto& beat = msg::type_support<msg::Heartbeat>();
    const int64_t a =
        w.add_topic("r1/position", pos.type_name,
                    R"({"reliability":"best_effort","durability":"volatile","history":"keep_last","depth":1,)"
                    R"("deadline_s":0.0,"liveliness":"automatic","liveliness_lease_s":0.0,"lifespan_s":0.0,)"
                    R"("latency_budget_s":0.0,"ownership":"shared","data_representation":[0]})");
    const int64_t b = w.add_topic("health/observer", beat.type_name, "");
    std::vector<plexus::cli::RecordedMessage> batch;
    for (int k = 0; k < 3; ++k)
      for (const auto& [id, ts] : {std::pair{a, &pos}, std::pair{b, &beat}}) {
        plexus::cli::RecordedMessage m;
        m.topic_id = id;
        m.receive_time_ns = 1'763'000'000'000'000'000 + k * 10'000'000 + (id == b ? 1000 : 0);
        m.seq_num = k + 1;
        m.data_time_ns = 420'000'000;
        m.origin_time_ns = 1'763'000'000'000'000'000;
        m.publish_time_ns = 1'763'000'000'000'250'000;
        m.cdr = sample_cdr(*ts, 16);
        batch.push_back(m);
      }
    w.insert(batch);
    w.commit();
  }
  sqlite3* db = nullptr;
  if (sqlite3_open(file.c_str(), &db) != SQLITE_OK ||
      sqlite3_exec(db, "PRAGMA page_size=512; VACUUM;", nullptr, nullptr, nullptr) != SQLITE_OK)
    throw std::runtime_error("cannot shrink " + file.string());
  sqlite3_close(db);
  std::ifstream in(file, std::ios::binary);
  std::vector<unsigned char> bytes{0};
  bytes.insert(bytes.end(), std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  write(dir / "recording", bytes);
  fs::remove(file);
}

std::vector<unsigned char> file_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::vector<unsigned char> bytes{0};  // byte 0 even: the rest is the file
  bytes.insert(bytes.end(), std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return bytes;
}

void mcap_seeds(const fs::path& dir) {
  fs::create_directories(dir);
  const fs::path file = fs::temp_directory_path() / "plexus_fuzz_seed.mcap";
  const auto& pos = msg::type_support<msg::PositionMeasurement>();
  const auto& beat = msg::type_support<msg::Heartbeat>();
  for (const auto& [name, compression] :
       {std::pair{"zstd", plexus::mcap::Compression::zstd}, std::pair{"lz4", plexus::mcap::Compression::lz4},
        std::pair{"none", plexus::mcap::Compression::none}}) {
    std::vector<unsigned char> cut;
    {
      plexus::cli::RecordingOptions o;
      o.compression = compression;
      o.metadata = {{"recorder", "fuzz_seeds"}};
      plexus::cli::McapRecordingWriter w(file.string(), o);
      const int64_t a = w.add_topic("r1/position", pos, R"({"reliability":"best_effort","durability":"volatile"})");
      const int64_t b = w.add_topic("health/observer", beat, "");
      for (int k = 0; k < 3; ++k) {
        plexus::cli::SampleBatch batch;
        for (const auto& [id, ts] : {std::pair{a, &pos}, std::pair{b, &beat}}) {
          const auto cdr = sample_cdr(*ts, 16);
          msg::StampHeader h;
          h.seq_num(static_cast<uint64_t>(k + 1));
          h.publish_time_ns(1'763'000'000'000'250'000);
          batch.add(id, 1'763'000'000'000'000'000 + k * 10'000'000 + (id == b ? 1000 : 0), &h, cdr.data(), cdr.size());
        }
        w.insert(batch);
        w.flush();  // a chunk per pair of samples
        if (k == 1) cut = file_bytes(file);
      }
      w.commit();
    }
    write(dir / (std::string("recording_") + name), file_bytes(file));
    if (compression == plexus::mcap::Compression::zstd) write(dir / "cut_short", cut);
  }
  fs::remove(file);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: fuzz_seeds CORPUS_DIR (tests/fuzz/corpus)\n");
    return 2;
  }
  try {
    cdr_seeds(fs::path(argv[1]) / "cdr_decode");
    recording_seed(fs::path(argv[1]) / "recording_reader");
    mcap_seeds(fs::path(argv[1]) / "mcap_reader");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz_seeds: %s\n", e.what());
    return 1;
  }
  return 0;
}
