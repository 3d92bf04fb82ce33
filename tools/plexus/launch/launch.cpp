// plexus launch SCENARIO: the stages in order (stages.hpp), and how a run ends (LaunchRun).
#include <algorithm>
#include <csignal>
#include <cstdio>

#include "child_process.hpp"
#include "plexus/base/clock.hpp"
#include "plexus/base/teardown_deadline.hpp"
#include "plexus/evaluation/run_folder.hpp"
#include "run_result.hpp"
#include "stages.hpp"

namespace plexus::cli {

std::atomic<bool> g_launch_stop{false};
std::atomic<int> g_launch_signal{0};

namespace {
void on_signal(int s) {
  g_launch_signal = s;
  g_launch_stop = true;
}
}  // namespace

void stop_on_signal(int signal) { std::signal(signal, on_signal); }

int run_launch(LaunchOptions o) {
  LaunchPlan plan = plan_launch(o);
  LaunchRun run;
  if (!preflight_launch(o, plan, run)) return 1;  // the launcher that started this share gave up
  start_launch(o, plan, run);
  if (!plan.runs_clock) return serve_launch(o, plan, run);
  if (plan.realtime) {
    RealtimeResult r;
    if (const auto ended = run_realtime_launch(o, plan, run, r)) return *ended;
    return summarise_realtime(o, plan, run, r);
  }
  LockstepOutcome r;
  if (const auto ended = run_lockstep_launch(o, plan, run, r)) return *ended;
  return summarise_lockstep(o, plan, run, r);
}

bool LaunchPlan::is_external(const Process& p) const {
  return std::find(externals.begin(), externals.end(), p.name) != externals.end();
}

LaunchRun::~LaunchRun() {
  if (supervising) stop_all();
}

void LaunchRun::stop_all() {
  const int64_t t = monotonic_ns();
  if (supervisor) supervisor->stop();
  if (foxglove_bridge > 0) {
    stop(foxglove_bridge);  // SIGTERM: it closes its connections and prints its counters to its log
    foxglove_bridge = 0;
  }
  if (remotes) remotes->stop();
  if (teardown_s < 0) teardown_s = static_cast<double>(monotonic_ns() - t) * 1e-9;
  if (relay) relay->drain();  // the children's last lines before the launcher's verdict
}

int LaunchRun::failure(const std::string& what, int rc) {
  stop_all();
  const std::string lost = remotes ? remotes->failure() : std::string();  // a lost host is the cause
  const std::string why = !lost.empty() ? lost : !what.empty() ? what : death();
  scenario::mark_run_folder(run_dir, "failed: " + why);
  std::fprintf(stderr, "plexus launch: %s\n", why.c_str());
  return done(rc);
}

int LaunchRun::interrupted() {
  stop_all();
  const double wall_s = static_cast<double>(monotonic_ns() - launched_ns) * 1e-9;
  return done(interrupted_run("plexus launch", g_launch_signal, run_dir, wall_s));
}

std::string LaunchRun::death() const {
  const auto d = supervisor ? supervisor->first_death() : std::nullopt;
  return d ? exit_report(d->service, d->status) : std::string();
}

std::string LaunchRun::exit_report(const std::string& service, int status, int wait_ms) const {
  const std::string exited = service + " exited with code " + std::to_string(status);
  if (status >= 128 || !relay) return exited;  // killed by a signal: no words of its own
  const std::string last = relay->last_line(service, wait_ms);
  return last.empty() ? exited : exited + ": " + last;
}

bool LaunchRun::host_lost() const { return remotes && !remotes->failure().empty(); }

int LaunchRun::done(int rc) { return exit_within(rc, kTeardownDeadlineS, "plexus launch"); }

}  // namespace plexus::cli
