// plexus record -o FILE [--topics a,b]: records topics to a SQLite file (see recording.hpp),
// with the receive time and the header times of every sample and its CDR bytes.
//
// One reader thread per topic waits on its reader and takes each sample as it arrives (so
// the receive time is the arrival, not a polling tick); the main thread writes batches in
// one transaction every 100 ms.
#include <algorithm>
#include <cstdio>
#include <deque>
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
#include "topic_discovery.hpp"

namespace plexus::cli {
namespace {

struct RecordOpts {
  DdsOptions dds;
  std::string out, topics, qos_file, profile;
  double wait = 1.5, duration = 0;
  int count = 0;
};

struct TopicReader {
  std::string name;
  const msg::TypeSupport* ts = nullptr;
  int64_t id = 0;
  std::unique_ptr<rt::ReaderBackend> reader;
};

int run_record(const RecordOpts& o) {
  rt::parse_vendor(o.dds.dds);
  if (o.out.empty()) throw InputError("-o/--out: a recording file is required");
  if (!(o.duration >= 0)) throw InputError("--duration: must be >= 0 seconds");
  if (o.count < 0) throw InputError("--count: must be >= 0");
  if (!(o.wait >= 0 && o.wait <= 600)) throw InputError("--wait: must be in 0..600 seconds");
  if (!o.profile.empty())
    rt::QosProfiles::load(o.qos_file.empty() ? rt::default_qos_file() : o.qos_file).get(o.profile);
  RecordingWriter file(o.out);  // file errors first: exit 2 before any DDS work
  install_stop_handler();
  auto p = make_participant(o.dds, "plexus_record", "plexus_record");

  // Which topics: the given ones (waiting for their writers), or every topic with a writer,
  // including topics that appear while recording (discovery is polled, as rosbag2 does).
  const std::vector<std::string> wanted = split_list(o.topics);
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

  std::mutex mu;
  std::vector<RecordedMessage> pending, batch;
  std::atomic<uint64_t> total{0};
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
      r.id = file.add_topic(t, ts->type_name, qos_to_json(ws.front().qos).dump());
      r.reader = p->make_reader(*ts, t, subscriber_qos(o.qos_file, o.profile, qos, 1000));
      threads.emplace_back([&, rp = &r] {
        void* sample = rp->ts->create();
        std::vector<unsigned char> buf(rp->ts->max_cdr_size);
        rt::SampleMeta meta;
        while (!done && !g_stop) {
          if (!rp->reader->wait(50'000'000)) continue;
          while (rp->reader->take(sample, &meta)) {
            RecordedMessage m;
            m.topic_id = rp->id;
            m.receive_time_ns = meta.receive_time_ns;
            if (rp->ts->header) {
              const msg::StampHeader& h = *rp->ts->header(sample);
              m.seq_num = static_cast<int64_t>(h.seq_num());
              m.data_time_ns = h.data_time_ns();
              m.origin_time_ns = h.origin_time_ns();
              m.publish_time_ns = h.publish_time_ns();
            }
            const std::size_t n = rp->ts->serialize(sample, buf.data(), buf.size());
            m.cdr.assign(buf.begin(), buf.begin() + static_cast<std::ptrdiff_t>(n));
            std::lock_guard lk(mu);
            pending.push_back(std::move(m));
            if (o.count > 0 && ++total >= static_cast<uint64_t>(o.count)) done = true;
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
  auto flush = [&] {
    {
      std::lock_guard lk(mu);
      batch.swap(pending);
    }
    if (o.count > 0 && written + batch.size() > static_cast<uint64_t>(o.count))
      batch.resize(static_cast<std::size_t>(static_cast<uint64_t>(o.count) - written));
    file.insert(batch);
    written += batch.size();
    batch.clear();
  };
  int tick = 0;
  while (!done && !g_stop && monotonic_ns() < end) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    flush();
    if (wanted.empty() || readers.size() < wanted.size())
      if (++tick % 2 == 0) add_topics();
  }
  done = true;
  for (auto& t : threads) t.join();
  flush();
  const std::size_t n_topics = readers.size();
  readers.clear();
  std::printf("recorded %llu samples from %zu topic(s) to %s\n", static_cast<unsigned long long>(written), n_topics,
              o.out.c_str());
  if (n_topics == 0) {
    std::fprintf(stderr, "plexus record: no topic with a writer was discovered on domain %d\n", o.dds.domain);
    return 1;  // `file` is not committed: an existing recording at -o is left as it was
  }
  file.commit();
  return 0;
}

}  // namespace

Command add_record_command(CLI::App& root) {
  auto o = std::make_shared<RecordOpts>();
  Command c;
  c.app = root.add_subcommand("record", "Record topics to a SQLite file (CDR + receive and header times)");
  add_dds_options(c.app, o->dds);
  c.app
      ->add_option("-o,--out", o->out, "recording file to create (replaced, once the recording succeeds, if it exists)")
      ->required();
  c.app->add_option("--topics", o->topics, "comma-separated topics (default: every topic with a writer)");
  c.app->add_option("--duration", o->duration, "stop after S seconds (0: until Ctrl-C or --count)");
  c.app->add_option("--count", o->count, "stop after N samples in total (0: no limit)");
  c.app->add_option("--wait", o->wait, "--topics: seconds to wait for their writers to be discovered")
      ->capture_default_str()
      ->check(positive_seconds());
  c.app->add_option("--profile", o->profile, "subscribe with this QoS profile (default: one matching every writer)");
  c.app->add_option("--qos-file", o->qos_file, "QoS profiles file (default: deploy/qos.yaml)");
  c.run = [o] { return run_record(*o); };
  return c;
}

}  // namespace plexus::cli
