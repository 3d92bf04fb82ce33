// Fast DDS discovery data -> plexus::rt::EndpointQos (internal, for FastParticipant::Discovery).
#pragma once

#include <fastdds/dds/core/policy/QosPolicies.hpp>

#include "plexus/runtime/discovery.hpp"

namespace plexus::rt::detail {

inline double fast_seconds(const eprosima::fastrtps::Duration_t& d) {
  if (d == eprosima::fastrtps::c_TimeInfinite) return 0;
  return static_cast<double>(d.to_ns()) * 1e-9;
}

/// Q: eprosima::fastrtps::WriterQos or ReaderQos (both have these members).
template <class Q>
EndpointQos endpoint_qos_from_fast(const Q& q) {
  namespace fdds = eprosima::fastdds::dds;
  EndpointQos e;
  e.reliability = q.m_reliability.kind == fdds::RELIABLE_RELIABILITY_QOS ? QosProfile::Reliability::reliable
                                                                         : QosProfile::Reliability::best_effort;
  e.durability = q.m_durability.kind == fdds::VOLATILE_DURABILITY_QOS ? QosProfile::Durability::volatile_
                                                                      : QosProfile::Durability::transient_local;
  e.durability_stronger =
      q.m_durability.kind == fdds::TRANSIENT_DURABILITY_QOS || q.m_durability.kind == fdds::PERSISTENT_DURABILITY_QOS;
  e.deadline_s = fast_seconds(q.m_deadline.period);
  switch (q.m_liveliness.kind) {
    case fdds::AUTOMATIC_LIVELINESS_QOS: e.liveliness = QosProfile::Liveliness::automatic; break;
    case fdds::MANUAL_BY_PARTICIPANT_LIVELINESS_QOS:
      e.liveliness = QosProfile::Liveliness::manual_by_participant;
      break;
    case fdds::MANUAL_BY_TOPIC_LIVELINESS_QOS: e.liveliness = QosProfile::Liveliness::manual_by_topic; break;
  }
  e.liveliness_lease_s = fast_seconds(q.m_liveliness.lease_duration);
  e.lifespan_s = fast_seconds(q.m_lifespan.duration);
  e.latency_budget_s = fast_seconds(q.m_latencyBudget.duration);
  if (q.m_latencyBudget.duration == eprosima::fastrtps::c_TimeInfinite) e.latency_budget_s = 1e9;
  e.exclusive_ownership = q.m_ownership.kind == fdds::EXCLUSIVE_OWNERSHIP_QOS;
  for (auto v : q.representation.m_value) e.data_representation.push_back(static_cast<int>(v));
  return e;
}

}  // namespace plexus::rt::detail
