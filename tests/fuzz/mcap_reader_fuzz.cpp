// libFuzzer target: reading an MCAP file (common/mcap: reader.cpp) and, as a plexus
// recording (tools/plexus/mcap_recording.cpp), everything `plexus replay` decides from it
// before it publishes (replay_checks.hpp).
//
// Input layout (the seeds in tests/fuzz/corpus/mcap_reader/ follow it; fuzz_seeds.cpp):
//   byte 0 even   the rest is the file, byte for byte (a recording's bytes, mutated)
//   byte 0 odd    the rest drives FuzzedDataProvider to write a file with mcap::Writer:
//                 schemas (plexus types with their IDL, or anything), channels, messages of
//                 any times and bytes, chunk flushes, zstd, lz4 or no compression, closed or
//                 not; then the file is cut at any byte and up to four bytes are overwritten
//
// Checked: the file is read (up to a cut) or refused with an InputError of one line that
// names it; no other exception, crash, leak, hang or undefined behaviour; messages come in
// log-time order; a scanned file's messages are as many as its statistics say.
#include <fuzzer/FuzzedDataProvider.h>

#include <cstddef>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <typeinfo>
#include <vector>

#include "fuzz_support.hpp"
#include "mcap_recording.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/mcap/reader.hpp"
#include "plexus/mcap/writer.hpp"
#include "plexus/msg/messages.hpp"
#include "replay_checks.hpp"

namespace {

using plexus::fuzz::finding;
namespace cli = plexus::cli;
namespace mcap = plexus::mcap;
namespace msg = plexus::msg;

const std::string& file_path() {
  static const std::string path = plexus::fuzz::scratch_dir() + "/fuzz.mcap";
  return path;
}

void write_bytes(const uint8_t* data, std::size_t size) {
  std::ofstream out(file_path(), std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
}

void write_with_writer(FuzzedDataProvider& in) {
  mcap::WriterOptions o;
  o.compression = static_cast<mcap::Compression>(in.ConsumeIntegralInRange(0, 2));
  o.chunk_size = in.ConsumeIntegralInRange<std::size_t>(1024, 8192);
  {
    mcap::Writer w(file_path(), o);
    std::vector<uint16_t> schemas{0}, channels;
    const auto& all = msg::all_type_supports();
    const int n_schemas = in.ConsumeIntegralInRange(0, 3);
    for (int i = 0; i < n_schemas; ++i) {
      if (in.ConsumeBool()) {
        const msg::TypeSupport& ts = *all[in.ConsumeIntegralInRange<std::size_t>(0, all.size() - 1)];
        schemas.push_back(w.add_schema(ts.type_name, "omgidl", ts.schema));
      } else {
        schemas.push_back(w.add_schema(in.ConsumeRandomLengthString(30), in.ConsumeRandomLengthString(10),
                                       in.ConsumeRandomLengthString(60)));
      }
    }
    const int n_channels = in.ConsumeIntegralInRange(0, 4);
    for (int i = 0; i < n_channels; ++i) {
      std::map<std::string, std::string> meta;
      if (in.ConsumeBool())
        meta["qos"] = in.ConsumeBool() ? R"({"reliability":"reliable","durability":"volatile"})"
                                       : in.ConsumeRandomLengthString(60);
      channels.push_back(w.add_channel(schemas[in.ConsumeIntegralInRange<std::size_t>(0, schemas.size() - 1)],
                                       in.ConsumeRandomLengthString(20),
                                       in.ConsumeBool() ? "cdr" : in.ConsumeRandomLengthString(8), meta));
    }
    const int n_messages = channels.empty() ? 0 : in.ConsumeIntegralInRange(0, 64);
    for (int i = 0; i < n_messages; ++i) {
      const uint16_t c = channels[in.ConsumeIntegralInRange<std::size_t>(0, channels.size() - 1)];
      const uint64_t t = in.ConsumeBool()
                             ? in.ConsumeIntegralInRange<uint64_t>(1'700'000'000'000'000'000, 1'700'000'001'000'000'000)
                             : in.ConsumeIntegral<uint64_t>();
      std::vector<unsigned char> data = in.ConsumeBytes<unsigned char>(in.ConsumeIntegralInRange<std::size_t>(0, 200));
      if (in.ConsumeBool()) data.insert(data.begin(), {0x00, 0x01, 0x00, 0x00});
      w.write(c, in.ConsumeIntegral<uint32_t>(), t, in.ConsumeIntegral<uint64_t>(), data.data(), data.size());
      if (in.ConsumeProbability<float>() < 0.1f) w.flush();
    }
    if (in.ConsumeBool())
      w.close();
    else
      w.flush();
  }  // a writer not closed closes here: the cut below makes the file one that was not
  std::error_code ec;
  const auto size = std::filesystem::file_size(file_path(), ec);
  if (ec || size == 0) return;
  if (in.ConsumeBool()) std::filesystem::resize_file(file_path(), in.ConsumeIntegralInRange<uint64_t>(0, size), ec);
  const auto now = std::filesystem::file_size(file_path(), ec);
  if (ec || now == 0) return;
  std::fstream f(file_path(), std::ios::in | std::ios::out | std::ios::binary);
  const int n = in.ConsumeIntegralInRange(0, 4);
  for (int i = 0; i < n; ++i) {
    f.seekp(static_cast<std::streamoff>(in.ConsumeIntegralInRange<uint64_t>(0, now - 1)));
    const char b = static_cast<char>(in.ConsumeIntegral<uint8_t>());
    f.write(&b, 1);
  }
}

void read_file() {
  const mcap::Reader r(file_path());
  for (const auto& [id, ch] : r.channels()) CHECK(ch.schema_id == 0 || r.schemas().count(ch.schema_id));
  uint64_t count = 0, last = 0;
  r.for_each_message([&](const mcap::MessageView& m) {
    CHECK(m.channel != nullptr && r.channels().count(m.channel->id));
    CHECK(m.log_time >= last);
    CHECK(m.size == 0 || m.data != nullptr);
    last = m.log_time;
    ++count;
    return true;
  });
  if (!r.from_summary()) CHECK(count == r.statistics().message_count);
  // A time window reads a subset, in order.
  uint64_t some = 0;
  r.for_each_message([&](const mcap::MessageView&) { return ++some, true; }, 1'700'000'000'000'000'000,
                     1'700'000'000'500'000'000);
  CHECK(some <= count);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  std::error_code ec;
  std::filesystem::remove(file_path(), ec);
  if ((data[0] & 1) == 0) {
    write_bytes(data + 1, size - 1);
  } else {
    FuzzedDataProvider in(data + 1, size - 1);
    write_with_writer(in);
  }
  for (int pass = 0; pass < 2; ++pass) {
    try {
      if (pass == 0) {
        read_file();
      } else {
        const cli::McapRecordingReader rec(file_path());
        plexus::fuzz::read_as_replay(rec, file_path());
      }
    } catch (const plexus::InputError& e) {
      plexus::fuzz::check_one_line(e.what());
      const std::string what = e.what();
      if (what.rfind(file_path(), 0) != 0 && what.rfind("--topics", 0) != 0)
        finding("the refusal does not name the file: " + what);
    } catch (const std::exception& e) {
      finding(std::string("an exception other than InputError escaped: ") + typeid(e).name() + ": " + e.what());
    }
  }
  return 0;
}
