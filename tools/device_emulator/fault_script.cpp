#include "fault_script.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>

#include "plexus/base/clock.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/base/yaml_reader.hpp"
#include "plexus/link/frame.hpp"

namespace plexus::emulator {
namespace {

constexpr std::size_t kMaxFaultBytes = 16384;  // garbage, oversize: a quarter of the TX ring
constexpr int64_t kMaxCount = 1'000'000;
constexpr double kMaxFor = 86400.0;

struct KindInfo {
  FaultKind kind;
  const char* name;
  const char* key;  // its one parameter
};
constexpr KindInfo kKinds[] = {
    {FaultKind::flip, "flip", "count"},       {FaultKind::drop, "drop", "bytes"},
    {FaultKind::garbage, "garbage", "bytes"}, {FaultKind::oversize, "oversize", "bytes"},
    {FaultKind::poison, "poison", "count"},   {FaultKind::stall, "stall", "for"},
    {FaultKind::unplug, "unplug", "for"},
};

const KindInfo& info(FaultKind k) {
  for (const auto& i : kKinds)
    if (i.kind == k) return i;
  return kKinds[0];
}

Fault make_fault(const std::string& kind, const std::string& where) {
  Fault f;
  for (const auto& i : kKinds)
    if (kind == i.name) {
      f.kind = i.kind;
      switch (i.kind) {
        case FaultKind::drop: f.bytes = 5; break;
        case FaultKind::garbage: f.bytes = 64; break;
        case FaultKind::oversize: f.bytes = 3 * link::kMaxEncodedFrame; break;
        default: break;
      }
      return f;
    }
  throw InputError(where + ": unknown fault kind '" + kind +
                   "' (expected flip, drop, garbage, oversize, poison, stall or unplug)");
}

bool parse_double(const std::string& s, double& v) {
  if (s.empty()) return false;
  errno = 0;
  char* end = nullptr;
  v = std::strtod(s.c_str(), &end);
  return errno == 0 && end == s.c_str() + s.size() && std::isfinite(v);
}

bool parse_int(const std::string& s, int64_t lo, int64_t hi, int64_t& v) {
  if (s.empty() || s.find_first_not_of("0123456789") != std::string::npos || s.size() > 12) return false;
  v = std::stoll(s);
  return v >= lo && v <= hi;
}

double parse_time(const std::string& s, const std::string& where) {
  double t = 0.0;
  if (!parse_double(s, t) || t < 0.0) throw InputError(where + ": expected a time in seconds >= 0, got '" + s + "'");
  return t;
}

/// Sets the kind's one parameter from text; `where` names it in errors.
void set_param(Fault& f, const std::string& key, const std::string& value, const std::string& where) {
  const KindInfo& i = info(f.kind);
  if (key != i.key)
    throw InputError(where + ": " + i.name + " has no parameter '" + key + "' (it takes " + i.key + "=...)");
  int64_t n = 0;
  switch (f.kind) {
    case FaultKind::flip:
    case FaultKind::poison:
      if (!parse_int(value, 1, kMaxCount, n))
        throw InputError(where + ": expected a frame count 1 .. " + std::to_string(kMaxCount) + ", got '" + value +
                         "'");
      f.count = n;
      break;
    case FaultKind::drop:
      if (!parse_int(value, 1, static_cast<int64_t>(link::kMaxEncodedFrame), n))
        throw InputError(where + ": expected bytes 1 .. " + std::to_string(link::kMaxEncodedFrame) + ", got '" + value +
                         "'");
      f.bytes = static_cast<std::size_t>(n);
      break;
    case FaultKind::garbage:
      if (!parse_int(value, 1, kMaxFaultBytes, n))
        throw InputError(where + ": expected bytes 1 .. " + std::to_string(kMaxFaultBytes) + ", got '" + value + "'");
      f.bytes = static_cast<std::size_t>(n);
      break;
    case FaultKind::oversize:
      if (!parse_int(value, static_cast<int64_t>(link::kMaxEncodedFrame), kMaxFaultBytes, n))
        throw InputError(where + ": expected bytes " + std::to_string(link::kMaxEncodedFrame) + " .. " +
                         std::to_string(kMaxFaultBytes) +
                         " (an oversize frame is longer than kMaxEncodedFrame), got '" + value + "'");
      f.bytes = static_cast<std::size_t>(n);
      break;
    case FaultKind::stall:
    case FaultKind::unplug: {
      double s = 0.0;
      if (!parse_double(value, s) || s <= 0.0 || s > kMaxFor)
        throw InputError(where + ": expected seconds > 0 (at most a day), got '" + value + "'");
      f.for_s = s;
      break;
    }
  }
}

void check_complete(const Fault& f, bool have_for, const std::string& where) {
  if ((f.kind == FaultKind::stall || f.kind == FaultKind::unplug) && !have_for)
    throw InputError(where + ": " + info(f.kind).name + " needs for=S (how long, in seconds)");
}

}  // namespace

const char* to_string(FaultKind kind) { return info(kind).name; }

Fault parse_fault_spec(const std::string& spec) {
  const std::string where = "--fault " + spec;
  const auto at = spec.find('@');
  if (at == std::string::npos)
    throw InputError(where + ": expected KIND@T or KIND@T:key=value,... (T: seconds since the start)");
  Fault f = make_fault(spec.substr(0, at), where);
  const auto colon = spec.find(':', at);
  f.at = parse_time(spec.substr(at + 1, colon == std::string::npos ? std::string::npos : colon - at - 1), where);
  bool have_for = false;
  if (colon != std::string::npos) {
    const std::string params = spec.substr(colon + 1);
    if (params.empty()) throw InputError(where + ": expected key=value after ':'");
    std::size_t pos = 0;
    while (pos <= params.size()) {
      const auto comma = params.find(',', pos);
      const std::string item = params.substr(pos, comma == std::string::npos ? std::string::npos : comma - pos);
      const auto eq = item.find('=');
      if (eq == std::string::npos || eq == 0) throw InputError(where + ": expected key=value, got '" + item + "'");
      const std::string key = item.substr(0, eq);
      set_param(f, key, item.substr(eq + 1), where + ": " + key);
      have_for = have_for || key == "for";
      if (comma == std::string::npos) break;
      pos = comma + 1;
    }
  }
  check_complete(f, have_for, where);
  f.origin = where;
  return f;
}

std::vector<Fault> load_fault_file(const std::string& path) {
  const YAML::Node root = load_yaml_file(path);
  if (!root.IsSequence()) throw InputError(path + ": expected a list of faults (- {kind: flip, at: 1.0, count: 3})");
  std::vector<Fault> out;
  for (std::size_t i = 0; i < root.size(); ++i) {
    const YAML::Node n = root[i];
    const std::string item = "[" + std::to_string(i) + "]";
    if (!n.IsMap())
      throw InputError(path + ":" + std::to_string(n.Mark().line + 1) + ": " + item +
                       ": expected a map with kind, at and the kind's parameter");
    const YamlMap m(n, path, item);
    const std::string kind = m.required<std::string>("kind");
    Fault f = make_fault(kind, m.where(m.node("kind")) + ": " + m.key_path("kind"));
    f.at = m.required<double>("at");
    if (f.at < 0.0) m.fail("at", "expected a time in seconds >= 0");
    const char* key = info(f.kind).key;
    const bool have = m.has(key);
    if (have) set_param(f, key, m.required<std::string>(key), m.where(m.node(key)) + ": " + m.key_path(key));
    m.reject_unknown();
    check_complete(f, have, m.where() + ": " + item);
    f.origin = m.where();
    out.push_back(std::move(f));
  }
  return out;
}

FaultInjector::FaultInjector(std::vector<Fault> faults, uint64_t seed) : faults_(std::move(faults)), rng_(seed) {
  std::stable_sort(faults_.begin(), faults_.end(), [](const Fault& a, const Fault& b) { return a.at < b.at; });
  waiting_.reserve(faults_.size());
  std::size_t most = 0;
  for (const auto& f : faults_)
    if (f.kind == FaultKind::garbage || f.kind == FaultKind::oversize) most = std::max(most, f.bytes + 1);
  scratch_.resize(most);
}

void FaultInjector::tick(double t, EmulatorLink& link) {
  while (next_ < faults_.size() && faults_[next_].at <= t) start(faults_[next_++], t, link);
  if (stalled_ && t >= stall_until_) {
    stalled_ = false;
    for (auto& f : faults_)
      if (f.kind == FaultKind::stall && f.started) f.applied = true;
  }
  if (unplugged_ && t >= replug_at_ && t >= next_retry_) {
    if (link.reopen()) {
      unplugged_ = false;
      for (auto& f : faults_)
        if (f.kind == FaultKind::unplug && f.started) f.applied = true;
      uint64_t held = 0;
      if (log_limit_.allow(monotonic_ns(), held)) spdlog::info("fault: plugged in again: {}", link.describe());
    } else {
      next_retry_ = t + 0.1;
    }
  }
  if (!sending(link)) return;
  for (std::size_t i = 0; i < waiting_.size();) {
    Fault& f = faults_[waiting_[i]];
    if ((f.kind == FaultKind::garbage || f.kind == FaultKind::oversize) && send_bytes(f, link))
      waiting_.erase(waiting_.begin() + static_cast<std::ptrdiff_t>(i));
    else
      ++i;
  }
}

void FaultInjector::start(Fault& f, double t, EmulatorLink& link) {
  f.started = true;
  f.started_at = std::round(t * 1e6) / 1e6;  // to the microsecond: 0.1, not 0.09999999999999999
  uint64_t held = 0;
  if (log_limit_.allow(monotonic_ns(), held)) {
    if (held > 0)
      spdlog::info("fault: {} at {:.3f} s ({} fault lines held back)", f.origin, t, held);
    else
      spdlog::info("fault: {} at {:.3f} s", f.origin, t);
  }
  switch (f.kind) {
    case FaultKind::flip:
    case FaultKind::drop:
    case FaultKind::poison: waiting_.push_back(static_cast<std::size_t>(&f - faults_.data())); break;
    case FaultKind::garbage:
    case FaultKind::oversize:
      // While stalled or unplugged nothing goes out: the bytes wait for the link.
      if (!sending(link) || !send_bytes(f, link)) waiting_.push_back(static_cast<std::size_t>(&f - faults_.data()));
      break;
    case FaultKind::stall:
      stalled_ = true;
      stall_until_ = std::max(stall_until_, t + f.for_s);
      break;
    case FaultKind::unplug:
      link.close();
      unplugged_ = true;
      replug_at_ = std::max(replug_at_, t + f.for_s);
      next_retry_ = 0.0;
      break;
  }
}

bool FaultInjector::send_bytes(Fault& f, EmulatorLink& link) {
  const std::size_t n = f.kind == FaultKind::oversize ? f.bytes + 1 : f.bytes;
  if (!link.room_for(n)) return false;  // tried again at the next tick
  for (std::size_t i = 0; i < f.bytes; ++i) {
    const auto r = static_cast<uint8_t>(rng_() & 0xFF);
    scratch_[i] = f.kind == FaultKind::oversize ? static_cast<uint8_t>(1 + r % 255) : r;
  }
  if (f.kind == FaultKind::oversize) scratch_[f.bytes] = 0;
  link.queue(scratch_.data(), n, false);
  f.applied = true;
  return true;
}

Fault* FaultInjector::active(FaultKind kind) {
  for (std::size_t i : waiting_)
    if (faults_[i].kind == kind) return &faults_[i];
  return nullptr;
}

void FaultInjector::finish_frame(Fault& f) {
  ++f.frames;
  const int64_t needed = f.kind == FaultKind::drop ? 1 : f.count;
  if (f.frames < needed) return;
  f.applied = true;
  const auto idx = static_cast<std::size_t>(&f - faults_.data());
  waiting_.erase(std::find(waiting_.begin(), waiting_.end(), idx));
}

void FaultInjector::on_payload(uint8_t* payload, std::size_t n) {
  if (waiting_.empty() || n < 8) return;
  Fault* p = active(FaultKind::poison);
  if (!p) return;
  // Frames 1, 3, 5, ... of the fault: NaN; frames 2, 4, ...: 1e300 (finite, absurd).
  link::put_f64_le(payload, p->frames % 2 == 0 ? std::numeric_limits<double>::quiet_NaN() : 1e300);
  finish_frame(*p);
}

std::size_t FaultInjector::on_encoded(uint8_t* frame, std::size_t n) {
  if (waiting_.empty() || n < 2) return n;
  const std::size_t body = n - 1;  // the delimiter stays: the damage is inside one frame
  if (Fault* f = active(FaultKind::flip)) {
    const std::size_t byte = static_cast<std::size_t>(rng_() % body);
    frame[byte] = static_cast<uint8_t>(frame[byte] ^ (1u << (rng_() % 8)));
    finish_frame(*f);
  }
  if (Fault* d = active(FaultKind::drop)) {
    const std::size_t k = std::min(d->bytes, body - 1);  // at least one byte stays before the delimiter
    const std::size_t from = (body - k) / 2;
    std::memmove(frame + from, frame + from + k, n - from - k);
    n -= k;
    finish_frame(*d);
  }
  return n;
}

nlohmann::ordered_json FaultInjector::summary() const {
  auto list = nlohmann::ordered_json::array();
  for (const auto& f : faults_) {
    nlohmann::ordered_json j{{"kind", to_string(f.kind)}, {"at", f.at}, {"applied", f.applied}};
    switch (f.kind) {
      case FaultKind::flip:
      case FaultKind::poison: j["count"] = f.count; break;
      case FaultKind::drop:
      case FaultKind::garbage:
      case FaultKind::oversize: j["bytes"] = f.bytes; break;
      case FaultKind::stall:
      case FaultKind::unplug: j["for"] = f.for_s; break;
    }
    if (f.kind == FaultKind::flip || f.kind == FaultKind::poison || f.kind == FaultKind::drop) j["frames"] = f.frames;
    j["started_at"] = f.started ? nlohmann::ordered_json(f.started_at) : nlohmann::ordered_json(nullptr);
    list.push_back(std::move(j));
  }
  return list;
}

}  // namespace plexus::emulator
