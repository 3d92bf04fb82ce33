#include "plexus/runtime/qos.hpp"

#include <dlfcn.h>

#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include "plexus/base/input_error.hpp"
#include "plexus/base/yaml_reader.hpp"

namespace plexus::rt {
namespace {

template <class E, std::size_t N>
E parse_enum(const YamlMap& m, const std::string& key, E fallback, const std::pair<const char*, E> (&names)[N]) {
  if (!m.has(key)) {
    m.node(key);
    return fallback;
  }
  const auto text = m.required<std::string>(key);
  std::string expected;
  for (const auto& [n, v] : names) {
    if (text == n) return v;
    expected += (expected.empty() ? "" : ", ") + std::string(n);
  }
  m.fail(key, "unknown value '" + text + "' (expected " + expected + ")");
}

// Both vendors must hold the value as it is: Fast DDS keeps whole seconds in an int32 (a
// larger value would be an undefined conversion), Cyclone DDS nanoseconds in an int64, and a
// value below 1 ns would become 0, which means something else. 1e9 s is 31 years.
double duration(const YamlMap& m, const std::string& key, double fallback) {
  const double v = m.optional<double>(key, fallback);
  if (v < 0) m.fail(key, "must be >= 0 seconds (0 means infinite/none), got " + std::to_string(v));
  if (v != 0.0 && (v < 1e-9 || v > 1e9)) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    m.fail(key, std::string("must be 0 (infinite/none) or within [1e-9, 1e9] seconds, got ") + text);
  }
  return v;
}

QosProfile parse_profile(const YamlMap& m, const std::string& name) {
  QosProfile p;
  p.name = name;
  p.reliability = parse_enum(m, "reliability", p.reliability,
                             {std::pair{"best_effort", QosProfile::Reliability::best_effort},
                              std::pair{"reliable", QosProfile::Reliability::reliable}});
  p.max_blocking_time_s = duration(m, "max_blocking_time_s", p.max_blocking_time_s);
  p.durability = parse_enum(m, "durability", p.durability,
                            {std::pair{"volatile", QosProfile::Durability::volatile_},
                             std::pair{"transient_local", QosProfile::Durability::transient_local}});
  p.history = parse_enum(
      m, "history", p.history,
      {std::pair{"keep_last", QosProfile::History::keep_last}, std::pair{"keep_all", QosProfile::History::keep_all}});
  p.depth = m.optional<int32_t>("depth", p.depth);
  if (p.depth < 1 || p.depth > 100000) m.fail("depth", "must be in 1..100000, got " + std::to_string(p.depth));
  p.deadline_s = duration(m, "deadline_s", p.deadline_s);
  p.liveliness = parse_enum(m, "liveliness", p.liveliness,
                            {std::pair{"automatic", QosProfile::Liveliness::automatic},
                             std::pair{"manual_by_participant", QosProfile::Liveliness::manual_by_participant},
                             std::pair{"manual_by_topic", QosProfile::Liveliness::manual_by_topic}});
  p.liveliness_lease_s = duration(m, "liveliness_lease_s", p.liveliness_lease_s);
  p.lifespan_s = duration(m, "lifespan_s", p.lifespan_s);
  p.latency_budget_s = duration(m, "latency_budget_s", p.latency_budget_s);
  m.reject_unknown();
  return p;
}

}  // namespace

const char* to_string(QosProfile::Reliability v) {
  return v == QosProfile::Reliability::reliable ? "reliable" : "best_effort";
}
const char* to_string(QosProfile::Durability v) {
  return v == QosProfile::Durability::transient_local ? "transient_local" : "volatile";
}
const char* to_string(QosProfile::History v) { return v == QosProfile::History::keep_all ? "keep_all" : "keep_last"; }
const char* to_string(QosProfile::Liveliness v) {
  switch (v) {
    case QosProfile::Liveliness::automatic: return "automatic";
    case QosProfile::Liveliness::manual_by_participant: return "manual_by_participant";
    case QosProfile::Liveliness::manual_by_topic: return "manual_by_topic";
  }
  return "?";
}

QosProfiles QosProfiles::from_node(const YAML::Node& doc, const std::string& origin) {
  YamlMap root(doc, origin);
  QosProfiles out;
  out.origin_ = origin;
  YamlMap profiles = root.map("profiles");
  for (const auto& name : profiles.keys()) out.profiles_[name] = parse_profile(profiles.map(name), name);
  if (out.profiles_.empty()) root.fail("profiles", "defines no profile");
  root.reject_unknown();
  return out;
}

QosProfiles QosProfiles::parse(const std::string& yaml_text, const std::string& origin) {
  return from_node(load_yaml_string(yaml_text, origin), origin);
}

QosProfiles QosProfiles::load(const std::string& path) { return from_node(load_yaml_file(path), path); }

const QosProfile& QosProfiles::get(const std::string& name) const {
  auto it = profiles_.find(name);
  if (it == profiles_.end()) {
    std::string known;
    for (const auto& [n, p] : profiles_) known += (known.empty() ? "" : ", ") + n;
    throw InputError(origin_ + ": unknown QoS profile '" + name + "' (known: " + known + ")");
  }
  return it->second;
}

std::string describe(const QosProfile& q) {
  std::string s = "profile " + q.name + ": " + to_string(q.reliability) + ", " + to_string(q.durability) + ", " +
                  to_string(q.history);
  if (q.history == QosProfile::History::keep_last) s += " " + std::to_string(q.depth);
  if (q.deadline_s > 0) s += ", deadline " + std::to_string(q.deadline_s) + " s";
  if (q.liveliness_lease_s > 0)
    s += ", " + std::string(to_string(q.liveliness)) + " lease " + std::to_string(q.liveliness_lease_s) + " s";
  return s;
}

std::string default_qos_file() {
  if (const char* env = std::getenv("PLEXUS_QOS_FILE"); env && *env) return env;
  namespace fs = std::filesystem;
  std::error_code ec;
  // Beside this library, which a user's program built against an installed plexus shares with
  // plexus's own: the build tree's deploy/ (build/lib/), or the install prefix's share/plexus.
  std::vector<fs::path> candidates;
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&default_qos_file), &info) && info.dli_fname) {
    const fs::path lib = fs::absolute(info.dli_fname, ec).parent_path();
    candidates.push_back(lib / "../../deploy/qos.yaml");
    candidates.push_back(lib / PLEXUS_SHARE_FROM_LIB / "qos.yaml");
  }
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    candidates.push_back(exe.parent_path() / "../../deploy/qos.yaml");
    candidates.push_back(exe.parent_path() / "../share/plexus/qos.yaml");
  }
  for (const fs::path& candidate : candidates)
    if (fs::exists(candidate, ec)) return fs::weakly_canonical(candidate, ec).string();
  return "deploy/qos.yaml";
}

}  // namespace plexus::rt
