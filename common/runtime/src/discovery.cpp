#include "plexus/runtime/discovery.hpp"

#include <algorithm>
#include <cstdio>

namespace plexus::rt {
namespace {

std::string seconds(double s) {
  if (s <= 0) return "inf";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%gs", s);
  return buf;
}

std::string durability_text(const EndpointQos& q) {
  if (q.durability_stronger) return "transient+";
  return to_string(q.durability);
}

std::string repr_text(const std::vector<int>& r) {
  if (r.empty()) return "XCDR1 (default)";
  std::string s;
  for (int v : r) s += (s.empty() ? "" : "|") + std::string(v == 0 ? "XCDR1" : v == 1 ? "XML" : v == 2 ? "XCDR2" : "?");
  return s;
}

int durability_rank(const EndpointQos& q) {
  if (q.durability_stronger) return 2;
  return q.durability == QosProfile::Durability::transient_local ? 1 : 0;
}

// "infinite" (0) is the largest duration.
bool longer(double a, double b) {  // a > b
  if (a <= 0) return b > 0;
  if (b <= 0) return false;
  return a > b + 1e-12;
}

}  // namespace

std::optional<QosMismatch> check_compatible(const EndpointQos& w, const EndpointQos& r) {
  if (w.reliability == QosProfile::Reliability::best_effort && r.reliability == QosProfile::Reliability::reliable)
    return QosMismatch{"RELIABILITY", to_string(w.reliability), to_string(r.reliability)};
  if (durability_rank(w) < durability_rank(r)) return QosMismatch{"DURABILITY", durability_text(w), durability_text(r)};
  if (longer(w.deadline_s, r.deadline_s)) return QosMismatch{"DEADLINE", seconds(w.deadline_s), seconds(r.deadline_s)};
  if (static_cast<int>(w.liveliness) < static_cast<int>(r.liveliness) ||
      longer(w.liveliness_lease_s, r.liveliness_lease_s))
    return QosMismatch{"LIVELINESS", std::string(to_string(w.liveliness)) + " lease " + seconds(w.liveliness_lease_s),
                       std::string(to_string(r.liveliness)) + " lease " + seconds(r.liveliness_lease_s)};
  if (w.exclusive_ownership != r.exclusive_ownership)
    return QosMismatch{"OWNERSHIP", w.exclusive_ownership ? "exclusive" : "shared",
                       r.exclusive_ownership ? "exclusive" : "shared"};
  if (w.latency_budget_s > r.latency_budget_s + 1e-12)
    return QosMismatch{"LATENCYBUDGET", seconds(w.latency_budget_s),
                       r.latency_budget_s > 0 ? seconds(r.latency_budget_s) : "0"};
  const int offered = w.data_representation.empty() ? 0 : w.data_representation.front();
  bool accepted = r.data_representation.empty() ? offered == 0 : false;
  for (int v : r.data_representation) accepted = accepted || v == offered;
  if (!accepted)
    return QosMismatch{"DATA_REPRESENTATION", repr_text(w.data_representation), repr_text(r.data_representation)};
  return std::nullopt;
}

std::string describe(const EndpointQos& q) {
  std::string s = std::string(to_string(q.reliability)) + ", " + durability_text(q);
  if (q.history_known)
    s += q.history == QosProfile::History::keep_all ? ", keep_all" : ", keep_last " + std::to_string(q.depth);
  else
    s += ", history n/a";
  s += ", deadline " + seconds(q.deadline_s);
  s += ", liveliness " + std::string(to_string(q.liveliness)) + " lease " + seconds(q.liveliness_lease_s);
  s += ", lifespan " + seconds(q.lifespan_s);
  s += ", latency_budget " + (q.latency_budget_s > 0 ? seconds(q.latency_budget_s) : std::string("0"));
  s += ", ownership " + std::string(q.exclusive_ownership ? "exclusive" : "shared");
  s += ", representation " + repr_text(q.data_representation);
  return s;
}

QosProfile reader_qos_matching(const std::vector<EndpointQos>& writers, int32_t depth) {
  QosProfile p;
  p.name = "auto";
  bool all_reliable = !writers.empty(), all_latched = !writers.empty();
  for (const auto& w : writers) {
    all_reliable = all_reliable && w.reliability == QosProfile::Reliability::reliable;
    all_latched = all_latched && durability_rank(w) >= 1;
  }
  p.reliability = all_reliable ? QosProfile::Reliability::reliable : QosProfile::Reliability::best_effort;
  p.durability = all_latched ? QosProfile::Durability::transient_local : QosProfile::Durability::volatile_;
  p.history = QosProfile::History::keep_last;
  p.depth = depth;
  return p;
}

QosProfile writer_qos_like(const EndpointQos& q, int32_t depth) {
  QosProfile p;
  p.name = "recorded";
  p.reliability = q.reliability;
  p.durability = durability_rank(q) >= 1 ? QosProfile::Durability::transient_local : QosProfile::Durability::volatile_;
  p.history = q.history_known ? q.history : QosProfile::History::keep_last;
  p.depth = q.history_known && q.history == QosProfile::History::keep_last ? std::max(q.depth, depth) : depth;
  p.deadline_s = q.deadline_s;
  p.liveliness = q.liveliness;
  p.liveliness_lease_s = q.liveliness_lease_s;
  p.lifespan_s = q.lifespan_s;
  p.latency_budget_s = q.latency_budget_s;
  return p;
}

}  // namespace plexus::rt
