// Stage 5 of plexus launch on the clock's host: launch.json and the summary, the metrics and
// the run folder (finish_run), the report with --report, the exit code (stages.hpp).
#include <cstdio>

#include "plexus/evaluation/run_folder.hpp"
#include "run_result.hpp"
#include "stages.hpp"

namespace plexus::cli {
namespace {

/// launch.json's processes (what this launcher started), the participants per host they were
/// given (dds.participants_per_host, raised to what the run needs), and their security.
void add_processes(const LaunchPlan& plan, RunSummary& summary) {
  summary.extra["processes"] = process_table(plan.procs);
  summary.extra["participants_per_host"] = plan.net.max_participants_per_host;
  if (plan.security.enabled) summary.extra["security"] = plan.security.to_json();
}

/// How long the start and the stop took, and (one command) each host's clock and state.
void add_hosts(const LaunchPlan& plan, const LaunchRun& run, RunSummary& summary) {
  summary.extra["startup_s"] = run.startup_s;
  summary.extra["teardown_s"] = run.teardown_s;
  if (!run.remotes) return;
  summary.extra["hosts"] = run.remotes->report();
  char line[200];
  std::snprintf(line, sizeof line, "hosts: %zu, every process running %.2f s after the command, all stopped in %.2f s",
                plan.remote_hosts.size() + 1, run.startup_s, run.teardown_s);
  summary.lines.push_back(line);
}

/// One line per command signal that a sensor sample reached: its sensor-to-command latency.
void add_latency_lines(const nlohmann::ordered_json& latency, RunSummary& summary) {
  for (const auto& [name, l] : latency.items()) {
    if (l["samples"].get<int>() == 0) continue;  // no sensor sample reached it (an open-loop command)
    char line[320];
    std::snprintf(line, sizeof line, "latency sensor -> %s: p50 %.0f us, p99 %.0f us (%d samples)%s", name.c_str(),
                  l["p50_us"].get<double>(), l["p99_us"].get<double>(), l["samples"].get<int>(),
                  l.contains("clock_offset_corrected_us")
                      ? (", corrected by " + l["clock_offset_corrected_us"].dump() + " us of clock offset").c_str()
                      : "");
    summary.lines.push_back(line);
  }
}

}  // namespace

int summarise_realtime(const LaunchOptions& o, const LaunchPlan& plan, LaunchRun& run, RealtimeResult& r) {
  const std::string died = run.death();
  char headline[256];
  std::snprintf(headline, sizeof headline, "scenario %s: realtime over %zu processes (%s), %.3g s",
                plan.sc.name.c_str(), plan.everywhere.size(), plan.vendors_label.c_str(), r.wall);
  RunSummary summary;
  summary.headline = headline;
  add_processes(plan, summary);
  summary.extra["services"] = r.services;
  summary.extra["command_latency"] = r.latency;
  nlohmann::ordered_json restarts = nlohmann::ordered_json::object();
  for (const auto& p : plan.procs)
    if (p.restarts) restarts[p.service()] = p.restarts;
  summary.extra["restarts"] = restarts;
  if (!r.loops.empty()) summary.extra["loops"] = r.loops;  // the timing budgets (timing_budget.hpp)
  if (!r.fault.empty()) {
    r.fault["killed"] = run.supervisor->killed();
    summary.extra["fault"] = r.fault;
  }
  // A process that died for good: the run folder still records what happened, then it fails.
  if (!died.empty()) summary.extra["failure"] = died;
  add_latency_lines(r.latency, summary);
  add_hosts(plan, run, summary);
  const int rc = finish_run(plan.sc, r.log, r.wall, run.run_dir, o.json, o.quiet, summary);
  if (o.report) print_report(run.run_dir, o.json);
  if (!died.empty()) {
    scenario::mark_run_folder(run.run_dir, "failed: " + died);  // recorded, but not a complete run
    std::fprintf(stderr, "plexus launch: %s\n", died.c_str());
    return LaunchRun::done(1);
  }
  return LaunchRun::done(rc);
}

int summarise_lockstep(const LaunchOptions& o, const LaunchPlan& plan, LaunchRun& run, const LockstepOutcome& out) {
  const scenario::Scenario& sc = plan.sc;
  const double steps_per_s = out.wall > 0 ? static_cast<double>(sc.steps + 1) / out.wall : 0.0;
  char headline[256];
  std::snprintf(headline, sizeof headline,
                "scenario %s: %lld steps in lockstep over %zu processes (%s), %.3g s, %.0f steps/s", sc.name.c_str(),
                static_cast<long long>(sc.steps), plan.everywhere.size(), plan.vendors_label.c_str(), out.wall,
                steps_per_s);
  RunSummary summary;
  summary.headline = headline;
  summary.extra["steps_per_s"] = steps_per_s;
  add_processes(plan, summary);
  summary.extra["response"] = out.response;
  add_hosts(plan, run, summary);
  const int rc = finish_run(sc, out.log, out.wall, run.run_dir, o.json, o.quiet, summary);
  if (o.report) print_report(run.run_dir, o.json);
  return LaunchRun::done(rc);
}

}  // namespace plexus::cli
