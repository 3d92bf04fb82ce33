// QoS profiles by name, from deploy/qos.yaml, applied identically by both back ends.
#pragma once

#include <cstdint>
#include <map>
#include <string>

namespace YAML {
class Node;
}

namespace plexus::rt {

/// One named QoS profile. Durations are in seconds; 0 means "infinite" (not set).
struct QosProfile {
  enum class Reliability { best_effort, reliable };
  enum class Durability { volatile_, transient_local };
  enum class History { keep_last, keep_all };
  enum class Liveliness { automatic, manual_by_participant, manual_by_topic };

  std::string name;
  Reliability reliability = Reliability::reliable;
  double max_blocking_time_s = 0.1;
  Durability durability = Durability::volatile_;
  History history = History::keep_last;
  int32_t depth = 1;        ///< keep_last depth (>= 1)
  double deadline_s = 0.0;  ///< 0: no deadline
  Liveliness liveliness = Liveliness::automatic;
  double liveliness_lease_s = 0.0;  ///< 0: infinite lease
  double lifespan_s = 0.0;          ///< 0: infinite
  double latency_budget_s = 0.0;    ///< 0: none
};

const char* to_string(QosProfile::Reliability v);
const char* to_string(QosProfile::Durability v);
const char* to_string(QosProfile::History v);
const char* to_string(QosProfile::Liveliness v);

/// One line: "profile sensor: best_effort, volatile, keep_last 1, deadline 0.05 s".
std::string describe(const QosProfile& q);

/// A set of profiles loaded from a YAML file:
///
///   profiles:
///     sensor:
///       reliability: best_effort        # or reliable (+ max_blocking_time_s)
///       durability: volatile            # or transient_local
///       history: keep_last              # or keep_all
///       depth: 1
///       deadline_s: 0.05                # optional, 0 = none
///       liveliness: automatic           # or manual_by_participant, manual_by_topic
///       liveliness_lease_s: 1.0         # optional, 0 = infinite
///       lifespan_s: 0                   # optional
///       latency_budget_s: 0             # optional
///
/// Every key is validated; an unknown key, a wrong type or an out-of-range value throws
/// InputError naming the file, line and key.
class QosProfiles {
 public:
  static QosProfiles load(const std::string& path);
  static QosProfiles parse(const std::string& yaml_text, const std::string& origin);

  /// The profile, or InputError "file: unknown QoS profile 'x' (known: a, b)".
  const QosProfile& get(const std::string& name) const;
  bool contains(const std::string& name) const { return profiles_.count(name) != 0; }
  const std::map<std::string, QosProfile>& all() const { return profiles_; }
  const std::string& origin() const { return origin_; }

 private:
  static QosProfiles from_node(const YAML::Node& doc, const std::string& origin);

  std::string origin_;
  std::map<std::string, QosProfile> profiles_;
};

/// deploy/qos.yaml of the source tree or of an installed plexus: $PLEXUS_QOS_FILE if set,
/// else the first of <exe dir>/../../deploy/qos.yaml (build tree) and ./deploy/qos.yaml.
std::string default_qos_file();

}  // namespace plexus::rt
