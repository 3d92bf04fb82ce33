// CycloneParticipant::dds_endpoints: the built-in DCPSPublication / DCPSSubscription
// topics (local endpoints included), with each endpoint's QoS as it was discovered.
#include <cstring>
#include <vector>

#include "cyclone_participant.hpp"

namespace plexus::rt {
namespace {

double seconds(dds_duration_t d) { return d == DDS_INFINITY ? 0.0 : static_cast<double>(d) * 1e-9; }

EndpointQos endpoint_qos(const dds_qos_t* q) {
  EndpointQos e;
  if (!q) return e;
  dds_reliability_kind_t rk;
  dds_duration_t blocking;
  if (dds_qget_reliability(q, &rk, &blocking))
    e.reliability =
        rk == DDS_RELIABILITY_RELIABLE ? QosProfile::Reliability::reliable : QosProfile::Reliability::best_effort;
  dds_durability_kind_t dk;
  if (dds_qget_durability(q, &dk)) {
    e.durability =
        dk == DDS_DURABILITY_VOLATILE ? QosProfile::Durability::volatile_ : QosProfile::Durability::transient_local;
    e.durability_stronger = dk == DDS_DURABILITY_TRANSIENT || dk == DDS_DURABILITY_PERSISTENT;
  }
  dds_history_kind_t hk;
  int32_t depth = 0;
  if (dds_qget_history(q, &hk, &depth)) {
    e.history_known = true;
    e.history = hk == DDS_HISTORY_KEEP_ALL ? QosProfile::History::keep_all : QosProfile::History::keep_last;
    e.depth = depth;
  }
  dds_duration_t d;
  if (dds_qget_deadline(q, &d)) e.deadline_s = seconds(d);
  dds_liveliness_kind_t lk;
  if (dds_qget_liveliness(q, &lk, &d)) {
    e.liveliness = lk == DDS_LIVELINESS_AUTOMATIC               ? QosProfile::Liveliness::automatic
                   : lk == DDS_LIVELINESS_MANUAL_BY_PARTICIPANT ? QosProfile::Liveliness::manual_by_participant
                                                                : QosProfile::Liveliness::manual_by_topic;
    e.liveliness_lease_s = seconds(d);
  }
  if (dds_qget_lifespan(q, &d)) e.lifespan_s = seconds(d);
  if (dds_qget_latency_budget(q, &d)) e.latency_budget_s = d == DDS_INFINITY ? 1e9 : static_cast<double>(d) * 1e-9;
  dds_ownership_kind_t ok;
  if (dds_qget_ownership(q, &ok)) e.exclusive_ownership = ok == DDS_OWNERSHIP_EXCLUSIVE;
  uint32_t n = 0;
  dds_data_representation_id_t* values = nullptr;
  if (dds_qget_data_representation(q, &n, &values) && values) {
    for (uint32_t i = 0; i < n; ++i) e.data_representation.push_back(static_cast<int>(values[i]));
    dds_free(values);
  }
  return e;
}

std::string guid_hex(const dds_guid_t& g) {
  static const char* hex = "0123456789abcdef";
  std::string s;
  for (int i = 0; i < 16; ++i) {
    if (i == 12) s += '|';
    s += hex[g.v[i] >> 4];
    s += hex[g.v[i] & 15];
  }
  return s;
}

}  // namespace

std::vector<DiscoveredEndpoint> CycloneParticipant::dds_endpoints() const {
  std::vector<DiscoveredEndpoint> out;
  dds_guid_t self{};
  dds_get_guid(participant_, &self);
  for (const dds_entity_t rd : {builtin_publications_, builtin_subscriptions_}) {
    constexpr int kMax = 512;
    std::vector<void*> samples(kMax, nullptr);
    std::vector<dds_sample_info_t> infos(kMax);
    const int n = dds_read_mask(rd, samples.data(), infos.data(), kMax, kMax,
                                DDS_ANY_SAMPLE_STATE | DDS_ANY_VIEW_STATE | DDS_ALIVE_INSTANCE_STATE);
    for (int i = 0; i < n; ++i) {
      const auto* ep = static_cast<const dds_builtintopic_endpoint_t*>(samples[static_cast<std::size_t>(i)]);
      if (!infos[static_cast<std::size_t>(i)].valid_data || !ep->topic_name) continue;
      // Cyclone's own built-in endpoints and other internal topics are not user topics.
      if (std::strncmp(ep->topic_name, "DCPS", 4) == 0) continue;
      DiscoveredEndpoint d;
      d.topic = ep->topic_name;
      d.type_name = ep->type_name ? ep->type_name : "";
      d.is_writer = rd == builtin_publications_;
      d.local = std::memcmp(ep->participant_key.v, self.v, 12) == 0;
      d.participant = participant_name(ep->participant_key);
      d.guid = guid_hex(ep->key);
      d.qos = endpoint_qos(ep->qos);
      out.push_back(std::move(d));
    }
    if (n > 0) dds_return_loan(rd, samples.data(), n);
  }
  return out;
}

}  // namespace plexus::rt
