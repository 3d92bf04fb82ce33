// plexus topic list | echo TOPIC | hz TOPIC | info TOPIC: what `ros2 topic` does, on either
// DDS vendor, for any plexus message type (generic access through the generated
// TypeSupport: create, to_json, header).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>

#include "command.hpp"
#include "plexus/base/clock.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/msg/messages.hpp"
#include "plexus/runtime/producer_watch.hpp"
#include "recording.hpp"
#include "topic_discovery.hpp"

namespace plexus::cli {
namespace {

struct TopicOpts {
  DdsOptions dds;
  double wait = -1;  ///< -1: not given (list/info 2 s; echo/hz up to 5 s for the first writer)
  std::string topic, type, qos_file, profile, recording;
  int count = 0;
  double duration = 0;
  bool json = false, csv = false;
  double window_s = 1.0;
};

void check_common(const TopicOpts& o) {
  rt::parse_vendor(o.dds.dds);
  if (!(o.wait == -1 || (o.wait >= 0 && o.wait <= 600))) throw InputError("--wait: must be in 0..600 seconds");
  if (o.count < 0) throw InputError("--count: must be >= 0");
  if (!(o.duration >= 0)) throw InputError("--duration: must be >= 0 seconds");
  if (!o.profile.empty())
    rt::QosProfiles::load(o.qos_file.empty() ? rt::default_qos_file() : o.qos_file).get(o.profile);
}

// Flattens {"header": {"seq_num": 1}, "position": [1, 2]} to header.seq_num, position.0, position.1.
void flatten(const nlohmann::ordered_json& j, const std::string& prefix,
             std::vector<std::pair<std::string, std::string>>& out) {
  if (j.is_object()) {
    for (const auto& [k, v] : j.items()) flatten(v, prefix.empty() ? k : prefix + "." + k, out);
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i) flatten(j[i], prefix + "." + std::to_string(i), out);
  } else if (j.is_string()) {
    std::string s = j.get<std::string>();
    if (s.find_first_of(",\"\n") != std::string::npos) {
      std::string q = "\"";
      for (char ch : s) q += ch == '"' ? std::string("\"\"") : std::string(1, ch);
      s = q + "\"";
    }
    out.emplace_back(prefix, s);
  } else {
    out.emplace_back(prefix, j.dump());
  }
}

// Bounded by --count / --duration / Ctrl-C: calls fn for every sample taken.
template <class Fn>
void read_samples(rt::ReaderBackend& r, const msg::TypeSupport& ts, const TopicOpts& o, Fn&& fn) {
  void* sample = ts.create();
  const int64_t end = o.duration > 0 ? monotonic_ns() + static_cast<int64_t>(o.duration * 1e9) : INT64_MAX;
  int n = 0;
  rt::SampleMeta meta;
  while (!g_stop && monotonic_ns() < end && (o.count == 0 || n < o.count)) {
    if (!r.wait(50'000'000)) {
      fn(nullptr, meta);  // idle tick (hz prints its window)
      continue;
    }
    while ((o.count == 0 || n < o.count) && r.take(sample, &meta)) {
      ++n;
      fn(sample, meta);
    }
  }
  ts.destroy(sample);
}

int run_list(const TopicOpts& o) {
  check_common(o);
  auto p = make_participant(o.dds, "plexus_topic", "plexus_topic");
  struct Row {
    std::set<std::string> types;
    int writers = 0, readers = 0;
  };
  std::map<std::string, Row> rows;
  const double wait = o.wait < 0 ? 2.0 : o.wait;
  for (const auto& e : remote_endpoints(*p, wait)) {
    auto& r = rows[e.topic];
    r.types.insert(e.type_name);
    (e.is_writer ? r.writers : r.readers)++;
  }
  if (rows.empty())  // on stderr, so that --json's output stays the (empty) list
    std::fprintf(stderr, "plexus topic list: no topics discovered on domain %d in %.1f s\n", o.dds.domain, wait);
  if (o.json) {
    nlohmann::ordered_json j = nlohmann::ordered_json::array();
    for (const auto& [t, r] : rows)
      j.push_back({{"topic", t}, {"types", r.types}, {"writers", r.writers}, {"readers", r.readers}});
    std::printf("%s\n", j.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace).c_str());
    return 0;
  }
  // Columns as wide as their longest entry, so that long names keep them in line.
  std::vector<std::string> type_cells;
  int topic_w = 0, type_w = 0;
  for (const auto& [t, r] : rows) {
    std::string types;
    for (const auto& ty : r.types) types += (types.empty() ? "" : " | ") + ty;
    topic_w = std::max(topic_w, static_cast<int>(t.size()));
    type_w = std::max(type_w, static_cast<int>(types.size()));
    type_cells.push_back(std::move(types));
  }
  std::size_t i = 0;
  for (const auto& [t, r] : rows) {
    std::printf("%-*s  %-*s  %d writer%s, %d reader%s\n", topic_w, t.c_str(), type_w, type_cells[i++].c_str(),
                r.writers, r.writers == 1 ? "" : "s", r.readers, r.readers == 1 ? "" : "s");
  }
  return 0;
}

/// Prints samples as `topic echo` does: indented JSON, one JSON line each, or CSV rows.
class EchoPrinter {
 public:
  explicit EchoPrinter(const TopicOpts& o) : o_(o) {}
  void print(const msg::TypeSupport& ts, const void* s, int64_t receive_time_ns) {
    const auto j = ts.to_json(s);
    if (o_.csv) {
      cells_.clear();
      cells_.emplace_back("receive_time_ns", std::to_string(receive_time_ns));
      flatten(j, "", cells_);
      std::string line;
      if (!header_done_) {
        for (const auto& c : cells_) line += (line.empty() ? "" : ",") + c.first;
        std::printf("%s\n", line.c_str());
        header_done_ = true;
        line.clear();
      }
      for (const auto& c : cells_) line += (line.empty() ? "" : ",") + c.second;
      std::printf("%s\n", line.c_str());
    } else if (o_.json) {
      std::printf("%s\n", j.dump().c_str());
    } else {  // for reading: enumerators by name (--json and --csv keep the wire's integer)
      std::printf("%s\n---\n", msg::with_enum_names(ts, j).dump(2).c_str());
    }
    std::fflush(stdout);
  }

 private:
  const TopicOpts& o_;
  bool header_done_ = false;
  std::vector<std::pair<std::string, std::string>> cells_;
};

/// topic echo TOPIC --recording FILE: the topic's samples from a recording (MCAP or SQLite),
/// in receive-time order, printed as a live echo prints them.
int run_echo_recording(const TopicOpts& o) {
  const auto rec = open_recording(o.recording);
  const RecordedTopic* topic = nullptr;
  std::string names;
  for (const auto& t : rec->topics()) {
    if (t.name == o.topic) topic = &t;
    names += (names.empty() ? "" : ", ") + t.name;
  }
  if (!topic)
    throw InputError("--recording: topic '" + o.topic + "' is not in " + o.recording + " (topics: " + names + ")");
  const msg::TypeSupport* ts = msg::find_type_support(topic->type);
  if (!ts)
    throw InputError(o.recording + ": topic '" + o.topic + "' has type '" + topic->type + "', unknown to this build");
  if (!rec->cut_short().empty())
    std::fprintf(stderr, "plexus topic echo: warning: %s: %s; printing the samples before the cut\n",
                 o.recording.c_str(), rec->cut_short().c_str());
  EchoPrinter printer(o);
  void* sample = ts->create();
  int n = 0;
  uint64_t bad = 0;
  const int64_t end = o.duration > 0 ? static_cast<int64_t>(o.duration * 1e9) : INT64_MAX;  // of recorded time
  int64_t first = -1;
  try {
    rec->for_each([&](const RecordedMessage& m) {
      if (m.topic_id != topic->id) return true;
      if (first < 0) first = m.receive_time_ns;
      if (m.receive_time_ns - first > end || g_stop) return false;
      if (!ts->deserialize(m.cdr.data(), m.cdr.size(), sample)) {
        ++bad;
        return true;
      }
      printer.print(*ts, sample, m.receive_time_ns);
      return o.count == 0 || ++n < o.count;
    });
  } catch (...) {
    ts->destroy(sample);
    throw;
  }
  ts->destroy(sample);
  if (bad)
    std::fprintf(stderr, "plexus topic echo: %llu sample(s) of '%s' did not decode\n",
                 static_cast<unsigned long long>(bad), o.topic.c_str());
  return bad ? 1 : 0;
}

int run_echo(const TopicOpts& o) {
  check_common(o);
  if (o.csv && o.json) throw InputError("--csv and --json: choose one");
  if (!o.recording.empty()) return run_echo_recording(o);
  auto p = make_participant(o.dds, "plexus_topic_echo", "plexus_topic");
  std::vector<rt::EndpointQos> writers;
  const auto& ts = resolve_topic_type(*p, o.topic, o.type, o.wait < 0 ? 5.0 : o.wait, &writers);
  auto reader = p->make_reader(ts, o.topic, subscriber_qos(o.qos_file, o.profile, writers, 100));
  EchoPrinter printer(o);
  rt::ProducerWatch producers({o.topic});  // a second process writing the topic: warned when discovery shows it
  int64_t next_check = 0;
  read_samples(*reader, ts, o, [&](const void* s, const rt::SampleMeta& meta) {
    if (s) printer.print(ts, s, meta.receive_time_ns);
    if (monotonic_ns() >= next_check) producers.check(*p), next_check = monotonic_ns() + 1'000'000'000;
  });
  return 0;
}

int run_hz(const TopicOpts& o) {
  check_common(o);
  if (!(o.window_s > 0)) throw InputError("--window: must be > 0 seconds");
  auto p = make_participant(o.dds, "plexus_topic_hz", "plexus_topic");
  std::vector<rt::EndpointQos> writers;
  const auto& ts = resolve_topic_type(*p, o.topic, o.type, o.wait < 0 ? 5.0 : o.wait, &writers);
  auto reader = p->make_reader(ts, o.topic, subscriber_qos(o.qos_file, o.profile, writers, 100));
  // Intervals between receipts: this window and the whole run (Welford).
  struct Acc {
    uint64_t n = 0;
    double mean = 0, m2 = 0, min = 1e300, max = 0;
    void add(double x) {
      ++n;
      const double d = x - mean;
      mean += d / static_cast<double>(n);
      m2 += d * (x - mean);
      min = std::min(min, x);
      max = std::max(max, x);
    }
    double stddev() const { return n > 1 ? std::sqrt(m2 / static_cast<double>(n - 1)) : 0.0; }
  } win, all;
  int64_t last = 0, first = 0, window_start = monotonic_ns(), next_check = 0;
  uint64_t samples = 0;
  rt::ProducerWatch producers({o.topic});  // a second process writing the topic: warned when discovery shows it
  auto print = [&](const Acc& a, const char* what) {
    if (a.n == 0) {
      std::printf("%s: no new samples\n", what);
      return;
    }
    std::printf("%s: average rate %.3f Hz  min %.3f ms  max %.3f ms  std dev %.3f ms  over %llu samples\n", what,
                1.0 / a.mean, a.min * 1e3, a.max * 1e3, a.stddev() * 1e3, static_cast<unsigned long long>(a.n + 1));
  };
  read_samples(*reader, ts, o, [&](const void* s, const rt::SampleMeta& meta) {
    if (s) {
      ++samples;
      if (last != 0) {
        const double dt = static_cast<double>(meta.receive_time_ns - last) * 1e-9;
        win.add(dt);
        all.add(dt);
      } else {
        first = meta.receive_time_ns;
      }
      last = meta.receive_time_ns;
    }
    if (monotonic_ns() >= next_check) producers.check(*p), next_check = monotonic_ns() + 1'000'000'000;
    if (!o.json && monotonic_ns() - window_start >= static_cast<int64_t>(o.window_s * 1e9)) {
      print(win, o.topic.c_str());
      std::fflush(stdout);
      win = Acc{};
      window_start = monotonic_ns();
    }
  });
  if (o.json) {
    nlohmann::ordered_json j = {{"topic", o.topic},
                                {"type", ts.type_name},
                                {"samples", samples},
                                {"rate_hz", all.n ? 1.0 / all.mean : 0.0},
                                {"interval_min_ms", all.n ? all.min * 1e3 : 0.0},
                                {"interval_max_ms", all.max * 1e3},
                                {"interval_std_ms", all.stddev() * 1e3},
                                {"span_s", static_cast<double>(last - first) * 1e-9},
                                // The window itself (wall clock, ns), to compare another observer over it.
                                {"first_receive_ns", first},
                                {"last_receive_ns", last}};
    std::printf("%s\n", j.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace).c_str());
  } else {
    print(all, "total");
  }
  return samples > 0 ? 0 : 1;
}

int run_info(const TopicOpts& o) {
  check_common(o);
  auto p = make_participant(o.dds, "plexus_topic_info", "plexus_topic");
  std::vector<rt::DiscoveredEndpoint> eps;
  const double wait = o.wait < 0 ? 2.0 : o.wait;
  for (auto& e : remote_endpoints(*p, wait))
    if (e.topic == o.topic) eps.push_back(std::move(e));
  if (eps.empty()) {
    std::fprintf(stderr, "plexus topic info: no endpoint on topic '%s' discovered on domain %d in %.1f s\n",
                 o.topic.c_str(), o.dds.domain, wait);
    return 1;
  }
  rt::ProducerWatch({o.topic}).check(*p);
  std::set<std::string> types;
  for (const auto& e : eps) types.insert(e.type_name);
  nlohmann::ordered_json j;
  j["topic"] = o.topic;
  j["types"] = types;
  j["endpoints"] = nlohmann::ordered_json::array();
  for (const auto& e : eps)
    j["endpoints"].push_back({{"kind", e.is_writer ? "writer" : "reader"},
                              {"participant", e.participant},
                              {"guid", e.guid},
                              {"type", e.type_name},
                              {"qos", qos_to_json(e.qos)}});
  j["pairs"] = nlohmann::ordered_json::array();
  int incompatible = 0;
  for (const auto& w : eps) {
    if (!w.is_writer) continue;
    for (const auto& r : eps) {
      if (r.is_writer) continue;
      nlohmann::ordered_json pr = {
          {"writer", w.participant}, {"writer_guid", w.guid}, {"reader", r.participant}, {"reader_guid", r.guid}};
      if (w.type_name != r.type_name) {
        pr["matched"] = false;
        pr["policy"] = "TYPE";
        pr["offered"] = w.type_name;
        pr["requested"] = r.type_name;
        ++incompatible;
      } else if (auto m = rt::check_compatible(w.qos, r.qos)) {
        pr["matched"] = false;
        pr["policy"] = m->policy;
        pr["offered"] = m->offered;
        pr["requested"] = m->requested;
        ++incompatible;
      } else {
        pr["matched"] = true;
      }
      j["pairs"].push_back(pr);
    }
  }
  if (o.json) {
    std::printf("%s\n", j.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace).c_str());
    return 0;
  }
  std::string type_text;
  for (const auto& t : types) type_text += (type_text.empty() ? "" : ", ") + t;
  std::printf("Topic: %s\nType: %s\n", o.topic.c_str(), type_text.c_str());
  for (const char* kind : {"writer", "reader"}) {
    for (const auto& e : eps) {
      if (e.is_writer != (std::string(kind) == "writer")) continue;
      std::printf("  %s of '%s' (%s)\n    QoS: %s\n", kind, e.participant.c_str(), e.guid.c_str(),
                  rt::describe(e.qos).c_str());
    }
  }
  std::printf("Matching (DDS request-offered rules):\n");
  if (j["pairs"].empty()) std::printf("  no writer/reader pair\n");
  for (const auto& pr : j["pairs"]) {
    if (pr["matched"].get<bool>())
      std::printf("  %s -> %s: matched\n", pr["writer"].get<std::string>().c_str(),
                  pr["reader"].get<std::string>().c_str());
    else
      std::printf("  %s -> %s: INCOMPATIBLE %s (writer offers %s, reader requests %s)\n",
                  pr["writer"].get<std::string>().c_str(), pr["reader"].get<std::string>().c_str(),
                  pr["policy"].get<std::string>().c_str(), pr["offered"].get<std::string>().c_str(),
                  pr["requested"].get<std::string>().c_str());
  }
  (void)incompatible;
  return 0;
}

}  // namespace

Command add_topic_command(CLI::App& root) {
  auto o = std::make_shared<TopicOpts>();
  Command c;
  c.app = root.add_subcommand("topic", "Inspect topics: list, echo, hz, info (either DDS vendor)");
  c.app->require_subcommand(1);
  auto common = [o](CLI::App* s, bool reads) {
    add_dds_options(s, o->dds);
    s->add_option("--wait", o->wait, "seconds to wait for discovery (list/info: 2; echo/hz: up to 5 for a writer)")
        ->check(positive_seconds());
    s->add_flag("--json", o->json, "JSON output");
    if (reads) {
      s->add_option("topic", o->topic, "topic name")->required();
      s->add_option("--type", o->type, "message type (plexus::msg::Pose2D or Pose2D); default: the writers' type");
      s->add_option("--count", o->count, "stop after N samples (0: no limit)");
      s->add_option("--duration", o->duration, "stop after S seconds (0: no limit)");
      s->add_option("--profile", o->profile, "subscribe with this QoS profile (default: one matching every writer)");
      s->add_option("--qos-file", o->qos_file, "QoS profiles file (default: deploy/qos.yaml)");
    }
  };
  auto* list = c.app->add_subcommand("list", "List discovered topics with type and writer/reader counts");
  common(list, false);
  auto* echo = c.app->add_subcommand("echo", "Print the samples of a topic");
  common(echo, true);
  echo->add_flag("--csv", o->csv, "CSV output: a header row, then one row per sample");
  echo->add_option("--recording", o->recording,
                   "print the topic's samples from this recording (MCAP or SQLite) instead of the live domain; "
                   "--duration counts recorded time");
  auto* hz = c.app->add_subcommand("hz", "Receive rate of a topic");
  common(hz, true);
  hz->add_option("--window", o->window_s, "seconds per printed window")->capture_default_str();
  auto* info = c.app->add_subcommand("info", "Type, endpoints with QoS, and which pairs match (or which policy fails)");
  common(info, false);
  info->add_option("topic", o->topic, "topic name")->required();
  c.run = [o, list, echo, hz, info] {
    install_stop_handler();
    if (list->parsed()) return run_list(*o);
    if (echo->parsed()) return run_echo(*o);
    if (hz->parsed()) return run_hz(*o);
    if (info->parsed()) return run_info(*o);
    return 2;
  };
  return c;
}

}  // namespace plexus::cli
