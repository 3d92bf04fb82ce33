// One event API for both vendors: deadline missed, incompatible QoS, liveliness,
// matched/unmatched. Every event is also logged (warnings at a rate limit).
#pragma once

#include <cstdint>
#include <functional>
#include <string>

namespace plexus::rt {

enum class EventKind {
  deadline_missed,     ///< writer offered / reader requested deadline missed
  incompatible_qos,    ///< a remote endpoint on the same topic could not match; `policy` names why
  liveliness_lost,     ///< writer: it failed to assert liveliness within its lease
  liveliness_changed,  ///< reader: a matched writer became alive or not alive (`alive`)
  matched,             ///< an endpoint matched a remote one
  unmatched,           ///< a matched remote endpoint went away
  sample_lost,         ///< reader: samples lost (e.g. best-effort gaps)
};

const char* to_string(EventKind k);

struct Event {
  EventKind kind{};
  bool on_writer = false;  ///< the local endpoint is a writer (else a reader)
  std::string topic;
  std::string local;          ///< the local endpoint: "<participant name> writer" etc.
  std::string remote;         ///< the remote endpoint when known (participant name / GUID and its QoS value)
  std::string policy;         ///< incompatible_qos: the offending policy (RELIABILITY, DURABILITY, DEADLINE, ...)
  int32_t total_count = 0;    ///< cumulative count reported by the vendor
  int32_t current_count = 0;  ///< matched / alive count now, where the status has one
  bool alive = false;         ///< liveliness_changed: the remote writer is alive
  /// liveliness_changed, not alive: the writer went away (deleted, its participant left)
  /// rather than failing to assert its liveliness. A normal end of a run, not a problem.
  bool writer_left = false;

  /// One line, for logs and tests.
  std::string describe() const;
};

/// Called from the vendor's listener thread: keep it short, copy what you need.
using EventHandler = std::function<void(const Event&)>;

}  // namespace plexus::rt
