#include "plexus/runtime/events.hpp"

#include <spdlog/spdlog.h>

#include "plexus/base/clock.hpp"
#include "plexus/base/logging.hpp"
#include "plexus/runtime/participant.hpp"

namespace plexus::rt {

const char* to_string(EventKind k) {
  switch (k) {
    case EventKind::deadline_missed: return "deadline_missed";
    case EventKind::incompatible_qos: return "incompatible_qos";
    case EventKind::liveliness_lost: return "liveliness_lost";
    case EventKind::liveliness_changed: return "liveliness_changed";
    case EventKind::matched: return "matched";
    case EventKind::unmatched: return "unmatched";
    case EventKind::sample_lost: return "sample_lost";
  }
  return "?";
}

std::string Event::describe() const {
  std::string s = std::string(to_string(kind)) + " on topic '" + topic + "': local " + local;
  if (kind == EventKind::incompatible_qos) s += ", policy " + policy;
  if (!remote.empty()) s += ", remote " + remote;
  if (kind == EventKind::liveliness_changed) s += alive ? " (alive)" : writer_left ? " (writer left)" : " (not alive)";
  s += " (total " + std::to_string(total_count);
  if (kind == EventKind::matched || kind == EventKind::unmatched || kind == EventKind::liveliness_changed)
    s += ", now " + std::to_string(current_count);
  return s + ")";
}

void Participant::emit(const Event& e) const {
  // Matching is informational; problems are warnings, rate-limited per kind so a
  // flapping endpoint cannot flood the log.
  static RateLimiter limiters[7];
  const bool problem = e.kind == EventKind::deadline_missed || e.kind == EventKind::incompatible_qos ||
                       e.kind == EventKind::liveliness_lost || e.kind == EventKind::sample_lost ||
                       (e.kind == EventKind::liveliness_changed && !e.alive && !e.writer_left);
  uint64_t suppressed = 0;
  if (!problem) {
    spdlog::info("{}", e.describe());  // (un)matching happens at start-up and shutdown, not in steady state
  } else if (limiters[static_cast<int>(e.kind)].allow(monotonic_ns(), suppressed)) {
    const std::string tail = suppressed ? " [+" + std::to_string(suppressed) + " similar suppressed]" : "";
    spdlog::warn("{}{}", e.describe(), tail);
  }
  if (handler_) handler_(e);
}

}  // namespace plexus::rt
