#include "bench/bench_matrix.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "plexus/base/input_error.hpp"
#include "plexus/base/yaml_reader.hpp"
#include "plexus/runtime/qos.hpp"

namespace plexus::cli::bench {
namespace {

const std::vector<std::string> kTransports = {"udp", "shm"};
const std::vector<std::string> kTopologies = {"one_host", "two_ns"};

void check_member(const std::string& v, const std::vector<std::string>& allowed, const std::string& origin) {
  if (std::find(allowed.begin(), allowed.end(), v) != allowed.end()) return;
  std::string list;
  for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
  throw InputError(origin + ": unknown value '" + v + "' (expected " + list + ")");
}

template <class T>
void check_distinct(const std::vector<T>& v, const std::string& origin) {
  for (std::size_t i = 0; i < v.size(); ++i)
    for (std::size_t j = i + 1; j < v.size(); ++j)
      if (v[i] == v[j]) throw InputError(origin + ": an entry is listed twice");
}

std::vector<std::string> strings(const YamlMap& m, const std::string& key) {
  std::vector<std::string> out;
  for (const auto& n : m.sequence(key)) {
    if (!n.IsScalar()) throw InputError(m.where(n) + ": " + m.key_path(key) + ": expected a list of names");
    out.push_back(n.Scalar());
  }
  return out;
}

template <class T>
std::vector<T> numbers(const YamlMap& m, const std::string& key) {
  std::vector<T> out;
  for (const auto& n : m.sequence(key)) {
    try {
      out.push_back(n.as<T>());
    } catch (const YAML::Exception&) {
      throw InputError(m.where(n) + ": " + m.key_path(key) + ": expected a list of numbers");
    }
  }
  return out;
}

}  // namespace

std::string VendorPair::name() const { return std::string(rt::to_string(writer)) + "-" + rt::to_string(reader); }

double Matrix::headline_rate() const {
  for (double r : rates_hz)
    if (r > 0) return r;
  return 0;
}

std::vector<VendorPair> parse_pairs(const std::vector<std::string>& names, const std::string& origin) {
  std::vector<VendorPair> out;
  for (const auto& n : names) {
    const auto dash = n.find('-');
    if (dash == std::string::npos) throw InputError(origin + ": '" + n + "' is not WRITER-READER (e.g. fast-cyclone)");
    out.push_back({rt::parse_vendor(n.substr(0, dash), origin), rt::parse_vendor(n.substr(dash + 1), origin)});
  }
  return out;
}

Matrix preset(const std::string& name) {
  Matrix m;
  m.qos_file = rt::default_qos_file();
  if (name == "quick") {
    m.pairs = parse_pairs({"fast-fast", "cyclone-cyclone"}, "--preset");
    m.transports = {"udp"};
    m.profiles = {"command", "health"};  // a deadline and a liveliness lease: both events measured
    m.sizes = {64, 4096};
    m.rates_hz = {1000};
    m.topologies = {"one_host"};
    m.seconds_per_phase = 0.5;
    m.throughput_seconds = 0.5;
    return m;
  }
  if (name == "full") {
    m.pairs = parse_pairs({"fast-fast", "cyclone-cyclone", "fast-cyclone"}, "--preset");
    m.transports = {"udp", "shm"};
    m.profiles = {"sensor", "latency", "command", "health"};  // health: a liveliness lease
    m.sizes = {64, 4096, 65536, 1048576};
    m.rates_hz = {1000, 100, 0};
    m.topologies = {"one_host", "two_ns"};
    m.seconds_per_phase = 0.5;
    m.throughput_seconds = 0.5;
    return m;
  }
  throw InputError("--preset: unknown value '" + name + "' (expected quick, full)");
}

Matrix load_matrix(const std::string& path, Matrix m, const std::string& out_dir) {
  const YamlMap y(load_yaml_file(path), path);
  if (y.has("pairs")) m.pairs = parse_pairs(strings(y, "pairs"), path + ": pairs");
  if (y.has("transports")) m.transports = strings(y, "transports");
  if (y.has("sizes")) m.sizes = numbers<int>(y, "sizes");
  if (y.has("rates_hz")) m.rates_hz = numbers<double>(y, "rates_hz");
  if (y.has("topologies")) m.topologies = strings(y, "topologies");
  m.loss_percent = y.optional<double>("loss_percent", m.loss_percent);
  m.delay_ms = y.optional<double>("delay_ms", m.delay_ms);
  m.outage_s = y.optional<double>("outage_s", m.outage_s);
  m.seconds_per_phase = y.optional<double>("seconds_per_phase", m.seconds_per_phase);
  m.throughput_seconds = y.optional<double>("throughput_seconds", m.throughput_seconds);
  m.repeats = y.optional<int>("repeats", m.repeats);
  m.vendor_tools = y.optional<bool>("vendor_tools", m.vendor_tools);
  m.pin = y.optional<std::string>("pin", m.pin);
  m.domain = y.optional<int>("domain", m.domain);
  if (y.has("qos_file")) {
    const auto f = y.required<std::string>("qos_file");
    // Relative to the matrix file, as a user writes it next to it.
    m.qos_file = std::filesystem::path(f).is_absolute() ? f : (std::filesystem::path(path).parent_path() / f).string();
  }
  if (y.has("profiles")) {
    // A name, or an inline profile: {name: x, reliability: ..., ...}, written with the
    // named file's profiles into out_dir/qos.yaml so both ends read one file.
    YAML::Node merged = load_yaml_file(m.qos_file);
    bool inline_any = false;
    m.profiles.clear();
    for (const auto& n : y.sequence("profiles")) {
      if (n.IsScalar()) {
        m.profiles.push_back(n.Scalar());
        continue;
      }
      if (!n.IsMap() || !n["name"] || !n["name"].IsScalar())
        throw InputError(y.where(n) + ": profiles: an entry is a profile name or a mapping with a name");
      const std::string name = n["name"].Scalar();
      YAML::Node body = YAML::Clone(n);
      body.remove("name");
      merged["profiles"][name] = body;
      m.profiles.push_back(name);
      inline_any = true;
    }
    if (inline_any) {
      const std::string file = out_dir + "/qos.yaml";
      std::ofstream(file) << "# The named profiles of " << m.qos_file << " and the inline ones of " << path << "\n"
                          << YAML::Dump(merged) << "\n";
      m.qos_file = file;
    }
  }
  y.reject_unknown();
  validate(m, path);
  return m;
}

void validate(const Matrix& m, const std::string& origin) {
  auto need = [&](bool ok, const std::string& key, const std::string& what) {
    if (!ok) throw InputError(origin + ": " + key + ": " + what);
  };
  need(!m.pairs.empty(), "pairs", "at least one vendor pair");
  need(!m.transports.empty(), "transports", "at least one transport");
  need(!m.profiles.empty(), "profiles", "at least one QoS profile");
  need(!m.sizes.empty(), "sizes", "at least one payload size");
  need(!m.rates_hz.empty(), "rates_hz", "at least one rate");
  need(!m.topologies.empty(), "topologies", "at least one topology");
  for (const auto& t : m.transports) check_member(t, kTransports, origin + ": transports");
  for (const auto& t : m.topologies) check_member(t, kTopologies, origin + ": topologies");
  check_member(m.pin, {"split", "same", "none"}, origin + ": pin");
  for (int s : m.sizes) need(s >= 0 && s <= (1 << 20), "sizes", "each must be in 0..1048576 bytes");
  for (double r : m.rates_hz) need(r >= 0 && r <= 100000, "rates_hz", "each must be in 0..100000 Hz (0: unpaced)");
  std::vector<std::string> pair_names;
  for (const auto& p : m.pairs) pair_names.push_back(p.name());
  check_distinct(pair_names, origin + ": pairs");
  check_distinct(m.transports, origin + ": transports");
  check_distinct(m.profiles, origin + ": profiles");
  check_distinct(m.sizes, origin + ": sizes");
  check_distinct(m.rates_hz, origin + ": rates_hz");
  check_distinct(m.topologies, origin + ": topologies");
  need(m.loss_percent >= 0 && m.loss_percent <= 50, "loss_percent", "must be in 0..50");
  need(m.delay_ms >= 0 && m.delay_ms <= 1000, "delay_ms", "must be in 0..1000 ms");
  need(m.outage_s >= 0.01 && m.outage_s <= 5, "outage_s", "must be in 0.01..5 s");
  need(m.seconds_per_phase >= 0.1 && m.seconds_per_phase <= 30, "seconds_per_phase", "must be in 0.1..30 s");
  need(m.throughput_seconds >= 0 && m.throughput_seconds <= 30, "throughput_seconds", "must be in 0..30 s");
  need(m.repeats >= 1 && m.repeats <= 10, "repeats", "must be in 1..10");
  need(m.domain >= 0 && m.domain <= 232, "domain", "must be in 0..232");
  const auto profiles = rt::QosProfiles::load(m.qos_file);
  for (const auto& p : m.profiles) profiles.get(p);  // InputError naming the file and the known ones
}

}  // namespace plexus::cli::bench
