// Stage 4 of plexus launch: the run itself, on the clock's host in lockstep or realtime, and
// on any other host, serving until its processes end (stages.hpp).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <map>
#include <thread>

#include "failure_cause.hpp"
#include "lockstep_status.hpp"
#include "plexus/base/clock.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/distributed/lockstep.hpp"
#include "plexus/evaluation/run_folder.hpp"
#include "stages.hpp"
#include "timing_budget.hpp"

namespace plexus::cli {
namespace {

/// A producer on another host stamps its response with that host's clock: its offset, by producer.
std::map<std::string, double> producer_offsets_us(const scenario::Scenario& sc, const LaunchRun& run) {
  std::map<std::string, double> out;
  for (const auto& c : sc.components)
    if (run.remotes && !c.host.empty())
      out[c.component->name()] = static_cast<double>(run.remotes->offset(c.host).offset_ns) * 1e-3;
  return out;
}

/// Runs the clock or the realtime monitor (`body`) and ends the run: an exit code when it was
/// interrupted, failed (a LockstepError) or lost a host; else nothing, with every process stopped.
/// `timeout_s`: the lockstep timeout (--timeout).
std::optional<int> run_to_end(LaunchRun& run, const LaunchPlan& plan, double timeout_s,
                              const std::function<void()>& body) {
  try {
    body();
  } catch (const distributed::LockstepError& e) {
    if (g_launch_signal) return run.interrupted();
    return run.failure(lockstep_failure_cause(run, plan, e, timeout_s));  // before anything stops
  } catch (const BudgetError& e) {  // --strict: a placement that cannot fit a loop's budget
    return run.failure(e.what(), kExitBadInput);
  }
  if (g_launch_signal) return run.interrupted();
  run.stop_all();
  if (run.host_lost()) return run.failure("");  // the lost host is the cause (LaunchRun::failure)
  return std::nullopt;
}

}  // namespace

int serve_launch(const LaunchOptions& o, LaunchPlan& plan, LaunchRun& run) {
  // Another host runs the clock: serve until our processes end with the run.
  auto running = [&] {
    for (const auto& p : plan.procs)
      if (p.pid > 0) return true;
    return false;
  };
  while (running() && !g_launch_stop) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  if (g_launch_signal) return run.interrupted();
  run.stop_all();
  if (run.supervisor->first_death()) return run.failure("");  // failure() names the process (death())
  scenario::mark_run_folder(run.run_dir, "complete");
  if (plan.session && !plan.session->ended().empty()) {
    std::fprintf(stderr, "plexus launch --host %s: stopped: %s\n", o.host.c_str(), plan.session->ended().c_str());
    return LaunchRun::done(0);
  }
  if (!o.quiet)
    std::fprintf(stderr, "plexus launch --host %s: %zu processes done\n", o.host.c_str(), plan.procs.size());
  return LaunchRun::done(0);
}

std::optional<int> run_realtime_launch(const LaunchOptions& o, LaunchPlan& plan, LaunchRun& run, RealtimeResult& out) {
  return run_to_end(run, plan, o.timeout, [&] {
    std::vector<Process> all = plan.everywhere;  // monitored through heartbeats: not the external ones
    all.erase(std::remove_if(all.begin(), all.end(), [&](const Process& p) { return plan.is_external(p); }), all.end());
    std::map<std::string, int64_t> host_offsets;  // corrects cross-host latencies (remote_share.hpp)
    for (const auto& h : plan.remote_hosts) host_offsets[h] = run.remotes->offset(h).offset_ns;
    // Readiness (inputs matched) is awaited for half the services' own wait for the start
    // signal (--timeout), so that they always get it before they give up.
    BudgetCheck budget(loop_budgets(plan.sc, plan.everywhere), o.strict);
    out = run_realtime(plan.sc, *run.participant, plan.profiles, all, 30.0, o.timeout / 2, run.fault, *run.console,
                       g_launch_stop, host_offsets, &budget, run.monitor.get());
    run.startup_s = static_cast<double>(out.all_running_ns - plan.command_ns) * 1e-9;
    run.run_active = false;
    run.console->clear();
  });
}

std::optional<int> run_lockstep_launch(const LaunchOptions& o, LaunchPlan& plan, LaunchRun& run, LockstepOutcome& out) {
  const auto ended = run_to_end(run, plan, o.timeout, [&] {
    distributed::LockstepClock clock(plan.sc, *run.participant, plan.lockstep_qos, {.timeout_s = o.timeout});
    rt::Subscriber<msg::ParamReply> param_replies;  // plexus param set during the run; deleted with the clock
    if (run.recorder) param_replies = run.recorder->record_param_replies(*run.participant);
    clock.wait_ready(static_cast<int>(plan.everywhere.size()), 30.0, g_launch_stop);
    const int64_t start = monotonic_ns();
    run.startup_s = static_cast<double>(start - plan.command_ns) * 1e-9;
    LockstepStatus status(plan.sc, clock, *run.console, start, producer_offsets_us(plan.sc, run));
    out.log = clock.run(
        g_launch_stop, [&status](int64_t k, int64_t n) { status.observe(k, n); },
        run.recorder ? run.recorder->tap(clock.signals()) : distributed::LockstepClock::SampleTap{});
    out.wall = static_cast<double>(monotonic_ns() - start) * 1e-9;
    out.response = status.response();
    run.console->clear();
  });
  if (!ended && run.recorder) run.recorder->write();
  return ended;
}

}  // namespace plexus::cli
