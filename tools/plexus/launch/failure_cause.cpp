#include "failure_cause.hpp"

#include <set>

#include "plexus/distributed/lockstep_wait.hpp"

namespace plexus::cli {
namespace {

constexpr int kLastLineWaitMs = 1000;  // an exited process's pipe ends at once; the relay polls

/// This host's process that runs component `name`, or null.
const Process* process_of(const LaunchPlan& plan, const std::string& name) {
  for (const auto& p : plan.procs)
    for (const std::size_t c : p.components)
      if (plan.sc.components[c].component->name() == name) return &p;
  return nullptr;
}

}  // namespace

std::string lockstep_failure_cause(const LaunchRun& run, const LaunchPlan& plan,
                                   const distributed::LockstepError& error, double timeout_s) {
  std::string cause = error.what();
  if (!run.supervisor || !run.relay) return cause;
  const int64_t grace_ns = static_cast<int64_t>(timeout_s * 1e9) + 500'000'000;
  std::set<std::string> asked;
  // The next producer to ask (the clock's awaited one), or the process that ended the run.
  std::string producer = error.awaited();
  std::optional<ProcessSupervisor::Exit> exit;
  if (producer.empty()) {
    exit = run.supervisor->first_death();
    if (!exit) return cause;  // not a wait (a refused sample, a signal): the clock's message
  }
  for (;;) {
    if (!exit) {
      const Process* p = process_of(plan, producer);
      if (!p || !asked.insert(p->service()).second) return cause;  // on another host, or a loop
      const auto status = run.supervisor->await_exit(p->service(), grace_ns);
      if (!status || *status == 0) return cause;  // it still runs: the one that stopped answering
      exit = ProcessSupervisor::Exit{p->service(), *status};
    }
    asked.insert(exit->service);
    cause = run.exit_report(exit->service, exit->status, kLastLineWaitMs);
    if (exit->status >= 128) return cause;  // killed: the cause itself
    const auto wait = distributed::parse_lockstep_wait(run.relay->last_line(exit->service));
    if (!wait) return cause;  // it failed of something else: the cause itself
    producer = wait->producer;
    exit.reset();
  }
}

}  // namespace plexus::cli
