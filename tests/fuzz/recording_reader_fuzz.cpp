// libFuzzer target: reading a SQLite recording (tools/plexus/sqlite_recording.cpp) and everything `plexus
// replay` decides from it before it publishes (tools/plexus/replay_plan.cpp): the topics,
// their types and recorded QoS, the --summary, each sample's CDR decode, the times it is due
// at and its shifted header times.
//
// Input layout (the seeds in tests/fuzz/corpus/recording_reader/ follow it; fuzz_seeds.cpp):
//   byte 0 even   the rest is the file, byte for byte (a valid recording's bytes, mutated:
//                 a truncated or corrupted SQLite file)
//   byte 0 odd    the rest drives FuzzedDataProvider to write a recording: through
//                 SqliteRecordingWriter (the real schema) or through SQL with no column types or
//                 constraints (a file from another tool), with topics of known or unknown
//                 types, recorded QoS JSON, messages with any times and CDR bytes; then up to
//                 four bytes of the file are overwritten
//
// Checked: the file is read or refused with an InputError of one line that names it; no
// other exception, crash, leak, hang or undefined behaviour; what is accepted is what replay
// can publish (every topic's type known, its QoS within what both vendors apply, every
// sample's due time and shifted header times representable).
#include <fuzzer/FuzzedDataProvider.h>
#include <sqlite3.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <string>
#include <typeinfo>
#include <vector>

#include "fuzz_support.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/msg/messages.hpp"
#include "replay_checks.hpp"
#include "sqlite_recording.hpp"

namespace {

using plexus::fuzz::finding;
namespace cli = plexus::cli;
namespace msg = plexus::msg;

const std::string& recording_path() {
  static const std::string path = plexus::fuzz::scratch_dir() + "/fuzz.sqlite";
  return path;
}

void remove_files() {
  std::error_code ec;
  for (const char* suffix : {"", "-journal", "-wal", "-shm", ".partial", ".partial-journal"})
    std::filesystem::remove(recording_path() + suffix, ec);
}

void write_bytes(const uint8_t* data, std::size_t size) {
  std::ofstream out(recording_path(), std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
}

std::string type_name(FuzzedDataProvider& in) {
  const auto& all = msg::all_type_supports();
  if (in.ConsumeBool()) return all[in.ConsumeIntegralInRange<std::size_t>(0, all.size() - 1)]->type_name;
  return in.ConsumeRandomLengthString(40);
}

std::string qos_json(FuzzedDataProvider& in) {
  switch (in.ConsumeIntegralInRange(0, 2)) {
    case 0: return "";
    case 1:  // the shape plexus record writes, with fuzzed values
      return std::string("{\"reliability\":\"") + (in.ConsumeBool() ? "reliable" : "best_effort") +
             "\",\"durability\":\"" + (in.ConsumeBool() ? "volatile" : "transient") + "\",\"history\":\"" +
             (in.ConsumeBool() ? "keep_last" : "keep_all") +
             "\",\"depth\":" + std::to_string(in.ConsumeIntegral<int64_t>()) +
             ",\"deadline_s\":" + std::to_string(in.ConsumeFloatingPoint<double>()) + ",\"liveliness\":\"automatic\"," +
             "\"liveliness_lease_s\":" + std::to_string(in.ConsumeIntegral<int32_t>()) + ",\"lifespan_s\":0," +
             "\"latency_budget_s\":1e9,\"ownership\":\"shared\",\"data_representation\":[0]}";
    default: return in.ConsumeRandomLengthString(200);
  }
}

int64_t time_ns(FuzzedDataProvider& in) {
  return in.ConsumeBool() ? in.ConsumeIntegralInRange<int64_t>(1'700'000'000'000'000'000, 1'700'001'000'000'000'000)
                          : in.ConsumeIntegral<int64_t>();
}

std::vector<unsigned char> cdr(FuzzedDataProvider& in) {
  std::vector<unsigned char> b = in.ConsumeBytes<unsigned char>(in.ConsumeIntegralInRange<std::size_t>(0, 300));
  if (in.ConsumeBool()) b.insert(b.begin(), {0x00, 0x01, 0x00, 0x00});  // little-endian CDR
  return b;
}

/// Through SqliteRecordingWriter: the schema plexus record --format sqlite writes. False if the writer refused.
bool write_with_writer(FuzzedDataProvider& in) {
  try {
    cli::SqliteRecordingWriter w(recording_path());
    std::vector<int64_t> ids;
    const int topics = in.ConsumeIntegralInRange(0, 4);
    for (int i = 0; i < topics; ++i) {
      const std::string name = in.ConsumeRandomLengthString(32), type = type_name(in), qos = qos_json(in);
      ids.push_back(w.add_topic(name, type, qos));
    }
    std::vector<cli::RecordedMessage> batch;
    const int messages = in.ConsumeIntegralInRange(0, 16);
    for (int i = 0; i < messages; ++i) {
      cli::RecordedMessage m;
      m.topic_id = !ids.empty() && in.ConsumeBool() ? ids[in.ConsumeIntegralInRange<std::size_t>(0, ids.size() - 1)]
                                                    : in.ConsumeIntegral<int64_t>();
      m.receive_time_ns = time_ns(in);
      m.seq_num = in.ConsumeIntegral<int64_t>();
      m.data_time_ns = time_ns(in);
      m.origin_time_ns = time_ns(in);
      m.publish_time_ns = time_ns(in);
      m.cdr = cdr(in);
      batch.push_back(std::move(m));
    }
    w.insert(batch);
    w.commit();
    return true;
  } catch (const std::runtime_error&) {  // a name twice (UNIQUE), a message of no topic (the writer does not check)
    return false;
  }
}

/// One SQL value of any storage class.
void bind_any(FuzzedDataProvider& in, sqlite3_stmt* st, int column) {
  switch (in.ConsumeIntegralInRange(0, 4)) {
    case 0: sqlite3_bind_null(st, column); break;
    case 1: sqlite3_bind_int64(st, column, in.ConsumeIntegral<int64_t>()); break;
    case 2: sqlite3_bind_double(st, column, in.ConsumeFloatingPoint<double>()); break;
    case 3: {
      const std::string s = in.ConsumeRandomLengthString(40);
      sqlite3_bind_text(st, column, s.c_str(), static_cast<int>(s.size()), SQLITE_TRANSIENT);
      break;
    }
    default: {
      const auto b = in.ConsumeBytes<unsigned char>(in.ConsumeIntegralInRange<std::size_t>(0, 64));
      sqlite3_bind_blob(st, column, b.data(), static_cast<int>(b.size()), SQLITE_TRANSIENT);
    }
  }
}

/// Through SQL with untyped columns and no constraints: rows of anything.
void write_with_sql(FuzzedDataProvider& in) {
  sqlite3* db = nullptr;
  if (sqlite3_open(recording_path().c_str(), &db) != SQLITE_OK) finding("cannot create " + recording_path());
  const bool topics_table = in.ConsumeProbability<float>() < 0.95f,
             messages_table = in.ConsumeProbability<float>() < 0.95f;
  if (topics_table) sqlite3_exec(db, "CREATE TABLE topics(id, name, type, qos)", nullptr, nullptr, nullptr);
  if (messages_table)
    sqlite3_exec(db,
                 "CREATE TABLE messages(id INTEGER PRIMARY KEY, topic_id, receive_time_ns, seq_num, data_time_ns,"
                 " origin_time_ns, publish_time_ns, cdr)",
                 nullptr, nullptr, nullptr);
  sqlite3_stmt* st = nullptr;
  const int topics = in.ConsumeIntegralInRange(0, 4);
  if (topics_table && sqlite3_prepare_v2(db, "INSERT INTO topics VALUES(?,?,?,?)", -1, &st, nullptr) == SQLITE_OK) {
    for (int i = 0; i < topics; ++i) {
      if (in.ConsumeBool())
        sqlite3_bind_int64(st, 1, i + 1);
      else
        bind_any(in, st, 1);
      if (in.ConsumeBool())
        sqlite3_bind_text(st, 2, ("t" + std::to_string(i)).c_str(), -1, SQLITE_TRANSIENT);
      else
        bind_any(in, st, 2);
      if (in.ConsumeBool())
        sqlite3_bind_text(st, 3, type_name(in).c_str(), -1, SQLITE_TRANSIENT);
      else
        bind_any(in, st, 3);
      if (in.ConsumeBool())
        sqlite3_bind_text(st, 4, qos_json(in).c_str(), -1, SQLITE_TRANSIENT);
      else
        bind_any(in, st, 4);
      sqlite3_step(st);
      sqlite3_reset(st);
    }
  }
  sqlite3_finalize(st);
  st = nullptr;
  const int messages = in.ConsumeIntegralInRange(0, 16);
  if (messages_table &&
      sqlite3_prepare_v2(db,
                         "INSERT INTO messages(topic_id, receive_time_ns, seq_num, data_time_ns, origin_time_ns,"
                         " publish_time_ns, cdr) VALUES(?,?,?,?,?,?,?)",
                         -1, &st, nullptr) == SQLITE_OK) {
    for (int i = 0; i < messages; ++i) {
      for (int c = 1; c <= 6; ++c)
        if (in.ConsumeBool())
          sqlite3_bind_int64(st, c, c == 1 ? in.ConsumeIntegralInRange(1, 4) : time_ns(in));
        else
          bind_any(in, st, c);
      if (in.ConsumeBool()) {
        const auto b = cdr(in);
        sqlite3_bind_blob(st, 7, b.data(), static_cast<int>(b.size()), SQLITE_TRANSIENT);
      } else {
        bind_any(in, st, 7);
      }
      sqlite3_step(st);
      sqlite3_reset(st);
    }
  }
  sqlite3_finalize(st);
  sqlite3_close(db);
}

void corrupt(FuzzedDataProvider& in) {
  const int n = in.ConsumeIntegralInRange(0, 4);
  std::error_code ec;
  const auto size = std::filesystem::file_size(recording_path(), ec);
  if (ec || size == 0) return;
  std::fstream f(recording_path(), std::ios::in | std::ios::out | std::ios::binary);
  for (int i = 0; i < n; ++i) {
    f.seekp(static_cast<std::streamoff>(in.ConsumeIntegralInRange<uint64_t>(0, size - 1)));
    const char b = static_cast<char>(in.ConsumeIntegral<uint8_t>());
    f.write(&b, 1);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  remove_files();
  if ((data[0] & 1) == 0) {
    write_bytes(data + 1, size - 1);
  } else {
    FuzzedDataProvider in(data + 1, size - 1);
    if (in.ConsumeBool()) {
      if (!write_with_writer(in)) return 0;
    } else {
      write_with_sql(in);
    }
    corrupt(in);
  }
  try {
    const cli::SqliteRecordingReader rec(recording_path());
    plexus::fuzz::read_as_replay(rec, recording_path());
  } catch (const plexus::InputError& e) {
    plexus::fuzz::check_one_line(e.what());
    const std::string what = e.what();
    if (what.rfind(recording_path(), 0) != 0 && what.rfind("--topics", 0) != 0)
      finding("the refusal does not name the recording: " + what);
  } catch (const std::exception& e) {
    finding(std::string("an exception other than InputError escaped: ") + typeid(e).name() + ": " + e.what());
  }
  return 0;
}
