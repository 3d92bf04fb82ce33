// contract_probe: checks ONE source of a robot's topics (plant_simulator, serial_bridge,
// udp_bridge, plexus replay) against the robot's contract (docs/bridges.md "The contract",
// docs/topics.md), from outside, as any DDS program on the domain would see it.
//
//   contract_probe --dds fast --domain 130 --robot r1 --contract tests/bridges/unicycle_contract.yaml
//                  --discover 3 --measure 8 --drive --label serial --out result.json
//
// a. Discovery (at least --discover s, then until every contract topic has shown up, at
//    most --discover-timeout s more): the remote writers on <robot>/... and the remote
//    readers of the command topic must be the contract's: the same topics, types and QoS
//    (history only when the vendor reports it).
// b. Measurement (--measure s, from the moment every reader matched): every writer topic
//    (the contract's and any other discovered) is read with a QoS matching its writers;
//    rate = (count - 1) / (last - first receive time) within the contract's tolerance of
//    its nominal rate, and the samples must cover the window (a stream that stops midway
//    fails even if its rate before was right); headers: seq_num strictly increasing,
//    data_time_ns > 0 and within 1 s of the receive wall time, origin_time_ns > 0; values:
//    every member outside the header finite and below the contract's bound in magnitude,
//    and accepted by plexus's own edge check (WireSignal::decode).
// c. --drive: a step command (v, omega from the contract) on the command topic at its rate
//    for its duration, CLOCK_REALTIME data and origin time: the ground truth must move
//    along its heading and not sideways; then silence: after a grace period the truth must
//    stand still (a stale command stops the robot) while its samples keep arriving.
//    --health TOPIC (a bridge's heartbeat): its link counters must show STOP frames sent
//    after the commands stopped.
// d. --out: {source, vendor, domain, window, checks: [{name, passed, detail}], topics, passed}.
//
// --write-contract FILE: write what was discovered as a contract file (to author one).
// Exit 0 if every check passed, 1 if one failed, 2 for bad arguments.
#include <time.h>

#include <yaml-cpp/yaml.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <sstream>
#include <thread>
#include <vector>

#include "plexus/base/clock.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/base/logging.hpp"
#include "plexus/distributed/wire.hpp"
#include "plexus/msg/messages.hpp"
#include "plexus/runtime/discovery.hpp"
#include "plexus/runtime/participant.hpp"
#include "plexus/runtime/qos.hpp"
#include "plexus/runtime/transport.hpp"

namespace {

using namespace plexus;
using json = nlohmann::ordered_json;
constexpr int64_t kSecond = 1'000'000'000;

std::atomic<bool> g_stop{false};

int64_t ns_of(double s) { return static_cast<int64_t>(std::llround(s * 1e9)); }

void sleep_for_s(double s) {
  const int64_t end = monotonic_ns() + ns_of(s);
  while (!g_stop && monotonic_ns() < end) std::this_thread::sleep_for(std::chrono::milliseconds(5));
}

std::string num(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

// --- type names ------------------------------------------------------------------------

/// "plexus::msg::Pose2D", "plexus_msg_Pose2D", "Pose2D", "pose2d" -> "pose2d": the vendors
/// spell a scoped IDL name with `::` (both do for plexus types, DDS-XTypes style) or `_`
/// (idlc's C identifiers); the comparison ignores case and the module prefix.
std::string type_key(std::string s) {
  for (std::size_t p; (p = s.find("::")) != std::string::npos;) s.replace(p, 2, "_");
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (s.rfind("plexus_msg_", 0) == 0) s = s.substr(11);
  return s;
}

const msg::TypeSupport* type_support_of(const std::string& name) {
  for (const auto* ts : msg::all_type_supports())
    if (type_key(ts->type_name) == type_key(name)) return ts;
  return nullptr;
}

// --- QoS as the contract states it -------------------------------------------------------

/// The QoS fields a contract states, as text, from discovery data. Fast DDS does not
/// announce a data representation when it is the default (XCDR1): an empty list is [0].
std::map<std::string, std::string> qos_fields(const rt::EndpointQos& q) {
  std::map<std::string, std::string> m;
  m["reliability"] = rt::to_string(q.reliability);
  m["durability"] = q.durability_stronger ? "transient" : rt::to_string(q.durability);
  m["deadline_s"] = num("%g", q.deadline_s);
  m["liveliness"] = rt::to_string(q.liveliness);
  m["liveliness_lease_s"] = num("%g", q.liveliness_lease_s);
  m["lifespan_s"] = num("%g", q.lifespan_s);
  m["latency_budget_s"] = num("%g", q.latency_budget_s);
  m["ownership"] = q.exclusive_ownership ? "exclusive" : "shared";
  std::string repr;
  for (int v : q.data_representation.empty() ? std::vector<int>{0} : q.data_representation)
    repr += (repr.empty() ? "" : ",") + std::string(v == 0 ? "xcdr1" : v == 1 ? "xml" : v == 2 ? "xcdr2" : "?");
  m["data_representation"] = repr;
  if (q.history_known) {
    m["history"] = rt::to_string(q.history);
    if (q.history == rt::QosProfile::History::keep_last) m["depth"] = std::to_string(q.depth);
  }
  return m;
}

/// The contract's QoS map, normalised like qos_fields (numbers through %g).
std::map<std::string, std::string> contract_qos(const YAML::Node& n, const std::string& where) {
  static const std::set<std::string> known = {
      "reliability", "durability",       "deadline_s", "liveliness",          "liveliness_lease_s",
      "lifespan_s",  "latency_budget_s", "ownership",  "data_representation", "history",
      "depth"};
  if (!n || !n.IsMap()) throw InputError(where + ": qos: expected a map");
  std::map<std::string, std::string> m;
  for (const auto& kv : n) {
    const std::string k = kv.first.as<std::string>();
    if (!known.count(k)) throw InputError(where + ".qos." + k + ": unknown QoS field");
    if (k.size() > 2 && k.substr(k.size() - 2) == "_s")
      m[k] = num("%g", kv.second.as<double>());
    else if (k == "data_representation" && kv.second.IsSequence()) {
      std::string s;
      for (const auto& v : kv.second) s += (s.empty() ? "" : ",") + v.as<std::string>();
      m[k] = s;
    } else
      m[k] = kv.second.as<std::string>();
  }
  for (const auto& k : known)
    if (k != "history" && k != "depth" && !m.count(k)) throw InputError(where + ".qos: '" + k + "' missing");
  return m;
}

/// Differences between a contract QoS and a discovered one; history and depth only if the
/// vendor reported them (they are not part of standard discovery data).
std::string qos_diff(const std::map<std::string, std::string>& want, const std::map<std::string, std::string>& got) {
  std::string d;
  for (const auto& [k, v] : want) {
    const auto it = got.find(k);
    if (it == got.end()) continue;  // history, depth: not reported
    if (it->second != v) d += (d.empty() ? "" : "; ") + k + " " + it->second + " (contract " + v + ")";
  }
  return d;
}

// --- the contract file -------------------------------------------------------------------

struct ContractTopic {
  std::string topic;  ///< relative to the robot ("position")
  std::string type;
  std::map<std::string, std::string> qos;
  double rate_hz = 0;
};

struct Contract {
  std::vector<ContractTopic> writers;
  ContractTopic command;
  double rate_tolerance = 0.05;  ///< fraction
  double value_bound = 1000;     ///< |value| below this
  double max_data_age_s = 1.0;   ///< |data_time - receive time|
  double min_coverage = 0.9;     ///< samples span at least this fraction of the window
  // Drive (step command, then stale).
  std::string truth = "truth/state";
  double v = 0.5, omega = 0.0, drive_s = 2.0, command_rate_hz = 100;
  double min_forward_m = 0.5, max_sideways_m = 0.1;
  double stale_grace_s = 0.5, still_window_s = 1.0, max_still_m = 0.005;
};

Contract load_contract(const std::string& file) {
  YAML::Node doc;
  try {
    doc = YAML::LoadFile(file);
  } catch (const YAML::Exception& e) {
    throw InputError("--contract " + file + ": " + e.what());
  }
  Contract c;
  const auto get = [&](const YAML::Node& n, const char* key, double& out) {
    if (n[key]) out = n[key].as<double>();
  };
  try {
    if (const auto m = doc["measure"]) {
      get(m, "rate_tolerance", c.rate_tolerance);
      get(m, "value_bound", c.value_bound);
      get(m, "max_data_age_s", c.max_data_age_s);
      get(m, "min_coverage", c.min_coverage);
    }
    if (!doc["writers"] || !doc["writers"].IsMap()) throw InputError(file + ": writers: expected a map of topics");
    for (const auto& kv : doc["writers"]) {
      ContractTopic t;
      t.topic = kv.first.as<std::string>();
      const std::string where = file + ": writers." + t.topic;
      if (!kv.second["type"]) throw InputError(where + ".type: missing");
      t.type = kv.second["type"].as<std::string>();
      if (!type_support_of(t.type)) throw InputError(where + ".type: '" + t.type + "' is not a plexus message type");
      t.qos = contract_qos(kv.second["qos"], where);
      if (!kv.second["rate_hz"]) throw InputError(where + ".rate_hz: missing");
      t.rate_hz = kv.second["rate_hz"].as<double>();
      c.writers.push_back(std::move(t));
    }
    const auto cmd = doc["command"];
    if (!cmd || !cmd["topic"] || !cmd["type"]) throw InputError(file + ": command: expected topic, type, qos");
    c.command.topic = cmd["topic"].as<std::string>();
    c.command.type = cmd["type"].as<std::string>();
    c.command.qos = contract_qos(cmd["qos"], file + ": command");
    if (const auto d = doc["drive"]) {
      if (d["truth"]) c.truth = d["truth"].as<std::string>();
      get(d, "v", c.v);
      get(d, "omega", c.omega);
      get(d, "duration_s", c.drive_s);
      get(d, "rate_hz", c.command_rate_hz);
      get(d, "min_forward_m", c.min_forward_m);
      get(d, "max_sideways_m", c.max_sideways_m);
      get(d, "stale_grace_s", c.stale_grace_s);
      get(d, "still_window_s", c.still_window_s);
      get(d, "max_still_m", c.max_still_m);
    }
  } catch (const YAML::Exception& e) {
    throw InputError(file + ": " + e.what());
  }
  return c;
}

// --- checks ------------------------------------------------------------------------------

struct Checks {
  json list = json::array();
  bool all = true;
  void add(const std::string& name, bool passed, const std::string& detail) {
    list.push_back({{"name", name}, {"passed", passed}, {"detail", detail}});
    all = all && passed;
    std::fprintf(stderr, "contract_probe: %-28s %s  %s\n", name.c_str(), passed ? "pass" : "FAIL", detail.c_str());
  }
};

// --- measurement -------------------------------------------------------------------------

/// Walks a sample's JSON (header excluded): every number must be finite and below `bound`.
void scan_values(const json& j, const std::string& path, double bound, uint64_t& bad, std::string& first_bad) {
  if (j.is_object()) {
    for (const auto& [k, v] : j.items())
      if (!(path.empty() && k == "header")) scan_values(v, path.empty() ? k : path + "." + k, bound, bad, first_bad);
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i)
      scan_values(j[i], path + "[" + std::to_string(i) + "]", bound, bad, first_bad);
  } else if (j.is_number_float()) {
    const double v = j.get<double>();
    if (!std::isfinite(v) || std::fabs(v) >= bound) {
      if (bad++ == 0) first_bad = path + " = " + num("%g", v);
    }
  } else if (j.is_number()) {
    const double v = j.get<double>();
    if (std::fabs(v) >= bound) {
      if (bad++ == 0) first_bad = path + " = " + num("%g", v);
    }
  }
}

/// One topic read for the measurement (and, for the truth topic, the drive).
struct TopicReader {
  std::string topic;  ///< full name
  const msg::TypeSupport* ts = nullptr;
  std::unique_ptr<rt::ReaderBackend> reader;
  std::unique_ptr<scenario::SignalSpec> spec;  // every field plexus maps for the type
  std::unique_ptr<distributed::WireSignal> wire;
  double nominal_hz = 0;
  double value_bound = 1000, max_age_s = 1.0;
  std::thread thread;

  std::mutex mu;
  // Measurement window (CLOCK_REALTIME ns); samples outside it are not counted.
  int64_t win_start = INT64_MAX, win_end = INT64_MAX;
  uint64_t count = 0, before = 0;
  int64_t first = 0, last = 0, max_gap = 0;
  uint64_t last_seq = 0;
  bool any_seq = false;
  uint64_t seq_errors = 0, data_time_errors = 0, origin_errors = 0, bad_values = 0, refused = 0;
  std::string first_seq_error, first_time_error, first_bad_value, first_refusal;
  double max_age_seen_s = 0;
  // Newest sample (the drive reads the truth pose through it).
  json latest;
  int64_t latest_receive = 0;
  uint64_t total = 0;

  void run() {
    void* sample = ts->create();
    scenario::SignalSample decoded;
    while (!g_stop) {
      if (!reader->wait(50'000'000)) continue;
      rt::SampleMeta meta;
      while (reader->take(sample, &meta)) {
        const int64_t rx = wall_time_ns();
        const msg::StampHeader& h = *ts->header(sample);
        json j = ts->to_json(sample);
        std::lock_guard lock(mu);
        ++total;
        latest = j;
        latest_receive = rx;
        if (rx < win_start) {
          ++before;
          last_seq = h.seq_num();  // the sequence check starts with the first sample seen
          any_seq = true;
          continue;
        }
        if (rx > win_end) continue;
        if (count == 0)
          first = rx;
        else
          max_gap = std::max(max_gap, rx - last);
        last = rx;
        ++count;
        if (any_seq && h.seq_num() <= last_seq) {
          if (seq_errors++ == 0)
            first_seq_error = "seq " + std::to_string(h.seq_num()) + " after " + std::to_string(last_seq);
        }
        last_seq = h.seq_num();
        any_seq = true;
        const double age = static_cast<double>(rx - h.data_time_ns()) * 1e-9;
        if (h.data_time_ns() > 0) max_age_seen_s = std::max(max_age_seen_s, std::fabs(age));
        if (h.data_time_ns() <= 0 || std::fabs(age) > max_age_s) {
          if (data_time_errors++ == 0)
            first_time_error = "seq " + std::to_string(h.seq_num()) + ": data_time_ns " +
                               std::to_string(h.data_time_ns()) + " is " + num("%.3f", age) + " s before its receipt";
        }
        if (h.origin_time_ns() <= 0) {
          if (origin_errors++ == 0)
            first_time_error += (first_time_error.empty() ? "" : "; ") + std::string("origin_time_ns ") +
                                std::to_string(h.origin_time_ns());
        }
        scan_values(j, "", value_bound, bad_values, first_bad_value);
        if (wire) {
          std::size_t bad = 0;
          const auto why = wire->decode(sample, decoded, bad);
          if (why != distributed::Rejection::none) {
            if (refused++ == 0)
              first_refusal = std::string(distributed::to_string(why)) +
                              (why == distributed::Rejection::non_finite || why == distributed::Rejection::out_of_range
                                   ? " (" + spec->fields[bad] + " = " + num("%g", wire->value(sample, bad)) + ")"
                                   : "");
          }
        }
      }
    }
    ts->destroy(sample);
  }
};

double field(const json& j, const char* k) { return j.contains(k) && j[k].is_number() ? j[k].get<double>() : NAN; }

struct Pose {
  double x = NAN, y = NAN, theta = NAN;
  int64_t receive = 0;
  bool ok() const { return std::isfinite(x) && std::isfinite(y) && std::isfinite(theta); }
};

Pose pose_of(TopicReader& r) {
  std::lock_guard lock(r.mu);
  Pose p;
  if (r.latest.is_null()) return p;
  p.x = field(r.latest, "x");
  p.y = field(r.latest, "y");
  p.theta = field(r.latest, "theta");
  p.receive = r.latest_receive;
  return p;
}

/// The newest truth pose, waiting (up to 1 s) for one received in the last 100 ms.
Pose fresh_pose(TopicReader& r) {
  const int64_t end = monotonic_ns() + kSecond;
  Pose p;
  do {
    p = pose_of(r);
    if (p.ok() && wall_time_ns() - p.receive < 100'000'000) return p;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  } while (!g_stop && monotonic_ns() < end);
  return p;
}

std::string pose_text(const Pose& p) {
  return "(" + num("%.4f", p.x) + ", " + num("%.4f", p.y) + ", " + num("%.4f", p.theta) + ")";
}

/// A bridge's heartbeat: the newest link counters.
struct HealthReader {
  rt::Subscriber<msg::Heartbeat> sub;
  msg::Heartbeat latest;
  int64_t latest_receive = 0;
  uint64_t count = 0;
  void poll() {
    msg::Heartbeat hb;
    while (sub.take(hb)) {
      latest = hb;
      latest_receive = wall_time_ns();
      ++count;
    }
  }
};

json link_json(const msg::LinkStatus& s) {
  return {{"up", s.state() == plexus::msg::LINK_UP},
          {"frames_in", s.frames_in()},
          {"frames_out", s.frames_out()},
          {"crc_errors", s.crc_errors()},
          {"framing_errors", s.framing_errors()},
          {"oversize", s.oversize()},
          {"resyncs", s.resyncs()},
          {"rejected_frames", s.rejected_frames()},
          {"stale_commands", s.stale_commands()},
          {"stop_frames", s.stop_frames()},
          {"tx_errors", s.tx_errors()}};
}

void sleep_until_mono(int64_t t) {
  timespec ts{static_cast<time_t>(t / kSecond), static_cast<long>(t % kSecond)};
  while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) == EINTR && !g_stop) {}
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"contract_probe: checks one source of a robot's topics against its contract (tests/bridges/)"};
  std::string dds = "fast", robot = "r1", contract_file, out_file, label = "source", write_contract, health_topic;
  int domain = 0;
  double discover_s = 3, discover_timeout_s = 5, measure_s = 8;
  bool drive = false, no_command_reader = false;
  app.add_option("--dds", dds, "fast or cyclone")->check(CLI::IsMember({"fast", "cyclone"}));
  std::string transport = "auto";
  app.add_option("--transport", transport, "auto, udp or shm (docs/runtime.md, Transports)");
  app.add_option("--domain", domain, "DDS domain")->check(CLI::Range(0, 232));
  app.add_option("--robot", robot, "robot whose topics are checked");
  app.add_option("--contract", contract_file, "contract YAML (tests/bridges/unicycle_contract.yaml)")->required();
  app.add_option("--discover", discover_s, "seconds of discovery before the comparison")->check(CLI::Range(0.1, 60.0));
  app.add_option("--discover-timeout", discover_timeout_s,
                 "then at most this many more seconds for contract topics not yet seen")
      ->check(CLI::Range(0.0, 60.0));
  app.add_option("--measure", measure_s, "seconds of measurement")->check(CLI::Range(1.0, 600.0));
  app.add_flag("--drive", drive, "step command, then a stale command (not for replay)");
  app.add_flag("--no-command-reader", no_command_reader, "the source reads no command (replay): not compared");
  app.add_option("--health", health_topic, "a bridge's heartbeat topic: STOP frames after the commands stopped");
  app.add_option("--label", label, "source label in the result");
  app.add_option("--out", out_file, "result JSON");
  app.add_option("--write-contract", write_contract, "write what was discovered as a contract YAML (then exit)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  if (drive && no_command_reader) {
    std::fprintf(stderr, "contract_probe: error: --drive needs the command reader (not with --no-command-reader)\n");
    return 2;
  }
  std::signal(SIGINT, [](int) { g_stop = true; });
  std::signal(SIGTERM, [](int) { g_stop = true; });

  Contract contract;
  try {
    contract = load_contract(contract_file);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "contract_probe: error: %s\n", e.what());
    return 2;
  }
  const std::string prefix = robot + "/";
  const std::string command_topic = prefix + contract.command.topic;
  Checks checks;
  json result{{"source", label}, {"vendor", dds}, {"domain", domain}, {"robot", robot}};
  json topics_json = json::object();

  try {
    init_logging("contract_probe", "", "warn");
    rt::ParticipantOptions po;
    po.vendor = rt::parse_vendor(dds);
    po.domain_id = domain;
    po.name = "contract_probe";
    po.network.transport = rt::parse_transport(transport);
    auto p = rt::Participant::create(po);
    const auto profiles = rt::QosProfiles::load(rt::default_qos_file());

    // --- a. discovery
    const int64_t t_start = monotonic_ns();
    sleep_for_s(discover_s);
    std::vector<rt::DiscoveredEndpoint> writers, readers;
    const auto snapshot = [&] {
      writers.clear();
      readers.clear();
      for (auto& e : p->discovered_endpoints()) {
        if (e.local) continue;
        if (e.is_writer && e.topic.rfind(prefix, 0) == 0) writers.push_back(e);
        if (!e.is_writer && e.topic == command_topic) readers.push_back(e);
      }
    };
    const auto complete = [&] {
      for (const auto& t : contract.writers)
        if (std::none_of(writers.begin(), writers.end(), [&](const auto& e) { return e.topic == prefix + t.topic; }))
          return false;
      return no_command_reader || !readers.empty();
    };
    const int64_t extra_end = monotonic_ns() + ns_of(discover_timeout_s);
    for (snapshot(); !complete() && !g_stop && monotonic_ns() < extra_end; snapshot())
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    if (complete() && monotonic_ns() - t_start > ns_of(discover_s) + 50'000'000) {
      sleep_for_s(0.3);  // a late source: let its other endpoints arrive too
      snapshot();
    }
    const double discovery_took = static_cast<double>(monotonic_ns() - t_start) * 1e-9;
    std::sort(writers.begin(), writers.end(), [](const auto& a, const auto& b) { return a.topic < b.topic; });

    json disc{{"seconds", discovery_took}, {"writers", json::array()}, {"command_readers", json::array()}};
    for (const auto& e : writers)
      disc["writers"].push_back(
          {{"topic", e.topic}, {"type", e.type_name}, {"participant", e.participant}, {"qos", rt::describe(e.qos)}});
    for (const auto& e : readers)
      disc["command_readers"].push_back(
          {{"topic", e.topic}, {"type", e.type_name}, {"participant", e.participant}, {"qos", rt::describe(e.qos)}});
    result["discovery"] = disc;

    if (!write_contract.empty()) {
      YAML::Emitter y;
      const auto emit_qos = [&](const rt::EndpointQos& q) {
        y << YAML::Key << "qos" << YAML::Value << YAML::Flow << YAML::BeginMap;
        for (const auto& [k, v] : qos_fields(q)) {
          y << YAML::Key << k;
          if (k == "data_representation") {
            y << YAML::Value << YAML::Flow << YAML::BeginSeq;
            std::stringstream ss(v);
            for (std::string item; std::getline(ss, item, ',');) y << item;
            y << YAML::EndSeq;
          } else if (k.size() > 2 && k.substr(k.size() - 2) == "_s") {
            y << YAML::Value << std::stod(v);
          } else {
            y << YAML::Value << v;
          }
        }
        y << YAML::EndMap;
      };
      y << YAML::BeginMap << YAML::Key << "writers" << YAML::Value << YAML::BeginMap;
      for (const auto& e : writers) {
        y << YAML::Key << e.topic.substr(prefix.size()) << YAML::Value << YAML::BeginMap;
        y << YAML::Key << "type" << YAML::Value << e.type_name << YAML::Key << "rate_hz" << YAML::Value << 0;
        emit_qos(e.qos);
        y << YAML::EndMap;
      }
      y << YAML::EndMap;
      for (const auto& e : readers) {
        y << YAML::Key << "command" << YAML::Value << YAML::BeginMap;
        y << YAML::Key << "topic" << YAML::Value << e.topic.substr(prefix.size());
        y << YAML::Key << "type" << YAML::Value << e.type_name;
        emit_qos(e.qos);
        y << YAML::EndMap;
        break;
      }
      y << YAML::EndMap;
      std::ofstream(write_contract) << y.c_str() << '\n';
      std::fprintf(stderr, "contract_probe: wrote %s (%zu writers, %zu command readers)\n", write_contract.c_str(),
                   writers.size(), readers.size());
      return 0;
    }

    {  // topics: the same set
      std::set<std::string> want, got;
      for (const auto& t : contract.writers) want.insert(prefix + t.topic);
      for (const auto& e : writers) got.insert(e.topic);
      std::string missing, extra;
      for (const auto& t : want)
        if (!got.count(t)) missing += (missing.empty() ? "" : ", ") + t;
      for (const auto& t : got)
        if (!want.count(t)) extra += (extra.empty() ? "" : ", ") + t;
      // One writer per topic: a second one (a simulator left running beside a bridge or a
      // replay) would interleave its samples with the source's.
      std::string doubled;
      for (const auto& t : got) {
        const auto n = std::count_if(writers.begin(), writers.end(), [&](const auto& e) { return e.topic == t; });
        if (n != 1) doubled += (doubled.empty() ? "" : ", ") + t + " (" + std::to_string(n) + " writers)";
      }
      std::string detail = std::to_string(got.size()) + " writer topic(s) after " + num("%.1f", discovery_took) + " s";
      if (!missing.empty()) detail += "; missing: " + missing;
      if (!extra.empty()) detail += "; not in the contract: " + extra;
      if (!doubled.empty()) detail += "; more than one writer: " + doubled;
      checks.add("discovery.topics", missing.empty() && extra.empty() && doubled.empty(), detail);
    }
    const auto contract_of = [&](const std::string& topic) -> const ContractTopic* {
      for (const auto& t : contract.writers)
        if (prefix + t.topic == topic) return &t;
      return nullptr;
    };
    {  // types and QoS of every writer
      std::string type_bad, qos_bad;
      std::size_t compared = 0;
      for (const auto& e : writers) {
        const ContractTopic* t = contract_of(e.topic);
        if (!t) continue;
        ++compared;
        if (type_key(e.type_name) != type_key(t->type))
          type_bad += (type_bad.empty() ? "" : "; ") + e.topic + " is " + e.type_name + " (contract " + t->type + ")";
        if (const auto d = qos_diff(t->qos, qos_fields(e.qos)); !d.empty())
          qos_bad += (qos_bad.empty() ? "" : " | ") + e.topic + ": " + d;
      }
      checks.add("discovery.types", compared > 0 && type_bad.empty(),
                 type_bad.empty() ? std::to_string(compared) + " writer(s) of the contract's types" : type_bad);
      checks.add("discovery.qos", compared > 0 && qos_bad.empty(),
                 qos_bad.empty() ? std::to_string(compared) + " writer(s) with the contract's QoS" : qos_bad);
    }
    if (!no_command_reader) {
      std::string bad;
      for (const auto& e : readers) {
        if (type_key(e.type_name) != type_key(contract.command.type))
          bad += (bad.empty() ? "" : "; ") + std::string("type ") + e.type_name + " (contract " +
                 contract.command.type + ")";
        if (const auto d = qos_diff(contract.command.qos, qos_fields(e.qos)); !d.empty())
          bad += (bad.empty() ? "" : "; ") + d;
      }
      checks.add("discovery.command_reader", !readers.empty() && bad.empty(),
                 readers.empty() ? "no reader of " + command_topic
                                 : (bad.empty() ? std::to_string(readers.size()) + " reader(s) of " + command_topic +
                                                      " with the contract's type and QoS"
                                                : command_topic + ": " + bad));
    }

    // --- b. measurement: every contract topic and every other discovered writer topic
    std::map<std::string, std::vector<rt::EndpointQos>> by_topic;
    std::map<std::string, std::string> type_of;
    for (const auto& t : contract.writers) {
      by_topic[prefix + t.topic];
      type_of[prefix + t.topic] = t.type;
    }
    for (const auto& e : writers) {
      by_topic[e.topic].push_back(e.qos);
      if (!type_of.count(e.topic)) type_of[e.topic] = e.type_name;
    }
    std::vector<std::unique_ptr<TopicReader>> readers_m;
    for (const auto& [topic, qos] : by_topic) {
      auto r = std::make_unique<TopicReader>();
      r->topic = topic;
      r->ts = type_support_of(type_of[topic]);
      if (!r->ts) {
        checks.add("rate." + topic.substr(prefix.size()), false, "type " + type_of[topic] + " unknown to this build");
        continue;
      }
      if (const ContractTopic* t = contract_of(topic)) r->nominal_hz = t->rate_hz;
      r->value_bound = contract.value_bound;
      r->max_age_s = contract.max_data_age_s;
      if (const auto* wt = distributed::find_wire_type(r->ts->type_name)) {
        r->spec = std::make_unique<scenario::SignalSpec>();
        r->spec->name = topic;
        r->spec->message = wt->name;
        r->spec->producer = "contract_probe";
        std::set<std::string> seen;
        for (const auto& s : wt->slots)
          if (seen.insert(s.field).second) r->spec->fields.push_back(s.field);
        try {
          r->wire = std::make_unique<distributed::WireSignal>(*r->spec, 10'000'000);
        } catch (const std::exception&) {
          r->wire.reset();  // a type whose fields the signal model cannot bind: JSON scan only
        }
      }
      // Reader history deep enough that a starved probe thread loses nothing.
      r->reader = p->make_reader(*r->ts, topic, rt::reader_qos_matching(qos, 256));
      readers_m.push_back(std::move(r));
    }
    TopicReader* truth = nullptr;
    for (auto& r : readers_m)
      if (r->topic == prefix + contract.truth) truth = r.get();

    // The command writer and the heartbeat reader exist from now, so that they have matched
    // long before the drive.
    rt::Publisher<msg::UnicycleCommand> cmd_pub;
    if (drive) cmd_pub = p->publisher<msg::UnicycleCommand>(command_topic, profiles.get("state"));
    HealthReader health;
    if (!health_topic.empty()) health.sub = p->subscriber<msg::Heartbeat>(health_topic, profiles.get("health"));

    // Window: starts once every reader matched its writers (at most 3 s).
    const int64_t match_end = monotonic_ns() + 3 * kSecond;
    while (!g_stop && monotonic_ns() < match_end && std::any_of(readers_m.begin(), readers_m.end(), [](const auto& r) {
      return r->reader->matched_count() == 0;
    }))
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    const int64_t win_start = wall_time_ns() + 100'000'000;  // 100 ms for matching to settle both ways
    const int64_t win_end = win_start + ns_of(measure_s);
    for (auto& r : readers_m) {
      std::lock_guard lock(r->mu);
      r->win_start = win_start;
      r->win_end = win_end;
    }
    for (auto& r : readers_m) r->thread = std::thread([rp = r.get()] { rp->run(); });
    result["window"] = {{"start_wall_s", static_cast<double>(win_start) * 1e-9},
                        {"end_wall_s", static_cast<double>(win_end) * 1e-9},
                        {"measure_s", measure_s}};
    while (!g_stop && wall_time_ns() < win_end + 50'000'000) {
      if (health.sub) health.poll();
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }

    for (auto& r : readers_m) {
      std::lock_guard lock(r->mu);
      const std::string name = r->topic.substr(prefix.size());
      const double span = static_cast<double>(r->last - r->first) * 1e-9;
      const double rate = r->count > 1 && span > 0 ? static_cast<double>(r->count - 1) / span : 0.0;
      const double lead = r->count ? static_cast<double>(r->first - win_start) * 1e-9 : measure_s;
      const double tail = r->count ? static_cast<double>(win_end - r->last) * 1e-9 : measure_s;
      topics_json[r->topic] = {{"type", r->ts->type_name},
                               {"samples", r->count},
                               {"span_s", span},
                               {"rate_hz", rate},
                               {"nominal_hz", r->nominal_hz},
                               {"first_after_start_s", lead},
                               {"last_before_end_s", tail},
                               {"max_gap_ms", static_cast<double>(r->max_gap) * 1e-6},
                               {"seq_errors", r->seq_errors},
                               {"data_time_errors", r->data_time_errors},
                               {"origin_errors", r->origin_errors},
                               {"max_data_age_ms", r->max_age_seen_s * 1e3},
                               {"bad_values", r->bad_values},
                               {"edge_refusals", r->refused}};
      if (r->nominal_hz > 0) {
        const bool covered = span >= contract.min_coverage * measure_s;
        const bool in_rate = std::fabs(rate - r->nominal_hz) <= contract.rate_tolerance * r->nominal_hz;
        std::string d = num("%.2f Hz", rate) + " (nominal " + num("%g", r->nominal_hz) + " Hz +- " +
                        num("%g", contract.rate_tolerance * 100) + " %), " + std::to_string(r->count) +
                        " samples over " + num("%.2f", span) + " s of the " + num("%g", measure_s) +
                        " s window, max gap " + num("%.1f", static_cast<double>(r->max_gap) * 1e-6) + " ms";
        if (!covered) d += "; the samples do not cover " + num("%g", contract.min_coverage * 100) + " % of the window";
        checks.add("rate." + name, in_rate && covered && r->count > 1, d);
      } else {
        checks.add("rate." + name, false,
                   "not in the contract: no nominal rate (" + std::to_string(r->count) + " samples)");
      }
      const bool headers_ok = r->count > 0 && r->seq_errors == 0 && r->data_time_errors == 0 && r->origin_errors == 0;
      std::string hd = std::to_string(r->count) + " samples: seq strictly increasing, data time within " +
                       num("%g", contract.max_data_age_s) + " s of receipt (max " +
                       num("%.1f", r->max_age_seen_s * 1e3) + " ms), origin > 0";
      if (!headers_ok)
        hd = std::to_string(r->seq_errors) + " seq error(s) " + r->first_seq_error + "; " +
             std::to_string(r->data_time_errors) + " data time error(s), " + std::to_string(r->origin_errors) +
             " origin error(s) " + r->first_time_error + (r->count == 0 ? "; no sample" : "");
      checks.add("headers." + name, headers_ok, hd);
      const bool values_ok = r->count > 0 && r->bad_values == 0 && r->refused == 0;
      checks.add("values." + name, values_ok,
                 values_ok ? std::to_string(r->count) + " samples: every value finite, |v| < " +
                                 num("%g", contract.value_bound) + (r->wire ? ", edge check passed" : "")
                           : std::to_string(r->bad_values) + " bad value(s) (first " + r->first_bad_value + "), " +
                                 std::to_string(r->refused) + " edge-check refusal(s) " + r->first_refusal +
                                 (r->count == 0 ? "; no sample" : ""));
    }

    // --- c. drive
    if (drive && !g_stop) {
      json dj;
      if (!truth) {
        checks.add("drive.step", false, "no truth topic " + prefix + contract.truth + " to watch");
        checks.add("drive.stale_stop", false, "no truth topic");
      } else {
        const int64_t match_deadline = monotonic_ns() + 3 * kSecond;
        while (!g_stop && cmd_pub.matched_count() == 0 && monotonic_ns() < match_deadline)
          std::this_thread::sleep_for(std::chrono::milliseconds(10));
        const Pose p0 = fresh_pose(*truth);
        msg::Heartbeat hb_drive;
        uint64_t hb_drive_count = 0;
        const int64_t period = ns_of(1.0 / contract.command_rate_hz);
        const int64_t drive_start = monotonic_ns();
        int64_t next = drive_start;
        uint64_t sent = 0, refused_writes = 0;
        msg::UnicycleCommand cmd;
        while (!g_stop && next < drive_start + ns_of(contract.drive_s)) {
          sleep_until_mono(next);
          const int64_t now = wall_time_ns();
          cmd.header().data_time_ns(now);
          cmd.header().origin_time_ns(now);
          cmd.v(contract.v);
          cmd.omega(contract.omega);
          if (cmd_pub.publish(cmd))
            ++sent;
          else
            ++refused_writes;
          next += period;
          if (next < monotonic_ns() - period) next = monotonic_ns();  // starved: no burst of old commands
          if (health.sub) health.poll();
        }
        const double drive_took = static_cast<double>(monotonic_ns() - drive_start) * 1e-9;
        if (health.sub) {
          health.poll();
          hb_drive = health.latest;
          hb_drive_count = health.count;
        }
        const Pose p1 = fresh_pose(*truth);
        const double c0 = std::cos(p0.theta), s0 = std::sin(p0.theta);
        const double dx = p1.x - p0.x, dy = p1.y - p0.y;
        const double forward = dx * c0 + dy * s0, sideways = std::fabs(-dx * s0 + dy * c0);
        const bool step_ok = p0.ok() && p1.ok() && cmd_pub.matched_count() > 0 && forward > contract.min_forward_m &&
                             sideways < contract.max_sideways_m;
        std::string sd = std::to_string(sent) + " commands v=" + num("%g", contract.v) +
                         " omega=" + num("%g", contract.omega) + " in " + num("%.2f", drive_took) + " s: truth " +
                         pose_text(p0) + " -> " + pose_text(p1) + ", forward " + num("%.3f", forward) + " m (> " +
                         num("%g", contract.min_forward_m) + "), sideways " + num("%.4f", sideways) + " m (< " +
                         num("%g", contract.max_sideways_m) + ")";
        if (cmd_pub.matched_count() == 0) sd += "; the command writer matched no reader";
        if (!p0.ok() || !p1.ok()) sd += "; no fresh truth sample";
        checks.add("drive.step", step_ok, sd);
        dj = {{"commands_sent", sent},  {"writes_refused", refused_writes}, {"forward_m", forward},
              {"sideways_m", sideways}, {"start", pose_text(p0)},           {"end", pose_text(p1)}};

        // Silence: after the grace period the robot must stand still, its truth still live.
        sleep_for_s(contract.stale_grace_s);
        const Pose pa = fresh_pose(*truth);
        const uint64_t truth_before = [&] {
          std::lock_guard lock(truth->mu);
          return truth->total;
        }();
        const int64_t still_end = monotonic_ns() + ns_of(contract.still_window_s);
        while (!g_stop && monotonic_ns() < still_end) {
          if (health.sub) health.poll();
          std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
        const Pose pb = fresh_pose(*truth);
        const uint64_t truth_after = [&] {
          std::lock_guard lock(truth->mu);
          return truth->total;
        }();
        const double moved = std::hypot(pb.x - pa.x, pb.y - pa.y);
        const uint64_t live = truth_after - truth_before;
        const bool live_ok = static_cast<double>(live) >= 0.5 * truth->nominal_hz * contract.still_window_s;
        const bool still_ok = pa.ok() && pb.ok() && moved < contract.max_still_m && live_ok;
        std::string td = "commands stopped; " + num("%g", contract.stale_grace_s) + " s later truth " + pose_text(pa) +
                         ", " + num("%g", contract.still_window_s) + " s after that " + pose_text(pb) + ": moved " +
                         num("%.5f", moved) + " m (< " + num("%g", contract.max_still_m) + "), " +
                         std::to_string(live) + " truth samples meanwhile";
        if (!live_ok) td += " (too few: the truth is not live, so standing still proves nothing)";
        if (health.sub) {
          health.poll();
          const auto& before = hb_drive.link();
          const auto& after = health.latest.link();
          const bool stops =
              hb_drive_count > 0 && health.count > hb_drive_count && after.stop_frames() > before.stop_frames();
          td += "; " + health_topic + ": stop_frames " + std::to_string(before.stop_frames()) +
                " at the end of the drive -> " + std::to_string(after.stop_frames()) + " " +
                num("%g", contract.stale_grace_s + contract.still_window_s) + " s later";
          if (!stops)
            td += " (no STOP frame sent after the commands stopped" +
                  std::string(health.count == 0 ? ", no heartbeat received)" : ")");
          dj["link_at_drive_end"] = link_json(before);
          dj["link_after_stale"] = link_json(after);
          dj["heartbeats"] = health.count;
          checks.add("drive.stale_stop", still_ok && stops, td);
        } else {
          checks.add("drive.stale_stop", still_ok, td);
        }
        dj["still_moved_m"] = moved;
        dj["truth_samples_while_still"] = live;
      }
      result["drive"] = dj;
    }

    g_stop = true;
    for (auto& r : readers_m)
      if (r->thread.joinable()) r->thread.join();
  } catch (const InputError& e) {
    std::fprintf(stderr, "contract_probe: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    checks.add("probe", false, std::string("failed: ") + e.what());
  }

  result["checks"] = checks.list;
  result["topics"] = topics_json;
  result["passed"] = checks.all;
  if (!out_file.empty()) {
    std::ofstream f(out_file);
    f << result.dump(2) << '\n';
    if (!f) {
      std::fprintf(stderr, "contract_probe: error: cannot write %s\n", out_file.c_str());
      return 2;
    }
  } else {
    std::printf("%s\n", result.dump(2).c_str());
  }
  return checks.all ? 0 : 1;
}
