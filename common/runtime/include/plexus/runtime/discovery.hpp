// What a participant knows about the endpoints on its domain (local and remote), for tools:
// `plexus topic list|info`, automatic subscriber QoS in echo/hz/record.
//
// Both back ends fill it from their discovery data: Fast DDS from the participant
// listener's discovery callbacks, Cyclone DDS from the built-in DCPSPublication /
// DCPSSubscription / DCPSParticipant topics.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "plexus/runtime/qos.hpp"

namespace plexus::rt {

/// The QoS of an endpoint as seen in discovery. Durations in seconds, 0 = infinite (not
/// set), except latency_budget_s where 0 means none. History is not part of standard
/// discovery data: `history_known` says whether the vendor sent it.
struct EndpointQos {
  QosProfile::Reliability reliability = QosProfile::Reliability::best_effort;
  QosProfile::Durability durability = QosProfile::Durability::volatile_;
  bool durability_stronger = false;  ///< transient or persistent (reported as transient_local+)
  bool history_known = false;
  QosProfile::History history = QosProfile::History::keep_last;
  int32_t depth = 1;
  double deadline_s = 0;
  QosProfile::Liveliness liveliness = QosProfile::Liveliness::automatic;
  double liveliness_lease_s = 0;
  double lifespan_s = 0;
  double latency_budget_s = 0;
  bool exclusive_ownership = false;
  /// Data representations offered (writer: first one used) or accepted (reader):
  /// 0 = XCDR1, 2 = XCDR2 (DDS-XTypes ids). Empty: not announced (means XCDR1).
  std::vector<int> data_representation;
};

struct DiscoveredEndpoint {
  std::string topic;
  std::string type_name;
  bool is_writer = false;
  bool local = false;       ///< belongs to this participant
  std::string participant;  ///< participant (service) name, or its GUID prefix
  std::string guid;
  EndpointQos qos;
};

/// Request-offered check of the DDS spec (writer offers, reader requests). Returns the
/// first incompatible policy (RELIABILITY, DURABILITY, DEADLINE, LIVELINESS, OWNERSHIP,
/// LATENCYBUDGET, DATA_REPRESENTATION) with both values, or nullopt if they match.
struct QosMismatch {
  std::string policy;
  std::string offered;
  std::string requested;
};
std::optional<QosMismatch> check_compatible(const EndpointQos& writer, const EndpointQos& reader);

/// One line: "reliable, volatile, keep_last 16, deadline inf, liveliness automatic lease inf, ...".
std::string describe(const EndpointQos& q);

/// A reader QoS that matches every writer in `writers` (same topic): reliable only if all
/// of them are reliable, transient_local only if all are, no deadline, automatic liveliness
/// with an infinite lease, keep_last `depth`. Matches any writer when `writers` is empty
/// (best effort, volatile).
QosProfile reader_qos_matching(const std::vector<EndpointQos>& writers, int32_t depth);

/// A writer QoS reproducing a discovered writer's (history keep_last `depth` when unknown).
QosProfile writer_qos_like(const EndpointQos& q, int32_t depth);

}  // namespace plexus::rt
