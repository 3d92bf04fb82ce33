// What `plexus launch --monitor` shows (docs/viewing.md, "A web monitor of a launch"): each
// process as its heartbeats describe it, the rule that colours it, the run's progress, and
// the rows of the plotted field. Pure data and JSON, no DDS and no sockets: the realtime
// monitor (realtime_run.cpp) fills it, web_monitor.hpp serves it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "plexus/msg/messages.hpp"
#include "plexus/scenario/signal_log.hpp"

namespace plexus::cli {

/// A service beats once a second while it runs (five times a second while it waits for the
/// start): a heartbeat older than this reads as down.
constexpr double kHeartbeatSilentS = 1.5;

/// One process as the page shows it.
struct ProcessView {
  std::string name;     ///< its service name, as in its heartbeats ("motion_controller controller")
  std::string host;     ///< the scenario's host it runs on ("": the launcher's)
  bool seen = false;    ///< a heartbeat has arrived
  msg::Heartbeat beat;  ///< the last one
  double age_s = 0;     ///< since that heartbeat arrived
  double rate_hz = 0;   ///< loops per second between its last two running heartbeats (0: not known yet)
  int restarts = 0;     ///< times its heartbeats came from a new pid
  bool exited = false;  ///< on the launcher's host: the pid of its last heartbeat is gone
};

enum class Health { starting, ok, degraded, down, done };

/// starting: no heartbeat yet; down: exited, or silent for kHeartbeatSilentS; done: draining
/// at the end; degraded: running on held inputs; else ok.
Health health_of(const ProcessView& v);
const char* health_name(Health h);

/// The run as a whole: "starting" (waiting for every process), "running", "done".
struct RunProgress {
  std::string phase;
  double t_s = 0;         ///< since tick 0 (negative before the start)
  double duration_s = 0;  ///< the scenario's
};

/// The rows a plot has not shown yet, of one field of one signal of the run's log: after
/// select() (or reset()), the whole trace so far, then only what was appended since; either
/// thinned to at most `max_points` (every k-th row).
class PlotFeed {
 public:
  void select(std::string signal, std::string field);
  /// Sends the whole trace again at the next call (a page that just connected).
  void reset() { cursor_ = 0, reset_ = true; }
  /// {"signal", "field", "reset", "points": [[t, value], ...]}; null when nothing is selected.
  nlohmann::json next(const scenario::RunLog& log, std::size_t max_points);

 private:
  std::string signal_, field_;
  std::size_t cursor_ = 0;
  bool reset_ = true;
};

/// The status message of the page (its format: docs/viewing.md).
/// `host_offsets_ns`: each other host's clock minus the launcher's; `latency`: per command,
/// the sensor-to-command latency ({"p50_ms", "p99_ms"}) over the last second.
nlohmann::json status_json(const RunProgress& run, const std::vector<ProcessView>& procs,
                           const std::map<std::string, int64_t>& host_offsets_ns, const nlohmann::json& latency,
                           nlohmann::json plot);

}  // namespace plexus::cli
