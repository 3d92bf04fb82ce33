#include "sqlite_recording.hpp"

#include <sqlite3.h>

#include <algorithm>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <stdexcept>

#include "plexus/base/input_error.hpp"

namespace plexus::cli {
namespace {

void exec(sqlite3* db, const char* sql, const std::string& path) {
  char* err = nullptr;
  if (sqlite3_exec(db, sql, nullptr, nullptr, &err) != SQLITE_OK) {
    const std::string msg = err ? err : "unknown error";
    sqlite3_free(err);
    throw std::runtime_error(path + ": " + msg);
  }
}

}  // namespace

SqliteRecordingWriter::SqliteRecordingWriter(const std::string& path) : path_(path), partial_(path + ".partial") {
  std::error_code ec;
  std::filesystem::remove(partial_, ec);
  if (sqlite3_open_v2(partial_.c_str(), &db_, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr) != SQLITE_OK) {
    const std::string msg = db_ ? sqlite3_errmsg(db_) : "out of memory";
    sqlite3_close(db_);
    db_ = nullptr;
    throw InputError(path + ": cannot create recording (" + msg + ")");
  }
  try {
    exec(db_,
         "PRAGMA synchronous=NORMAL;"
         "CREATE TABLE meta(key TEXT PRIMARY KEY, value TEXT);"
         "INSERT INTO meta VALUES('format', 'plexus-recording-1');"
         "CREATE TABLE topics(id INTEGER PRIMARY KEY, name TEXT NOT NULL UNIQUE, type TEXT NOT NULL, qos TEXT);"
         "CREATE TABLE messages(id INTEGER PRIMARY KEY, topic_id INTEGER NOT NULL REFERENCES topics(id),"
         " receive_time_ns INTEGER NOT NULL, seq_num INTEGER, data_time_ns INTEGER, origin_time_ns INTEGER,"
         " publish_time_ns INTEGER, cdr BLOB NOT NULL);",
         path);
  } catch (const std::runtime_error& e) {
    sqlite3_close(db_);
    db_ = nullptr;
    throw InputError(path + ": cannot create recording (" + std::string(e.what()).substr(path.size() + 2) + ")");
  }
  sqlite3_prepare_v2(db_,
                     "INSERT INTO messages(topic_id, receive_time_ns, seq_num, data_time_ns, origin_time_ns,"
                     " publish_time_ns, cdr) VALUES(?,?,?,?,?,?,?)",
                     -1, &insert_, nullptr);
}

SqliteRecordingWriter::~SqliteRecordingWriter() {
  if (insert_) sqlite3_finalize(insert_);
  if (db_) {  // not committed: the recording failed
    sqlite3_close(db_);
    std::error_code ec;
    std::filesystem::remove(partial_, ec);
  }
}

void SqliteRecordingWriter::commit() {
  if (!db_) return;
  if (insert_) sqlite3_finalize(insert_);
  insert_ = nullptr;
  exec(db_, "CREATE INDEX IF NOT EXISTS messages_time ON messages(receive_time_ns)", partial_);
  sqlite3_close(db_);
  db_ = nullptr;
  std::error_code ec;
  std::filesystem::rename(partial_, path_, ec);
  if (ec) throw InputError(path_ + ": cannot write the recording (" + ec.message() + ")");
}

int64_t SqliteRecordingWriter::add_topic(const std::string& name, const std::string& type,
                                         const std::string& qos_json) {
  sqlite3_stmt* st = nullptr;
  sqlite3_prepare_v2(db_, "INSERT INTO topics(name, type, qos) VALUES(?,?,?)", -1, &st, nullptr);
  sqlite3_bind_text(st, 1, name.c_str(), -1, SQLITE_TRANSIENT);
  sqlite3_bind_text(st, 2, type.c_str(), -1, SQLITE_TRANSIENT);
  sqlite3_bind_text(st, 3, qos_json.c_str(), -1, SQLITE_TRANSIENT);
  const int rc = sqlite3_step(st);
  sqlite3_finalize(st);
  if (rc != SQLITE_DONE) throw std::runtime_error(path_ + ": " + sqlite3_errmsg(db_));
  return sqlite3_last_insert_rowid(db_);
}

void SqliteRecordingWriter::insert(const std::vector<RecordedMessage>& batch) {
  if (batch.empty()) return;
  exec(db_, "BEGIN", path_);
  for (const auto& m : batch) {
    sqlite3_bind_int64(insert_, 1, m.topic_id);
    sqlite3_bind_int64(insert_, 2, m.receive_time_ns);
    sqlite3_bind_int64(insert_, 3, m.seq_num);
    sqlite3_bind_int64(insert_, 4, m.data_time_ns);
    sqlite3_bind_int64(insert_, 5, m.origin_time_ns);
    sqlite3_bind_int64(insert_, 6, m.publish_time_ns);
    sqlite3_bind_blob(insert_, 7, m.cdr.data(), static_cast<int>(m.cdr.size()), SQLITE_STATIC);
    if (sqlite3_step(insert_) != SQLITE_DONE) {
      const std::string msg = sqlite3_errmsg(db_);
      sqlite3_reset(insert_);
      sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
      throw std::runtime_error(path_ + ": " + msg);
    }
    sqlite3_reset(insert_);
  }
  exec(db_, "COMMIT", path_);
}

void SqliteRecordingWriter::insert(const SampleBatch& batch) {
  if (batch.empty()) return;
  exec(db_, "BEGIN", path_);
  for (const auto& m : batch.entries) {
    sqlite3_bind_int64(insert_, 1, m.topic_id);
    sqlite3_bind_int64(insert_, 2, m.receive_time_ns);
    sqlite3_bind_int64(insert_, 3, m.seq_num);
    sqlite3_bind_int64(insert_, 4, m.data_time_ns);
    sqlite3_bind_int64(insert_, 5, m.origin_time_ns);
    sqlite3_bind_int64(insert_, 6, m.publish_time_ns);
    sqlite3_bind_blob(insert_, 7, batch.cdr(m), static_cast<int>(m.size), SQLITE_STATIC);
    if (sqlite3_step(insert_) != SQLITE_DONE) {
      const std::string msg = sqlite3_errmsg(db_);
      sqlite3_reset(insert_);
      sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
      throw std::runtime_error(path_ + ": " + msg);
    }
    sqlite3_reset(insert_);
  }
  exec(db_, "COMMIT", path_);
}

SqliteRecordingReader::SqliteRecordingReader(const std::string& path) : path_(path) {
  if (!std::filesystem::is_regular_file(path)) throw InputError(path + ": no such file");
  if (sqlite3_open_v2(path.c_str(), &db_, SQLITE_OPEN_READONLY, nullptr) != SQLITE_OK) {
    sqlite3_close(db_);
    db_ = nullptr;
    throw InputError(path + ": cannot open recording");
  }
  // A recording cut short (a copy interrupted, a full disk) can still open and list its
  // topics; SQLite's own check finds it. quick_check reads every page: linear in the size.
  sqlite3_stmt* st = nullptr;
  std::string check = "not run";
  if (sqlite3_prepare_v2(db_, "PRAGMA quick_check", -1, &st, nullptr) == SQLITE_OK && sqlite3_step(st) == SQLITE_ROW)
    check = reinterpret_cast<const char*>(sqlite3_column_text(st, 0));
  else
    check = sqlite3_errmsg(db_);
  sqlite3_finalize(st);
  st = nullptr;
  for (auto& c : check)
    if (c == '\n') c = ' ';  // one line
  if (check != "ok") {
    sqlite3_close(db_);
    db_ = nullptr;
    throw InputError(path + ": truncated or corrupt recording (SQLite: " + check + ")");
  }
  if (sqlite3_prepare_v2(db_, "SELECT id, name, type, IFNULL(qos, '') FROM topics ORDER BY id", -1, &st, nullptr) !=
      SQLITE_OK) {
    sqlite3_close(db_);
    db_ = nullptr;
    throw InputError(path + ": not a plexus recording (no topics table)");
  }
  // Written by RecordingWriter, every topic has an id, a name and a type, each id and name
  // once; a file that breaks this was not (or no longer is) a plexus recording.
  int rc = 0;
  std::string bad;
  std::set<std::string> names;
  while ((rc = sqlite3_step(st)) == SQLITE_ROW) {
    RecordedTopic t;
    const auto* name = reinterpret_cast<const char*>(sqlite3_column_text(st, 1));
    const auto* type = reinterpret_cast<const char*>(sqlite3_column_text(st, 2));
    const auto* qos = reinterpret_cast<const char*>(sqlite3_column_text(st, 3));
    t.id = sqlite3_column_int64(st, 0);
    if (sqlite3_column_type(st, 0) != SQLITE_INTEGER)
      bad = "a topic without an integer id";
    else if (!name || !type || !qos)
      bad = "topic " + std::to_string(t.id) + " without a name or a type";
    else if (!topics_.empty() && topics_.back().id == t.id)
      bad = "topic id " + std::to_string(t.id) + " twice";
    if (!bad.empty()) break;
    t.name = name;
    t.type = type;
    t.qos_json = qos;
    if (!names.insert(t.name).second) {
      bad = "topic '" + t.name + "' twice";
      break;
    }
    topics_.push_back(std::move(t));
  }
  if (bad.empty() && rc != SQLITE_DONE) bad = std::string("truncated or corrupt (SQLite: ") + sqlite3_errmsg(db_) + ")";
  sqlite3_finalize(st);
  if (!bad.empty()) {
    sqlite3_close(db_);
    db_ = nullptr;
    throw InputError(path + ": not a plexus recording: " + bad);
  }
}

SqliteRecordingReader::~SqliteRecordingReader() {
  if (db_) sqlite3_close(db_);
}

int64_t SqliteRecordingReader::message_count() const {
  sqlite3_stmt* st = nullptr;
  int64_t n = 0;
  if (sqlite3_prepare_v2(db_, "SELECT COUNT(*) FROM messages", -1, &st, nullptr) == SQLITE_OK &&
      sqlite3_step(st) == SQLITE_ROW)
    n = sqlite3_column_int64(st, 0);
  sqlite3_finalize(st);
  return n;
}

void SqliteRecordingReader::for_each(const std::function<bool(const RecordedMessage&)>& fn) const {
  sqlite3_stmt* raw = nullptr;
  if (sqlite3_prepare_v2(
          db_,
          "SELECT topic_id, receive_time_ns, seq_num, data_time_ns, origin_time_ns, publish_time_ns, cdr,"
          " id FROM messages ORDER BY receive_time_ns, id",
          -1, &raw, nullptr) != SQLITE_OK) {
    sqlite3_finalize(raw);
    throw InputError(path_ + ": not a plexus recording (no messages table)");
  }
  // Finalized however the loop ends (fn may throw): an open statement keeps the file open.
  const std::unique_ptr<sqlite3_stmt, int (*)(sqlite3_stmt*)> owner(raw, sqlite3_finalize);
  sqlite3_stmt* st = raw;
  // RecordingWriter binds six integers and a blob, with the receive time from this machine's
  // wall clock; a row that is otherwise was not written by it.
  const auto refuse = [&](const std::string& why) { throw InputError(path_ + ": not a plexus recording: " + why); };
  std::set<int64_t> topic_ids;
  for (const auto& t : topics_) topic_ids.insert(t.id);
  // The rows come through the receive-time index, which quick_check does not compare with
  // the table: a damaged index gave rows out of order (found by fuzzing), or could drop or
  // repeat some. Checked here for the cost of a count: the order row by row, the number of
  // rows against the table's own at the end.
  RecordedMessage m;
  int64_t rows = 0, last_receive = std::numeric_limits<int64_t>::min();
  bool stopped = false;
  int rc = 0;
  while ((rc = sqlite3_step(st)) == SQLITE_ROW) {
    const std::string row = "message " + std::to_string(sqlite3_column_int64(st, 7));
    for (int c = 0; c < 6; ++c)
      if (sqlite3_column_type(st, c) != SQLITE_INTEGER)
        refuse(row + ": " + sqlite3_column_name(st, c) + " is not an integer");
    if (sqlite3_column_type(st, 6) != SQLITE_BLOB && sqlite3_column_type(st, 6) != SQLITE_NULL)
      refuse(row + ": cdr is not a blob");
    m.topic_id = sqlite3_column_int64(st, 0);
    m.receive_time_ns = sqlite3_column_int64(st, 1);
    m.seq_num = sqlite3_column_int64(st, 2);
    m.data_time_ns = sqlite3_column_int64(st, 3);
    m.origin_time_ns = sqlite3_column_int64(st, 4);
    m.publish_time_ns = sqlite3_column_int64(st, 5);
    if (m.receive_time_ns < 0) refuse(row + ": negative receive time " + std::to_string(m.receive_time_ns));
    if (m.receive_time_ns < last_receive)
      refuse("truncated or corrupt (messages out of receive-time order: a damaged index)");
    last_receive = m.receive_time_ns;
    ++rows;
    if (!topic_ids.count(m.topic_id))
      refuse(row + ": topic " + std::to_string(m.topic_id) + " is not in the topics table");
    const auto* blob = static_cast<const unsigned char*>(sqlite3_column_blob(st, 6));
    const int bytes = sqlite3_column_bytes(st, 6);
    if (!blob && bytes > 0) refuse(row + ": out of memory reading its cdr");
    m.cdr.assign(blob, blob + bytes);
    if (!fn(m)) {
      stopped = true;
      break;
    }
  }
  if (rc != SQLITE_ROW && rc != SQLITE_DONE)
    refuse(std::string("truncated or corrupt (SQLite: ") + sqlite3_errmsg(db_) + ")");
  if (!stopped) {
    sqlite3_stmt* count = nullptr;
    int64_t in_table = -1;
    if (sqlite3_prepare_v2(db_, "SELECT COUNT(*) FROM messages NOT INDEXED", -1, &count, nullptr) == SQLITE_OK &&
        sqlite3_step(count) == SQLITE_ROW)
      in_table = sqlite3_column_int64(count, 0);
    sqlite3_finalize(count);
    if (in_table != rows)
      refuse("truncated or corrupt (" + std::to_string(rows) + " messages through the index, " +
             (in_table < 0 ? std::string("an unreadable table") : std::to_string(in_table) + " in the table") +
             ": a damaged index)");
  }
}

RecordingInfo SqliteRecordingReader::info() const {
  RecordingInfo info;
  info.format = "sqlite";
  std::map<int64_t, std::size_t> index;
  for (const auto& t : topics_) {
    index[t.id] = info.topics.size();
    info.topics.push_back({t.name, t.type, t.qos_json, 0});
  }
  sqlite3_stmt* st = nullptr;
  if (sqlite3_prepare_v2(db_,
                         "SELECT topic_id, COUNT(*), MIN(receive_time_ns), MAX(receive_time_ns) FROM messages"
                         " GROUP BY topic_id",
                         -1, &st, nullptr) != SQLITE_OK) {
    sqlite3_finalize(st);
    throw InputError(path_ + ": not a plexus recording (no messages table)");
  }
  bool first = true;
  while (sqlite3_step(st) == SQLITE_ROW) {
    const auto it = index.find(sqlite3_column_int64(st, 0));
    if (it == index.end()) continue;
    const auto n = static_cast<uint64_t>(sqlite3_column_int64(st, 1));
    info.topics[it->second].messages = n;
    info.messages += n;
    const int64_t lo = sqlite3_column_int64(st, 2), hi = sqlite3_column_int64(st, 3);
    info.start_ns = first ? lo : std::min(info.start_ns, lo);
    info.end_ns = first ? hi : std::max(info.end_ns, hi);
    first = false;
  }
  sqlite3_finalize(st);
  return info;
}

}  // namespace plexus::cli
