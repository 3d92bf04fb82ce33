// A heartbeat's ServiceState as docs/topics.md names it ("running", "degraded", ...): what
// `plexus service list` and the launch monitor's page print.
#pragma once

#include "plexus/msg/messages.hpp"

namespace plexus::cli {

inline const char* state_name(msg::ServiceState s) {
  switch (s) {
    case msg::SERVICE_CONFIGURING: return "configuring";
    case msg::SERVICE_WAITING: return "waiting";
    case msg::SERVICE_RUNNING: return "running";
    case msg::SERVICE_DEGRADED: return "degraded";
    case msg::SERVICE_DRAINING: return "draining";
  }
  return "?";
}

}  // namespace plexus::cli
