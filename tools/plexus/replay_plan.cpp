#include "replay_plan.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "plexus/base/input_error.hpp"
#include "plexus/runtime/discovery.hpp"

namespace plexus::cli {
namespace {

/// The recorded QoS JSON (qos_to_json in topic_discovery.cpp), read strictly: every key
/// optional (a vendor may not announce it), every present one of the written type and values.
class RecordedQosReader {
 public:
  RecordedQosReader(const nlohmann::json& j, std::string where) : j_(j), where_(std::move(where)) {}

  template <class E, std::size_t N>
  E choice(const char* key, E fallback, const std::pair<const char*, E> (&names)[N]) const {
    if (!j_.contains(key)) return fallback;
    const auto& v = j_.at(key);
    if (v.is_string())
      for (const auto& [n, e] : names)
        if (v.get_ref<const std::string&>() == n) return e;
    std::string expected;
    for (const auto& [n, e] : names) expected += (expected.empty() ? "" : ", ") + std::string(n);
    fail(key,
         "expected one of " + expected + ", got " + v.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
  }

  double seconds(const char* key) const {
    if (!j_.contains(key)) return 0.0;
    const auto& v = j_.at(key);
    if (!v.is_number()) fail(key, "expected a number of seconds, got " + short_dump(v));
    const double s = v.get<double>();
    if (!(s == 0.0 || (s >= 1e-9 && s <= 1e9)))
      fail(key, "must be 0 (none) or within [1e-9, 1e9] s, got " + short_dump(v));
    return s;
  }

  /// An int32 (a JSON integer; anything else, a fraction or out of range, is refused).
  int32_t integer(const char* key, int32_t fallback) const {
    if (!j_.contains(key)) return fallback;
    const auto& v = j_.at(key);
    if (v.is_number_unsigned() && v.get<uint64_t>() <= static_cast<uint64_t>(std::numeric_limits<int32_t>::max()))
      return static_cast<int32_t>(v.get<uint64_t>());
    if (v.is_number_integer() && !v.is_number_unsigned() && v.get<int64_t>() >= std::numeric_limits<int32_t>::min() &&
        v.get<int64_t>() <= std::numeric_limits<int32_t>::max())
      return static_cast<int32_t>(v.get<int64_t>());
    fail(key, "expected a 32-bit integer, got " + short_dump(v));
  }

  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    throw InputError(where_ + ": " + key + ": " + what +
                     " (replay with --profile PROFILE to publish with a profile instead)");
  }

 private:
  static std::string short_dump(const nlohmann::json& v) {
    std::string s = v.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    if (s.size() > 40) s = s.substr(0, 40) + "...";
    return s;
  }

  const nlohmann::json& j_;
  std::string where_;
};

}  // namespace

rt::QosProfile recorded_qos(const RecordedTopic& topic, const std::string& file, int32_t depth) {
  using Q = rt::QosProfile;
  if (topic.qos_json.empty()) {  // not discovered when it was recorded
    Q q = rt::writer_qos_like(rt::EndpointQos{}, depth);
    q.reliability = Q::Reliability::reliable;
    return q;
  }
  const std::string where = file + ": topic '" + topic.name + "': recorded QoS";
  const nlohmann::json j = nlohmann::json::parse(topic.qos_json, nullptr, false);
  if (j.is_discarded() || !j.is_object()) throw InputError(where + ": not a JSON object");
  const RecordedQosReader r(j, where);
  rt::EndpointQos e;
  e.reliability = r.choice(
      "reliability", Q::Reliability::best_effort,
      {std::pair{"reliable", Q::Reliability::reliable}, std::pair{"best_effort", Q::Reliability::best_effort}});
  enum class D { volatile_, transient_local, transient };
  const D d = r.choice("durability", D::volatile_,
                       {std::pair{"volatile", D::volatile_}, std::pair{"transient_local", D::transient_local},
                        std::pair{"transient", D::transient}});
  e.durability = d == D::volatile_ ? Q::Durability::volatile_ : Q::Durability::transient_local;
  e.durability_stronger = d == D::transient;
  if (j.contains("history")) {
    e.history_known = true;
    e.history = r.choice("history", Q::History::keep_last,
                         {std::pair{"keep_last", Q::History::keep_last}, std::pair{"keep_all", Q::History::keep_all}});
    e.depth = r.integer("depth", 1);
    // keep_all: the depth is whatever the vendor reported, and unused.
    if (e.history == Q::History::keep_last && (e.depth < 1 || e.depth > 100000))
      r.fail("depth", "a keep_last depth must be in 1..100000, got " + std::to_string(e.depth));
  }
  e.deadline_s = r.seconds("deadline_s");
  e.liveliness = r.choice("liveliness", Q::Liveliness::automatic,
                          {std::pair{"automatic", Q::Liveliness::automatic},
                           std::pair{"manual_by_participant", Q::Liveliness::manual_by_participant},
                           std::pair{"manual_by_topic", Q::Liveliness::manual_by_topic}});
  e.liveliness_lease_s = r.seconds("liveliness_lease_s");
  e.lifespan_s = r.seconds("lifespan_s");
  e.latency_budget_s = r.seconds("latency_budget_s");
  return rt::writer_qos_like(e, depth);
}

std::vector<ReplayTopic> plan_replay_topics(const RecordingReader& rec, const std::string& file,
                                            const std::vector<std::string>& wanted, const rt::QosProfile* fixed,
                                            bool restamp) {
  for (const auto& w : wanted)
    if (std::none_of(rec.topics().begin(), rec.topics().end(), [&](const RecordedTopic& t) { return t.name == w; }))
      throw InputError("--topics: topic '" + w + "' is not in " + file);
  std::vector<ReplayTopic> out;
  for (const auto& t : rec.topics()) {
    if (!wanted.empty() && std::find(wanted.begin(), wanted.end(), t.name) == wanted.end()) continue;
    ReplayTopic r;
    r.topic = t;
    r.ts = msg::find_type_support(t.type);
    if (!r.ts) throw InputError(file + ": topic '" + t.name + "' has type '" + t.type + "', unknown to this build");
    // A live stand-in (--restamp) keeps the recorded writer's history when discovery told
    // it, else newest-wins (keep_last 1) as every plexus realtime topic; a plain replay
    // keeps up to 64 samples for slow readers.
    r.qos = fixed ? *fixed : recorded_qos(t, file, restamp ? 1 : 64);
    out.push_back(std::move(r));
  }
  return out;
}

std::vector<TopicSummary> summarize_recording(const RecordingReader& rec) {
  std::vector<TopicSummary> out;
  std::map<int64_t, std::size_t> index;
  for (const auto& t : rec.topics()) {
    index[t.id] = out.size();
    out.push_back({&t});
  }
  rec.for_each([&](const RecordedMessage& m) {
    auto& a = out[index.at(m.topic_id)];
    if (a.count++ == 0) a.first_ns = m.receive_time_ns;
    a.last_ns = m.receive_time_ns;
    for (unsigned char b : m.cdr) a.digest = (a.digest ^ b) * 1099511628211ull;  // FNV-1a over the CDR bytes
    return true;
  });
  return out;
}

int64_t replay_due_ns(int64_t receive_ns, int64_t first_ns, double rate_scale) {
  const double due = static_cast<double>(receive_ns - first_ns) / rate_scale;
  // 2^63 is exactly a double; anything at or beyond it does not fit an int64.
  if (!(due < 9223372036854775808.0)) return std::numeric_limits<int64_t>::max();
  return due > 0 ? static_cast<int64_t>(due) : 0;
}

bool shift_time(int64_t t, int64_t shift, int64_t& out) {
  int64_t r = 0;
  if (__builtin_add_overflow(t, shift, &r)) return false;
  out = r;
  return true;
}

}  // namespace plexus::cli
