// `plexus launch` in realtime mode, on the clock's host: start every process together,
// record every signal with its latency from the sensor sample that started its chain,
// collect heartbeats and the live status line, stop after the scenario's duration.
#pragma once

#include <atomic>
#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "launch_plan.hpp"
#include "plexus/runtime/participant.hpp"
#include "plexus/runtime/qos.hpp"
#include "plexus/scenario/scenario.hpp"
#include "plexus/scenario/signal_log.hpp"
#include "status_console.hpp"
#include "timing_budget.hpp"
#include "web_monitor.hpp"

namespace plexus::cli {

/// What a realtime run measured, for launch.json and the summary.
struct RealtimeResult {
  scenario::RunLog log;
  nlohmann::ordered_json services = nlohmann::ordered_json::object();
  nlohmann::ordered_json latency = nlohmann::ordered_json::object();
  nlohmann::ordered_json fault = nlohmann::ordered_json::object();
  nlohmann::ordered_json loops = nlohmann::ordered_json::object();  ///< BudgetCheck::record()
  double wall = 0;
  int64_t all_running_ns = 0;  ///< monotonic time every process had reported (its first heartbeat)
};

/// Fault injection state shared with the launcher's watcher thread.
struct FaultClock {
  std::atomic<int64_t> run_start_ns{0};  ///< monotonic time of the start signal (0: not started)
  std::atomic<int64_t> killed_ns{0};     ///< monotonic time of the injected kill (0: none yet)
  std::atomic<int64_t> respawned_ns{0};  ///< monotonic time the killed process was started again (0: not yet)
};

/// Waits (up to start_timeout_s) for a heartbeat from every process in `procs`, then (up to
/// ready_wait_s more) until none reports CONFIGURING, i.e. every input of every process has
/// matched a writer of its producer; past that wait it starts anyway, with a warning naming
/// the processes still matching (their loops hold until their inputs arrive). Then it
/// publishes the start signal and records until the duration has passed, every host is
/// draining, or `stop`. Throws distributed::LockstepError when a process never reports.
/// `host_clock_offset_ns`: each other host's clock minus this one's (plexus launch over ssh);
/// the sensor-to-command latency of a robot on such a host is corrected by it (the sample's
/// origin time is that host's clock, the arrival this one's), and says so in its record.
/// `budget`: the loops' timing budgets, measured over the first second (timing_budget.hpp);
/// it throws BudgetError out of here when strict and a loop does not fit.
/// `web`: --monitor's page, fed four times a second from the first heartbeat to the end.
RealtimeResult run_realtime(scenario::Scenario& sc, rt::Participant& participant, const rt::QosProfiles& profiles,
                            const std::vector<Process>& procs, double start_timeout_s, double ready_wait_s,
                            FaultClock& fault, StatusConsole& console, const std::atomic<bool>& stop,
                            const std::map<std::string, int64_t>& host_clock_offset_ns = {},
                            BudgetCheck* budget = nullptr, WebMonitor* web = nullptr);

}  // namespace plexus::cli
