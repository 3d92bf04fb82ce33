#include "plexus/runtime/participant.hpp"

#include <algorithm>
#include <cctype>

#include "cyclone/cyclone_participant.hpp"
#include "fastdds/fast_participant.hpp"
#include "plexus/base/bounded_name.hpp"
#include "plexus/base/input_error.hpp"

namespace plexus::rt {

std::unique_ptr<Participant> Participant::create(const ParticipantOptions& options) {
  if (options.domain_id < 0 || options.domain_id > 232)
    throw InputError("--domain: DDS domain id must be in 0..232, got " + std::to_string(options.domain_id));
  if (options.network.max_participants_per_host < 1 ||
      options.network.max_participants_per_host > kMaxParticipantsPerHost)
    throw InputError("--max-participants: participants per host must be in 1.." +
                     std::to_string(kMaxParticipantsPerHost) + ", got " +
                     std::to_string(options.network.max_participants_per_host));
  if (options.security.enabled)
    check_security_files(options.security, "DDS Security of participant '" + options.name + "'");
  if (!(options.network.reliable_heartbeat_s >= 0.001 && options.network.reliable_heartbeat_s <= 10.0))
    throw InputError("network: reliable_heartbeat_s must be in [0.001, 10] s, got " +
                     std::to_string(options.network.reliable_heartbeat_s));
  ParticipantOptions o = options;
  o.name = bounded_name(options.name, kMaxDiscoveryName);  // e.g. a process hosting 20 robots' components
  if (o.vendor == Vendor::fast) return std::make_unique<FastParticipant>(o);
  return std::make_unique<CycloneParticipant>(o);
}

DdsNames Participant::wire_names(const msg::TypeSupport& type, const std::string& topic) const {
  DdsNames names = dds_names(options_.naming, type, topic);
  for (const std::string* n : {&names.topic, &names.type})
    if (n->size() > kMaxDiscoveryName)
      throw InputError((n == &names.topic ? "topic name '" : "type name '") + *n + "' is " + std::to_string(n->size()) +
                       " bytes; DDS discovery between the vendors carries at most " +
                       std::to_string(kMaxDiscoveryName) + " (Fast DDS 2.9 drops longer ones)");
  // A character one vendor refuses (topic_name_char) is refused on both, so a name that
  // works with one vendor works in a mixed deployment too.
  const std::string& t = names.topic;
  const bool valid =
      !t.empty() && !std::isdigit(static_cast<unsigned char>(t[0])) && std::all_of(t.begin(), t.end(), topic_name_char);
  if (!valid)
    throw InputError("topic name '" + t +
                     "': DDS topic names between the vendors hold letters, digits, '_' and '/' only, and do not "
                     "start with a digit (Cyclone DDS refuses others)");
  return names;
}

std::vector<DiscoveredEndpoint> Participant::discovered_endpoints() const {
  std::vector<DiscoveredEndpoint> out = dds_endpoints();
  if (options_.naming != Naming::plexus)
    for (auto& e : out) {
      e.topic = plexus_topic(options_.naming, e.topic);
      e.type_name = plexus_type(options_.naming, e.type_name);
    }
  return out;
}

}  // namespace plexus::rt
