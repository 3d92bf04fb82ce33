// plexus record -o FILE [--topics a,b]: records topics to a plexus recording (recording.hpp:
// MCAP by default, SQLite for a *.sqlite file or --format sqlite), with the receive time and
// the header times of every sample and its CDR bytes as received.
//
// One reader thread per topic waits on its reader and takes each sample with its bytes as
// they arrived (take_raw: the receive time is the arrival, not a polling tick, and the CDR
// is the writer's, not re-encoded); the main thread writes what they took every 100 ms and
// hands the file a finished chunk every second, so a recorder killed loses at most that.
//
// plexus record info FILE: a recording's summary (counts, span, topics with type and QoS);
// of a complete MCAP file from its summary section alone.
// plexus record convert IN OUT: a recording into another format (an old SQLite one into MCAP).
#include <algorithm>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <map>
#include <mutex>
#include <set>
#include <thread>

#include "command.hpp"
#include "plexus/base/clock.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/msg/header.h"
#include "plexus/msg/messages.hpp"
#include "recording.hpp"
#include "sample_queue.hpp"
#include "topic_discovery.hpp"

namespace plexus::cli {
namespace {

struct RecordOpts {
  DdsOptions dds;
  std::string out, topics, qos_file, profile, format, compression = "zstd";
  double wait = 1.5, duration = 0;
  int count = 0;
  std::string file, in;  // record info FILE; record convert IN OUT (OUT in `out`)
  bool json = false;
};

struct TopicReader {
  std::string name;
  const msg::TypeSupport* ts = nullptr;
  int64_t id = 0;
  std::unique_ptr<rt::ReaderBackend> reader;
};

RecordingOptions writer_options(const RecordOpts& o, const std::string& recorder) {
  RecordingOptions w;
  w.format = recording_format(o.out, o.format);
  w.compression = recording_compression(o.compression);
  w.library = std::string("plexus ") + PLEXUS_VERSION;
  w.metadata = {{"recorder", recorder}, {"version", PLEXUS_VERSION}};
  return w;
}

int run_record(const RecordOpts& o) {
  rt::parse_vendor(o.dds.dds);
  if (o.out.empty()) throw InputError("-o/--out: a recording file is required");
  if (!(o.duration >= 0)) throw InputError("--duration: must be >= 0 seconds");
  if (o.count < 0) throw InputError("--count: must be >= 0");
  if (!(o.wait >= 0 && o.wait <= 600)) throw InputError("--wait: must be in 0..600 seconds");
  if (!o.profile.empty())
    rt::QosProfiles::load(o.qos_file.empty() ? rt::default_qos_file() : o.qos_file).get(o.profile);
  RecordingOptions wo = writer_options(o, "plexus record");
  wo.metadata["vendor"] = o.dds.dds;
  wo.metadata["domain"] = std::to_string(o.dds.domain);
  auto file = make_recording_writer(o.out, wo);  // file errors first: exit 2 before any DDS work
  install_stop_handler();
  auto p = make_participant(o.dds, "plexus_record", "plexus_record");

  // Which topics: the given ones (waiting for their writers), or every topic with a writer,
  // including topics that appear while recording (discovery is polled, as rosbag2 does).
  const std::vector<std::string> wanted = split_comma_list(o.topics);
  auto writers_now = [&] {
    std::map<std::string, std::vector<rt::DiscoveredEndpoint>> w;
    for (const auto& e : p->discovered_endpoints())
      if (!e.local && e.is_writer) w[e.topic].push_back(e);
    return w;
  };
  if (!wanted.empty()) {
    const int64_t end_wait = monotonic_ns() + static_cast<int64_t>(o.wait * 1e9);
    for (;;) {
      const auto w = writers_now();
      bool all = true;
      for (const auto& t : wanted) all = all && w.count(t);
      if (all) break;
      if (g_stop || monotonic_ns() >= end_wait) {
        for (const auto& t : wanted)
          if (!w.count(t))
            throw std::runtime_error("--topics: no writer on topic '" + t + "' was discovered in " +
                                     std::to_string(o.wait).substr(0, 4) + " s");
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  }

  SampleQueue queue;
  SampleBatch batch;
  std::atomic<bool> done{false};
  std::deque<TopicReader> readers;  // deque: references stay valid as topics are added
  std::set<std::string> known;      // topics subscribed or skipped
  std::vector<std::thread> threads;
  auto add_topics = [&] {
    for (const auto& [t, ws] : writers_now()) {
      if (known.count(t) || (!wanted.empty() && std::find(wanted.begin(), wanted.end(), t) == wanted.end())) continue;
      known.insert(t);
      const msg::TypeSupport* ts = msg::find_type_support(ws.front().type_name);
      if (!ts) {
        std::fprintf(stderr, "plexus record: skipping '%s': type '%s' unknown to this build\n", t.c_str(),
                     ws.front().type_name.c_str());
        continue;
      }
      std::vector<rt::EndpointQos> qos;
      for (const auto& w : ws) qos.push_back(w.qos);
      TopicReader& r = readers.emplace_back();
      r.name = t;
      r.ts = ts;
      r.id = file->add_topic(t, *ts, qos_to_json(ws.front().qos).dump());
      r.reader = p->make_reader(*ts, t, subscriber_qos(o.qos_file, o.profile, qos, 1000));
      threads.emplace_back([&, rp = &r] {
        void* sample = rp->ts->create();
        std::vector<unsigned char> cdr;
        cdr.reserve(rp->ts->max_cdr_size);
        rt::SampleMeta meta;
        while (!done && !g_stop) {
          if (!rp->reader->wait(50'000'000)) continue;
          while (rp->reader->take_raw(sample, cdr, &meta)) {
            queue.push(rp->id, meta.receive_time_ns, rp->ts->header ? rp->ts->header(sample) : nullptr, cdr.data(),
                       cdr.size());
            if (o.count > 0 && queue.pushed() >= static_cast<uint64_t>(o.count)) done = true;
          }
        }
        rp->ts->destroy(sample);
      });
      std::fprintf(stderr, "plexus record: recording '%s' (%s)\n", t.c_str(), ts->type_name);
    }
  };
  add_topics();
  const int64_t end = o.duration > 0 ? monotonic_ns() + static_cast<int64_t>(o.duration * 1e9) : INT64_MAX;
  uint64_t written = 0;
  auto write_pending = [&] {
    queue.take(batch);
    if (o.count > 0 && written + batch.entries.size() > static_cast<uint64_t>(o.count))
      batch.entries.resize(static_cast<std::size_t>(static_cast<uint64_t>(o.count) - written));
    file->insert(batch);
    written += batch.entries.size();
  };
  int tick = 0;
  while (!done && !g_stop && monotonic_ns() < end) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    write_pending();
    if (++tick % 10 == 0) file->flush();  // a finished chunk every second: a kill loses at most that
    if (wanted.empty() || readers.size() < wanted.size())
      if (tick % 2 == 0) add_topics();
  }
  done = true;
  for (auto& t : threads) t.join();
  write_pending();
  const std::size_t n_topics = readers.size();
  readers.clear();
  if (n_topics == 0) {
    // `file` is not committed: nothing is written, an existing recording at -o is left as it was.
    std::fprintf(stderr, "plexus record: error: no topic with a writer was discovered on domain %d; %s not written\n",
                 o.dds.domain, o.out.c_str());
    return 1;
  }
  file->commit();
  std::printf("recorded %llu samples from %zu topic(s) to %s\n", static_cast<unsigned long long>(written), n_topics,
              o.out.c_str());
  return 0;
}

int run_info(const RecordOpts& o) {
  const auto rec = open_recording(o.file);
  const RecordingInfo info = rec->info();
  if (o.json) {
    nlohmann::ordered_json j;
    j["file"] = o.file;
    j["format"] = info.format;
    j["complete"] = info.cut_short.empty();
    if (!info.cut_short.empty()) j["cut_short"] = info.cut_short;
    if (info.format == "mcap") j["from_summary"] = info.from_summary;
    j["messages"] = info.messages;
    j["topics"] = info.topics.size();
    if (info.format == "mcap") {
      j["schemas"] = info.schemas;
      j["chunks"] = info.chunks;
      j["compression"] = info.compression;
    }
    j["start_ns"] = info.start_ns;
    j["end_ns"] = info.end_ns;
    j["duration_s"] = static_cast<double>(info.end_ns - info.start_ns) * 1e-9;
    if (!info.metadata.empty()) j["metadata"] = info.metadata;
    j["channels"] = nlohmann::ordered_json::array();
    for (const auto& t : info.topics) {
      nlohmann::ordered_json c = {{"topic", t.name}, {"type", t.type}, {"messages", t.messages}};
      c["qos"] =
          t.qos_json.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json::parse(t.qos_json, nullptr, false);
      j["channels"].push_back(c);
    }
    std::printf("%s\n", j.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace).c_str());
    return 0;
  }
  std::printf("%s: %s, %s\n", o.file.c_str(), info.format == "mcap" ? "MCAP" : "SQLite (plexus-recording-1)",
              info.cut_short.empty() ? "complete" : ("CUT SHORT: " + info.cut_short).c_str());
  std::printf("messages %llu on %zu topic(s), %.3f s", static_cast<unsigned long long>(info.messages),
              info.topics.size(), static_cast<double>(info.end_ns - info.start_ns) * 1e-9);
  if (info.format == "mcap")
    std::printf(", %llu chunk(s) (%s), %llu schema(s)%s", static_cast<unsigned long long>(info.chunks),
                info.compression.empty() ? "no chunks" : info.compression.c_str(),
                static_cast<unsigned long long>(info.schemas), info.from_summary ? "; from the summary" : "; scanned");
  std::printf("\n");
  for (const auto& t : info.topics)
    std::printf("  %-40s %-36s %8llu messages\n", t.name.c_str(), t.type.c_str(),
                static_cast<unsigned long long>(t.messages));
  return 0;
}

int run_convert(const RecordOpts& o) {
  std::error_code ec;
  if (std::filesystem::equivalent(o.in, o.out, ec))
    throw InputError("record convert: " + o.out + " is the recording it reads; write another file");
  const auto in = open_recording(o.in);
  if (!in->cut_short().empty())
    std::fprintf(stderr, "plexus record convert: %s: %s; converting what is there\n", o.in.c_str(),
                 in->cut_short().c_str());
  RecordingOptions wo = writer_options(o, "plexus record convert");
  wo.metadata["converted_from"] = o.in;
  std::map<int64_t, int64_t> ids;
  for (const auto& t : in->topics()) {
    const msg::TypeSupport* ts = msg::find_type_support(t.type);
    if (!ts) throw InputError(o.in + ": topic '" + t.name + "' has type '" + t.type + "', unknown to this build");
  }
  auto out = make_recording_writer(o.out, wo);
  for (const auto& t : in->topics()) ids[t.id] = out->add_topic(t.name, *msg::find_type_support(t.type), t.qos_json);
  SampleBatch batch;
  uint64_t n = 0;
  msg::StampHeader h;
  in->for_each([&](const RecordedMessage& m) {
    h.seq_num(static_cast<uint64_t>(m.seq_num));
    h.data_time_ns(m.data_time_ns);
    h.origin_time_ns(m.origin_time_ns);
    h.publish_time_ns(m.publish_time_ns);
    batch.add(ids.at(m.topic_id), m.receive_time_ns, &h, m.cdr.data(), m.cdr.size());
    if (batch.entries.size() >= 4096) {
      out->insert(batch);
      batch.clear();
    }
    ++n;
    return true;
  });
  out->insert(batch);
  out->commit();
  std::printf("converted %llu samples of %zu topic(s) from %s to %s\n", static_cast<unsigned long long>(n),
              in->topics().size(), o.in.c_str(), o.out.c_str());
  return 0;
}

}  // namespace

Command add_record_command(CLI::App& root) {
  auto o = std::make_shared<RecordOpts>();
  Command c;
  c.app = root.add_subcommand("record",
                              "Record topics to a file: MCAP (default) or SQLite; info and convert of recordings");
  c.app->require_subcommand(0, 1);
  add_dds_options(c.app, o->dds);
  c.app->add_option("-o,--out", o->out,
                    "recording file to create (an existing one is replaced once the first topic is recorded)");
  c.app->add_option("--format", o->format, "mcap or sqlite (default: sqlite for *.sqlite, *.db, *.db3, else mcap)");
  c.app->add_option("--compression", o->compression, "MCAP chunk compression: zstd, lz4 or none")
      ->capture_default_str();
  c.app->add_option("--topics", o->topics, "comma-separated topics (default: every topic with a writer)");
  c.app->add_option("--duration", o->duration, "stop after S seconds (0: until Ctrl-C or --count)");
  c.app->add_option("--count", o->count, "stop after N samples in total (0: no limit)");
  c.app->add_option("--wait", o->wait, "--topics: seconds to wait for their writers to be discovered")
      ->capture_default_str()
      ->check(positive_seconds());
  c.app->add_option("--profile", o->profile, "subscribe with this QoS profile (default: one matching every writer)");
  c.app->add_option("--qos-file", o->qos_file, "QoS profiles file (default: deploy/qos.yaml)");
  auto* info =
      c.app->add_subcommand("info", "A recording's format, counts, time span and topics (MCAP: from its summary)");
  info->add_option("file", o->file, "recording (MCAP or SQLite)")->required();
  info->add_flag("--json", o->json, "one JSON object");
  auto* convert = c.app->add_subcommand("convert", "Write a recording (MCAP or SQLite) in another format");
  convert->add_option("in", o->in, "recording to read")->required();
  convert->add_option("out", o->out, "recording to write (format by its name, or --format)")->required();
  convert->add_option("--format", o->format, "mcap or sqlite (default: by the name, as record does)");
  convert->add_option("--compression", o->compression, "MCAP chunk compression: zstd, lz4 or none")
      ->capture_default_str();
  c.run = [o, info, convert] {
    if (info->parsed()) return run_info(*o);
    if (convert->parsed()) return run_convert(*o);
    return run_record(*o);
  };
  return c;
}

}  // namespace plexus::cli
