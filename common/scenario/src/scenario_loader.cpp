// Loading and validating a scenario file (format: docs/scenarios.md).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <set>
#include <stdexcept>

#include <spdlog/spdlog.h>

#include "plexus/algorithms/core/validation.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/base/logging.hpp"
#include "plexus/base/yaml_reader.hpp"
#include "plexus/msg/registry.hpp"
#include "plexus/scenario/digest.hpp"
#include "plexus/scenario/format.hpp"
#include "plexus/scenario/plugins.hpp"
#include "plexus/scenario/registry.hpp"
#include "plexus/scenario/scenario.hpp"
#include "security_section.hpp"
#include "wiring.hpp"

namespace plexus::scenario {

const char* to_string(RobotSource::Type t) {
  switch (t) {
    case RobotSource::Type::simulator: return "simulator";
    case RobotSource::Type::serial_bridge: return "serial_bridge";
    case RobotSource::Type::udp_bridge: return "udp_bridge";
    case RobotSource::Type::replay: return "replay";
  }
  return "?";
}
namespace {

/// `priority` and `cpu` of a service or a robot (its plant-side process), realtime only; its
/// `priority` defaults to the scenario's clock.priority.
void read_scheduling(const YamlMap& section, ScenarioComponent& out, int default_priority) {
  out.priority = section.optional<int>("priority", default_priority);
  if (out.priority < 0 || out.priority > 99)
    section.fail("priority", "must be in 0..99 (SCHED_FIFO; 0: normal scheduling)");
  out.cpu = section.optional<int>("cpu", -1);
  if (out.cpu < -1 || out.cpu > 1023) section.fail("cpu", "must be a CPU number 0..1023 (-1: no affinity)");
}

bool valid_name(const std::string& s) {
  if (s.empty() || s.size() > 64) return false;
  for (char c : s)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-')) return false;
  return true;
}

/// A robot's or service's `dds` key: the vendor its process uses under `plexus launch`.
std::string dds_key(const YamlMap& section) {
  const std::string v = section.optional<std::string>("dds", "");
  if (section.has("dds") && v != "fast" && v != "cyclone")
    section.fail("dds", "expected fast or cyclone, got '" + v + "'");
  return v;
}

std::string known_list(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out.empty() ? "none" : out;
}

std::string name_key(const YamlMap& parent, const std::string& key, const char* what) {
  if (!valid_name(key))
    parent.fail(key, std::string("invalid ") + what + " name (letters, digits, '_' and '-', at most 64)");
  return key;
}

struct Loader {
  Scenario& sc;
  std::set<std::string> hosts;
  std::set<std::string> robot_names;
  std::vector<std::pair<YAML::Node, uint64_t>> derived_seeds;  // written into the resolved tree

  int64_t period_of(const YamlMap& section) const {
    if (!section.has("rate")) return 1;
    const double rate = section.required<double>("rate");
    const double base_rate = 1.0 / sc.step;
    if (rate <= 0.0) section.fail("rate", "must be > 0 Hz");
    if (rate > base_rate * (1.0 + 1e-9))
      section.fail("rate", "is faster than the base rate " + std::to_string(base_rate) + " Hz (1 / step)");
    const double period = base_rate / rate;
    const double whole = std::round(period);
    if (std::abs(period - whole) > 1e-6 * whole)
      section.fail("rate", "must divide the base rate " + std::to_string(base_rate) +
                               " Hz: the period must be a whole number of steps");
    return static_cast<int64_t>(whole);
  }

  ScenarioComponent build(const YamlMap& section, const std::string& path, const std::string& key,
                          const std::string& robot, const YAML::Node& node, bool service) {
    ComponentConfig cfg;
    cfg.key = key;
    cfg.robot = robot;
    cfg.name = service ? key : robot + "/" + key;
    cfg.type = section.required<std::string>("type");
    const ComponentType* type = find_component_type(cfg.type);
    if (!type) {
      std::vector<std::string> names;
      for (const auto* t : component_types()) names.push_back(t->name);
      section.fail("type", "unknown component type '" + cfg.type + "' (known: " + known_list(names) + ")");
    }
    cfg.kind = type->kind;
    const bool fits = service ? (cfg.kind != ComponentKind::plant && cfg.kind != ComponentKind::sensor)
                              : (key == "plant" ? cfg.kind == ComponentKind::plant : cfg.kind == ComponentKind::sensor);
    if (!fits) {
      const std::string place = service ? "services" : key == "plant" ? "a robot's plant" : "a robot's sensors";
      section.fail("type", "'" + cfg.type + "' is a " + to_string(cfg.kind) + " and cannot be used in " + place);
    }
    cfg.base_step = sc.step;
    cfg.base_dir = sc.base_dir;
    cfg.warnings = &sc.warnings;
    cfg.period_steps = period_of(section);
    if (section.has("seed")) {
      const long long seed = section.required<long long>("seed");
      if (seed < 0) section.fail("seed", "must be >= 0");
      cfg.seed = static_cast<uint64_t>(seed);
    } else {
      cfg.seed = derive_seed(sc.seed, cfg.name);
      derived_seeds.emplace_back(node, cfg.seed);
    }
    std::map<std::string, std::string> remap_where;
    if (section.has("remap")) {
      const YamlMap remap = section.map("remap");
      for (const auto& port : remap.keys()) {
        cfg.remap[port] = remap.required<std::string>(port);
        remap_where[port] = remap.where(remap.node(port)) + ": " + remap.key_path(port);
      }
    }
    ScenarioComponent out;
    out.remap_where = std::move(remap_where);
    if (service) {
      if (section.has("robot")) {
        cfg.robot = section.required<std::string>("robot");
        if (sc.partial ? !valid_name(cfg.robot) : !robot_names.count(cfg.robot))
          section.fail("robot", sc.partial ? "invalid robot name '" + cfg.robot + "'"
                                           : "no robot '" + cfg.robot + "' in robots");
      }
      out.host = section.optional<std::string>("host", "");
      if (section.has("host") && !hosts.count(out.host)) section.fail("host", "no host '" + out.host + "' in hosts");
      out.qos = section.optional<std::string>("qos", "");
      if (section.has("qos") && out.qos.empty()) section.fail("qos", "must name a QoS profile");
      out.dds = dds_key(section);
      out.process = section.optional<std::string>("process", "");
      if (section.has("process") && !valid_name(out.process))
        section.fail("process", "letters, digits, '_' and '-' only, at most 64 characters");
      out.restart = section.optional<std::string>("restart", out.restart);
      if (out.restart != "never" && out.restart != "on_failure" && out.restart != "always")
        section.fail("restart", "expected never, on_failure or always, got '" + out.restart + "'");
      out.restart_delay = section.optional<double>("restart_delay", 0.0);
      if (!(out.restart_delay >= 0.0 && out.restart_delay <= 3600.0))
        section.fail("restart_delay", "must be in [0, 3600] s");
      read_scheduling(section, out, sc.loop_priority);  // the clock section is read before the services
      out.blind_after_s = sc.blind_after_s;
      if (section.has("blind_after_s")) {
        if (cfg.kind != ComponentKind::estimator)
          section.fail("blind_after_s",
                       "only an estimator goes blind (this service is a " + std::string(to_string(cfg.kind)) + ")");
        out.blind_after_s = section.required<double>("blind_after_s");
        if (!(out.blind_after_s >= 0.0 && out.blind_after_s <= 60.0))
          section.fail("blind_after_s", "must be in [0, 60] s");
      }
    }
    cfg.section = &section;
    out.type = cfg.type;
    out.kind = cfg.kind;
    out.period_steps = cfg.period_steps;
    out.where = section.where() + ": " + path;
    try {
      out.component = type->factory(cfg);
    } catch (const InputError&) {
      throw;
    } catch (const algorithms::validation::ParameterError& e) {               // an algorithm's own parameter check
      if (section.has(e.parameter())) section.fail(e.parameter(), e.what());  // at the key's own line
      throw InputError(out.where + ": " + e.what());
    } catch (const std::invalid_argument& e) {
      throw InputError(out.where + ": " + e.what());
    } catch (const std::domain_error& e) {
      throw InputError(out.where + ": " + e.what());
    }
    section.reject_unknown();
    for (const auto& [port, signal] : cfg.remap) {
      bool found = false;
      for (const auto& p : out.component->inputs()) found = found || p->port() == port;
      for (const auto& p : out.component->outputs()) found = found || p->port() == port;
      if (!found) section.fail("remap", "'" + cfg.type + "' has no port '" + port + "'");
    }
    return out;
  }

  // `plugins:` before anything is built: their component, service and message types are then known.
  void load_plugins(const YamlMap& top) {
    if (!top.has("plugins")) return;
    const auto entries = top.sequence("plugins");
    for (std::size_t i = 0; i < entries.size(); ++i) {
      const std::string where = top.where(entries[i]) + ": plugins." + std::to_string(i);
      if (!entries[i].IsScalar()) throw InputError(where + ": expected the path of a shared library");
      const std::filesystem::path p = entries[i].as<std::string>();
      const std::string path =
          p.is_absolute() || sc.base_dir.empty() ? p.string() : (std::filesystem::path(sc.base_dir) / p).string();
      load_plugin(path, where);
      sc.plugins.push_back(std::filesystem::absolute(path).lexically_normal().string());
    }
  }

  void load_top(const YamlMap& top) {
    sc.name = top.required<std::string>("name");
    if (!valid_name(sc.name)) top.fail("name", "letters, digits, '_' and '-' only, at most 64 characters");
    sc.description = top.optional<std::string>("description", "");
    sc.base_dir = std::filesystem::path(sc.file).parent_path().string();
    if (top.has("base_dir")) {
      if (!sc.partial) top.fail("base_dir", "only a part of a scenario names the folder of its relative paths");
      sc.base_dir = top.required<std::string>("base_dir");
    }
    load_plugins(top);
    sc.step = top.required<double>("step");
    // At least 1 us: distributed runs carry the step in whole nanoseconds (a step below 0.5 ns
    // would be 0 there, and every process divides by it).
    if (!(sc.step >= 1e-6) || !std::isfinite(sc.step)) top.fail("step", "must be at least 1e-6 s");
    if (sc.partial && !top.has("duration")) {
      sc.until_stopped = true;
      sc.steps = kUntilStopped;
      sc.duration = static_cast<double>(sc.steps) * sc.step;
    } else {
      sc.duration = top.required<double>("duration");
      if (sc.duration <= 0.0) top.fail("duration", "must be > 0 s");
      if (sc.step > sc.duration) top.fail("step", "must not exceed the duration");
      const double steps = sc.duration / sc.step;
      if (steps > 1e9)
        top.fail("duration", format_number(sc.duration) + " s at a step of " + format_number(sc.step) +
                                 " s is more than the 1e9 steps a run can hold");
      sc.steps = std::llround(steps);
      if (std::abs(steps - static_cast<double>(sc.steps)) > 1e-6)
        top.fail("duration", "must be a whole number of steps (duration / step = " + std::to_string(steps) + ")");
    }
    const long long seed = sc.partial ? top.optional<long long>("seed", 0) : top.required<long long>("seed");
    if (seed < 0) top.fail("seed", "must be >= 0");
    sc.seed = static_cast<uint64_t>(seed);
    if (top.has("clock")) {
      const YamlMap clock = top.map("clock");
      const auto mode = clock.required<std::string>("mode");
      if (mode == "lockstep")
        sc.clock = ClockMode::lockstep;
      else if (mode == "realtime")
        sc.clock = ClockMode::realtime;
      else
        clock.fail("mode", "expected lockstep or realtime, got '" + mode + "'");
      sc.input_deadline_periods = clock.optional<double>("input_deadline_periods", sc.input_deadline_periods);
      if (!(sc.input_deadline_periods >= 1.0 && sc.input_deadline_periods <= 1000.0))
        clock.fail("input_deadline_periods", "must be in [1, 1000]");
      sc.blind_after_s = clock.optional<double>("blind_after_s", sc.blind_after_s);
      if (!(sc.blind_after_s >= 0.0 && sc.blind_after_s <= 60.0)) clock.fail("blind_after_s", "must be in [0, 60] s");
      sc.loop_priority = clock.optional<int>("priority", 0);
      if (sc.loop_priority < 0 || sc.loop_priority > 99)
        clock.fail("priority", "must be in 0..99 (SCHED_FIFO; 0: normal scheduling)");
      clock.reject_unknown();
    }
    if (top.has("dds")) {
      const YamlMap dds = top.map("dds");
      sc.dds_vendor = dds.optional<std::string>("vendor", "");
      if (dds.has("vendor") && sc.dds_vendor != "fast" && sc.dds_vendor != "cyclone")
        dds.fail("vendor", "expected fast or cyclone, got '" + sc.dds_vendor + "'");
      sc.dds_domain = dds.optional<int>("domain", 0);
      if (sc.dds_domain < 0 || sc.dds_domain > 232) dds.fail("domain", "must be in 0..232");
      sc.dds_transport = dds.optional<std::string>("transport", "auto");
      if (sc.dds_transport != "auto" && sc.dds_transport != "udp" && sc.dds_transport != "shm")
        dds.fail("transport", "expected auto, udp or shm, got '" + sc.dds_transport + "'");
      sc.dds_naming = dds.optional<std::string>("naming", "plexus");
      if (sc.dds_naming != "plexus" && sc.dds_naming != "ros2")
        dds.fail("naming", "expected plexus or ros2, got '" + sc.dds_naming + "'");
      sc.dds_participants_per_host = dds.optional<int>("participants_per_host", sc.dds_participants_per_host);
      if (sc.dds_participants_per_host < 1 || sc.dds_participants_per_host > kMaxParticipantsPerHost)
        dds.fail("participants_per_host", "must be in 1.." + std::to_string(kMaxParticipantsPerHost));
      dds.reject_unknown();
    }
    if (top.has("security")) sc.security = load_security_section(top, sc.base_dir);
    if (top.has("hosts")) {
      const YamlMap hs = top.map("hosts");
      for (const auto& h : hs.keys()) {
        const YamlMap host = hs.map(name_key(hs, h, "host"));
        sc.host_address[h] = host.optional<std::string>("address", "");
        auto& access = sc.host_access[h];
        access.ssh = host.optional<std::string>("ssh", "");
        access.workdir = host.optional<std::string>("workdir", "");
        access.plexus = host.optional<std::string>("plexus", "");
        // An ssh destination is one word: a leading '-' would reach ssh as an option.
        if (host.has("ssh") &&
            (access.ssh.empty() || access.ssh[0] == '-' || access.ssh.find_first_of(" \t\r\n") != std::string::npos))
          host.fail("ssh", "expected [user@]host or a Host of the ssh config (one word, not starting with '-')");
        for (const char* key : {"workdir", "plexus"})
          if (host.has(key) && (host.optional<std::string>(key, "").empty() ||
                                host.optional<std::string>(key, "").find_first_of("\r\n") != std::string::npos))
            host.fail(key, "expected a path on that host");
        if ((host.has("workdir") || host.has("plexus")) && !host.has("ssh"))
          host.fail(host.has("workdir") ? "workdir" : "plexus",
                    "only for a host reached over ssh (add ssh: [user@]host)");
        host.reject_unknown();
        hosts.insert(h);
        sc.hosts.push_back(h);
      }
    }
  }

  void load_inputs(const YamlMap& top) {
    if (!top.has("inputs")) return;
    if (!sc.partial) top.fail("inputs", "only a part of a scenario (a service's own document) declares inputs");
    const YamlMap inputs = top.map("inputs");
    for (const auto& signal : inputs.keys()) {
      const YamlMap in = inputs.map(signal);
      ExternalInput e;
      if (in.has("rate")) e.period_steps = period_of(in);
      if (in.has("period_steps")) {
        const long long period = in.required<long long>("period_steps");
        if (period < 1) in.fail("period_steps", "must be >= 1");
        e.period_steps = period;
      }
      if (in.has("stage")) {
        e.staged = true;
        if (!parse_component_kind(in.required<std::string>("stage"), e.stage))
          in.fail("stage", "expected plant, sensor, reference, estimator or controller");
      }
      e.qos = in.optional<std::string>("qos", "");
      e.producer = in.optional<std::string>("producer", "");
      in.reject_unknown();
      sc.inputs[signal] = e;
    }
  }

  /// robots.<r>.source: a type name, or a map with `type` and that type's keys.
  // A bridge's device time (docs/bridges.md, "Device time"): device_time, time_sync_hz, cycle_sync.
  static void device_time(const YamlMap& m, RobotSource& src) {
    src.device_time = m.optional<bool>("device_time", src.device_time);
    src.time_sync_hz = m.optional<double>("time_sync_hz", src.time_sync_hz);
    if (!(src.time_sync_hz >= 1.0 && src.time_sync_hz <= 200.0))
      m.fail("time_sync_hz", "expected 1 .. 200 exchanges per second");
    if (m.has("time_sync_hz") && !src.device_time) m.fail("time_sync_hz", "only with device_time: true");
    // The cycle sync (docs/bridges.md, "Cycle sync") is sent in the device's clock.
    src.cycle_sync = m.optional<bool>("cycle_sync", src.cycle_sync);
    if (src.cycle_sync && !src.device_time)
      m.fail("cycle_sync", "only with device_time: true (the cycle is sent in the device's clock)");
  }

  // A device's own frame table (docs/bridges.md, "A device's own frames"): each entry's
  // keys, its IDL type, and each field against that type's members.
  void frames(const YamlMap& m, RobotSource& src) {
    if (!m.has("frames")) return;
    const std::string base = m.key_path("frames");
    const auto entries = m.sequence("frames");
    if (entries.empty()) m.fail("frames", "expected a list of frames (leave the key out for the built-in table)");
    for (std::size_t i = 0; i < entries.size(); ++i) {
      const YamlMap e(entries[i], sc.file, base + "[" + std::to_string(i) + "]");
      DeclaredFrame f;
      f.where = e.where() + ": " + base + "[" + std::to_string(i) + "]";
      f.id = e.required<int>("id");
      if (f.id < 0 || f.id > 255) e.fail("id", "expected 0 .. 255 (0x00 .. 0xFF)");
      const std::string dir = e.required<std::string>("direction");
      if (dir != "to_host" && dir != "to_device")
        e.fail("direction", "expected to_host or to_device, got '" + dir + "'");
      f.to_device = dir == "to_device";
      f.topic = e.required<std::string>("topic");
      f.type = e.required<std::string>("type");
      f.meaning = e.optional<std::string>("meaning", "");
      const msg::WireType* type = msg::find_wire_type(f.type);
      if (!type) e.fail("type", "no IDL type '" + f.type + "' is known (plexus msg list shows them)");
      const auto fields = e.sequence("fields");
      if (fields.empty()) e.fail("fields", "expected the payload's fields, in order");
      for (std::size_t j = 0; j < fields.size(); ++j) {
        const YamlMap fm(fields[j], sc.file, e.key_path("fields") + "[" + std::to_string(j) + "]");
        DeclaredFrame::Field field;
        field.name = fm.required<std::string>("name");
        field.wire = fm.optional<std::string>("wire", field.wire);
        field.scale = fm.optional<double>("scale", field.scale);
        fm.reject_unknown();
        const msg::WireSlot* slot = nullptr;
        for (const auto& sl : type->slots)
          if (sl.field == field.name) slot = &sl;
        if (!slot) {
          std::vector<std::string> known;
          for (const auto& sl : type->slots)
            if (sl.primary) known.push_back(sl.field);
          fm.fail("name", "'" + field.name + "' is not a field of " + f.type + " (" + known_list(known) + ")");
        }
        static const std::set<std::string> kWire{"f64", "f32", "i8", "u8", "i16", "u16", "i32", "u32"};
        if (!kWire.count(field.wire)) fm.fail("wire", "expected f64, f32, i8, u8, i16, u16, i32 or u32");
        const bool integer_wire = field.wire[0] != 'f';
        if (!(field.scale > 0.0) || !std::isfinite(field.scale)) fm.fail("scale", "expected a number > 0");
        if (!integer_wire && fm.has("scale")) fm.fail("scale", "only for integer wire types (SI value = raw * scale)");
        // What the message member holds: an integer member takes integers only.
        const bool integer_member = slot->kind != msg::WireSlot::Kind::f64 && slot->kind != msg::WireSlot::Kind::f32;
        if (integer_member && (!integer_wire || field.scale != std::floor(field.scale)))
          fm.fail("wire", "member " + std::string(slot->path) + " of " + f.type + " holds integers; " + field.wire +
                              (integer_wire ? " with scale " + std::to_string(field.scale) : std::string()) +
                              " does not");
        for (const auto& other : f.fields)
          if (other.name == field.name) fm.fail("name", "'" + field.name + "' twice in one frame");
        f.fields.push_back(field);
      }
      e.reject_unknown();
      for (const auto& other : src.frames)
        if (other.id == f.id)
          e.fail("id", "id " + std::to_string(f.id) + " is declared twice (also " + other.where + ")");
      src.frames.push_back(std::move(f));
    }
  }

  void load_source(const YamlMap& robot, const std::string& rpath, const std::string& r) {
    RobotSource src;
    const YAML::Node node = robot.node("source");
    src.where = robot.where(node) + ": " + robot.key_path("source");
    const bool scalar = node.IsScalar();
    std::string type;
    if (scalar) type = robot.required<std::string>("source");
    const auto set_type = [&](const std::string& t, const auto& fail) {
      if (t == "simulator")
        src.type = RobotSource::Type::simulator;
      else if (t == "serial_bridge")
        src.type = RobotSource::Type::serial_bridge;
      else if (t == "udp_bridge")
        src.type = RobotSource::Type::udp_bridge;
      else if (t == "replay")
        src.type = RobotSource::Type::replay;
      else
        fail("expected simulator, serial_bridge, udp_bridge or replay, got '" + t + "'");
    };
    if (scalar) {
      set_type(type, [&](const std::string& m) { robot.fail("source", m); });
      if (src.type != RobotSource::Type::simulator)
        robot.fail("source",
                   "a " + type + " needs its parameters: write source: {type: " + type + ", ...} (docs/bridges.md)");
    } else {
      const YamlMap m = robot.map("source");
      set_type(m.required<std::string>("type"), [&](const std::string& msg) { m.fail("type", msg); });
      const auto positive = [&](const char* key, double fallback) {
        const double v = m.optional<double>(key, fallback);
        if (!(v > 0.0) || !std::isfinite(v)) m.fail(key, "expected a positive number of seconds");
        return v;
      };
      switch (src.type) {
        case RobotSource::Type::simulator: break;
        case RobotSource::Type::serial_bridge:
          src.device = m.required<std::string>("device");
          if (src.device.empty()) m.fail("device", "expected the path of a tty");
          src.baud = m.optional<long>("baud", src.baud);
          if (src.baud < 115200 || src.baud > 1000000) m.fail("baud", "expected 115200 .. 1000000");
          src.link_timeout_s = positive("link_timeout", src.link_timeout_s);
          src.retry_s = positive("retry", src.retry_s);
          device_time(m, src);
          frames(m, src);
          break;
        case RobotSource::Type::udp_bridge:
          src.bind = m.required<std::string>("bind");
          src.peer = m.required<std::string>("peer");
          src.link_timeout_s = positive("link_timeout", src.link_timeout_s);
          device_time(m, src);
          frames(m, src);
          break;
        case RobotSource::Type::replay: {
          const std::string rec = m.required<std::string>("recording");
          src.recording = std::filesystem::path(rec).is_absolute()
                              ? rec
                              : (std::filesystem::path(sc.base_dir) / rec).lexically_normal().string();
          break;
        }
      }
      m.reject_unknown();
    }
    if (src.type != RobotSource::Type::simulator) sc.sources[r] = src;
    (void)rpath;
  }

  void load_components(const YamlMap& top) {
    std::vector<ScenarioComponent> all;
    if (!sc.partial || top.has("robots")) {
      const YamlMap robots = top.map("robots");
      if (robots.keys().empty() && !sc.partial) top.fail("robots", "needs at least one robot");
      for (const auto& r : robots.keys()) {
        const YamlMap robot = robots.map(name_key(robots, r, "robot"));
        robot_names.insert(r);
        const std::string rpath = "robots." + r;
        const std::string robot_host = robot.optional<std::string>("host", "");
        if (robot.has("host") && !hosts.count(robot_host)) robot.fail("host", "no host '" + robot_host + "' in hosts");
        const std::string robot_dds = dds_key(robot);
        ScenarioComponent scheduling;  // the robot's `priority` and `cpu`, for its plant and sensors
        read_scheduling(robot, scheduling, sc.loop_priority);
        if (robot.has("source")) load_source(robot, rpath, r);
        const YamlMap plant = robot.map("plant");
        all.push_back(build(plant, rpath + ".plant", "plant", r, sc.resolved["robots"][r]["plant"], false));
        all.back().host = robot_host;
        all.back().dds = robot_dds;
        all.back().priority = scheduling.priority;
        all.back().cpu = scheduling.cpu;
        if (robot.has("sensors")) {
          const YamlMap sensors = robot.map("sensors");
          for (const auto& s : sensors.keys()) {
            const YamlMap sensor = sensors.map(name_key(sensors, s, "sensor"));
            all.push_back(build(sensor, rpath + ".sensors." + s, s, r, sc.resolved["robots"][r]["sensors"][s], false));
            all.back().host = robot_host;  // a robot's sensors run with its plant
            all.back().dds = robot_dds;
            all.back().priority = scheduling.priority;
            all.back().cpu = scheduling.cpu;
          }
        }
        robot.reject_unknown();
      }
    }
    if (top.has("services")) {
      const YamlMap services = top.map("services");
      for (const auto& s : services.keys()) {
        const YamlMap service = services.map(name_key(services, s, "service"));
        all.push_back(build(service, "services." + s, s, "", sc.resolved["services"][s], true));
      }
    }
    std::stable_sort(all.begin(), all.end(), [](const ScenarioComponent& a, const ScenarioComponent& b) {
      return static_cast<int>(a.kind) < static_cast<int>(b.kind);
    });
    sc.components = std::move(all);
    sc.signals = detail::wire(sc).signals;
  }

  /// `loops:`: each loop's members (robot or service names), its budget and its process.
  /// A loop's `process` is given to every member, as a service's own `process` key is.
  void load_loops(const YamlMap& top) {
    if (!top.has("loops")) return;
    if (sc.partial) top.fail("loops", "belongs to a whole scenario, not to one process's part");
    const YamlMap loops = top.map("loops");
    for (const auto& name : loops.keys()) {
      const YamlMap l = loops.map(name_key(loops, name, "loop"));
      ScenarioLoop loop;
      loop.name = name;
      loop.where = l.where() + ": loops." + name;
      const auto members = l.sequence("members");
      if (members.size() < 2) l.fail("members", "a loop has at least two members (robots or services)");
      int64_t fastest = 0;
      for (const auto& m : members) {
        if (!m.IsScalar()) l.fail("members", "expected a list of robot and service names");
        const std::string member = m.as<std::string>();
        std::size_t found = 0;
        for (std::size_t i = 0; i < sc.components.size(); ++i) {
          const auto& c = sc.components[i];
          const bool physical = c.kind == ComponentKind::plant || c.kind == ComponentKind::sensor;
          const std::string& n = c.component->name();
          if (physical ? n.substr(0, n.find('/')) != member : n != member) continue;
          if (std::count(loop.members.begin(), loop.members.end(), i))
            l.fail("members", "'" + member + "' is named twice");
          loop.members.push_back(i);
          fastest = fastest == 0 ? c.period_steps : std::min(fastest, c.period_steps);
          ++found;
        }
        if (found == 0) l.fail("members", "no robot or service '" + member + "' in this scenario");
        if (sc.sources.count(member))
          l.fail("members", "robot '" + member + "' is fed by its source (" + to_string(sc.sources.at(member).type) +
                                "), a process of its own: it cannot be a member of a loop");
      }
      loop.deadline_s = l.optional<double>("deadline", static_cast<double>(fastest) * sc.step);
      if (!(loop.deadline_s > 0.0 && loop.deadline_s <= 3600.0)) l.fail("deadline", "must be in (0, 3600] s");
      loop.process = l.optional<std::string>("process", "");
      if (l.has("process") && !valid_name(loop.process))
        l.fail("process", "letters, digits, '_' and '-' only, at most 64 characters");
      for (std::size_t i : loop.members) {
        auto& c = sc.components[i];
        if (loop.process.empty()) continue;
        if (!c.process.empty() && c.process != loop.process)
          l.fail("process",
                 "'" + c.component->name() + "' already runs in process '" + c.process + "' (" + c.where + ")");
        c.process = loop.process;
      }
      l.reject_unknown();
      sc.loops.push_back(std::move(loop));
    }
  }

  void load_metrics(const YamlMap& top) {
    if (!top.has("metrics")) return;
    const auto entries = top.sequence("metrics");
    std::set<std::string> names{"digest"};
    for (std::size_t i = 0; i < entries.size(); ++i) {
      const YamlMap entry(entries[i], sc.file, "metrics." + std::to_string(i));
      ScenarioMetric m;
      m.type = entry.required<std::string>("type");
      m.name = entry.optional<std::string>("name", m.type);
      m.paper = entry.optional<std::string>("paper", "");  // the published figure it reproduces (report table)
      const MetricType* type = find_metric_type(m.type);
      if (!type) {
        std::vector<std::string> known;
        for (const auto* t : metric_types()) known.push_back(t->name);
        entry.fail("type", "unknown metric type '" + m.type + "' (known: " + known_list(known) + ")");
      }
      if (!valid_name(m.name)) entry.fail("name", "letters, digits, '_' and '-' only");
      if (!names.insert(m.name).second) entry.fail("name", "metric '" + m.name + "' is defined twice (or is 'digest')");
      const MetricSetup setup(entry, sc.signals, sc.step, sc.duration);
      m.compute = type->factory(setup);
      entry.reject_unknown();
      sc.metrics.push_back(std::move(m));
    }
  }

  void load_expectations(const YamlMap& top) {
    if (!top.has("expectations")) return;
    const YamlMap ex = top.map("expectations");
    for (const auto& metric : ex.keys()) {
      const auto text = ex.required<std::string>(metric);
      const bool known =
          std::any_of(sc.metrics.begin(), sc.metrics.end(), [&](const auto& m) { return m.name == metric; });
      if (!known) ex.fail(metric, "no metric '" + metric + "' in metrics");
      Expectation e;
      if (!parse_expectation(metric, text, e))
        ex.fail(metric, "expected '<op> <number>' with op one of <=, >=, <, >, ==; got '" + text + "'");
      sc.expectations.push_back(e);
    }
    load_paper_inconsistent(top);
  }

  /// `paper_inconsistent:` {metric: evidence}: expectations whose published figure the
  /// paper's own text cannot produce (expectation.hpp); each names an expectation.
  void load_paper_inconsistent(const YamlMap& top) {
    if (!top.has("paper_inconsistent")) return;
    const YamlMap pi = top.map("paper_inconsistent");
    for (const auto& metric : pi.keys()) {
      const auto evidence = pi.required<std::string>(metric);
      if (evidence.empty()) pi.fail(metric, "must name the evidence (a docs page and section)");
      bool found = false;
      for (Expectation& e : sc.expectations)
        if (e.metric == metric) e.inconsistent = evidence, found = true;
      if (!found)
        pi.fail(metric, "no expectation on '" + metric +
                            "' in expectations (an entry here marks one; one removed from expectations, with "
                            "--set say, goes from paper_inconsistent too: --set paper_inconsistent={})");
    }
  }

  /// `parameter_changes:`: [{step, key, value}], each checked against its component's own
  /// validator now (parameter_change.hpp). A part skips the components it does not build: the
  /// launcher has checked the whole scenario.
  void load_parameter_changes(const YamlMap& top) {
    if (!top.has("parameter_changes")) return;
    const auto entries = top.sequence("parameter_changes");
    for (std::size_t i = 0; i < entries.size(); ++i) {
      const YamlMap entry(entries[i], sc.file, "parameter_changes." + std::to_string(i));
      ParameterChange change;
      change.where = entry.where() + ": parameter_changes." + std::to_string(i);
      const double step = entry.required<double>("step");
      if (!(step >= 0.0 && step == std::floor(step) && (sc.until_stopped || step <= static_cast<double>(sc.steps))))
        entry.fail("step",
                   "must be a whole step in [0, " + std::to_string(sc.steps) + "] (got " + format_number(step) + ")");
      change.step = static_cast<int64_t>(step);
      const auto name = entry.required<std::string>("key");
      change.value = entry.required<double>("value");
      entry.reject_unknown();
      std::string why;
      const auto ref = find_tunable(sc, {}, name, why);
      if (!ref) {
        if (sc.partial) continue;  // another process's component
        entry.fail("key", why);
      }
      if (const std::string bad = check_value(*ref->parameter, change.value); !bad.empty()) entry.fail("value", bad);
      change.component = ref->component;
      change.key = ref->parameter->key;
      sc.parameter_changes.push_back(std::move(change));
    }
    std::stable_sort(sc.parameter_changes.begin(), sc.parameter_changes.end(),
                     [](const auto& a, const auto& b) { return a.step < b.step; });
  }

  void load(const YamlMap& top) {
    // Read every top-level key first, so a misspelt one is reported before anything deeper.
    for (const char* k : {"robots", "services", "loops", "metrics", "expectations", "paper_inconsistent", "inputs",
                          "parameter_changes"})
      top.node(k);
    load_top(top);
    top.reject_unknown();
    load_inputs(top);
    load_components(top);
    load_loops(top);
    load_parameter_changes(top);
    if (sc.partial && (top.has("metrics") || top.has("expectations") || top.has("paper_inconsistent")))
      top.fail(top.has("metrics")        ? "metrics"
               : top.has("expectations") ? "expectations"
                                         : "paper_inconsistent",
               "belongs to a whole scenario, not to one service's part");
    load_metrics(top);
    load_expectations(top);
    for (auto& [node, seed] : derived_seeds) {
      YAML::Node n = node;
      n["seed"] = seed;
    }
  }
};

Scenario load_root(YAML::Node root, const std::string& origin, const std::vector<Override>& overrides,
                   LoadOptions options) {
  Scenario sc;
  sc.file = origin;
  sc.partial = options.partial;
  try {
    apply_overrides(root, overrides);
    sc.resolved = root;
    Loader loader{sc, {}, {}, {}};
    loader.load(YamlMap(root, origin));
  } catch (const InputError& e) {
    throw InputError(attribute_to_override(e.what(), origin, overrides));
  }
  return sc;
}

}  // namespace

Scenario load_scenario(const std::string& path, const std::vector<Override>& overrides, LoadOptions options) {
  return load_root(load_yaml_file(path), path, overrides, options);
}

Scenario load_scenario_text(const std::string& text, const std::string& origin, const std::vector<Override>& overrides,
                            LoadOptions options) {
  return load_root(load_yaml_string(text, origin), origin, overrides, options);
}

Scenario load_scenario_tree(YAML::Node root, const std::string& origin, const std::vector<Override>& overrides,
                            LoadOptions options) {
  return load_root(std::move(root), origin, overrides, options);
}

bool parse_component_kind(const std::string& name, ComponentKind& kind) {
  for (auto k : {ComponentKind::plant, ComponentKind::sensor, ComponentKind::reference, ComponentKind::estimator,
                 ComponentKind::controller})
    if (name == to_string(k)) {
      kind = k;
      return true;
    }
  return false;
}

void log_warnings(const Scenario& scenario, const std::string& where_details, bool quiet) {
  // On stderr, as every log line: stdout carries `plexus sim --json`.
  auto log = named_logger("scenario");
  for (const auto& w : scenario.warnings) {
    const std::string details = w.detail.empty() ? std::string() : where_details;
    log->log(quiet ? spdlog::level::info : spdlog::level::warn, "{}{}", w.text, details);
    if (!w.detail.empty()) log->info("{}", w.detail);
  }
}

}  // namespace plexus::scenario
