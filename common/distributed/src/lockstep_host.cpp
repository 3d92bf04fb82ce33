// LockstepHost (lockstep.hpp): a host's steps run on the DDS receive threads. Each sample
// that arrives (a remote input, a clock tick) pokes the pump, and the thread that received
// it runs as much of the host's steps as the inputs there allow (StepExecutor::step_from),
// publishing the outputs itself; the next sample resumes where it stopped. No thread is
// woken per sample besides the receiving one (docs/performance.md, section 4). The run
// thread only watches: the stop flag, the bounded waits, the end of the run.
#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <limits>

#include "input_guard.hpp"
#include "lockstep_text.hpp"
#include "plexus/base/clock.hpp"
#include "plexus/distributed/lockstep.hpp"
#include "plexus/distributed/lockstep_wait.hpp"
#include "plexus/distributed/param_server.hpp"
#include "pumped_run.hpp"

namespace plexus::distributed {
namespace {

using scenario::SignalSample;
using scenario::SignalSpec;

/// The latest samples received of one remote signal, by step. Used by the pump's thread only.
class RemoteSignal {
 public:
  RemoteSignal(const SignalSpec& spec, rt::Participant& p, const rt::QosProfile& qos, int64_t step_ns,
               detail::InputGuard& guard)
      : spec_(&spec), sub_(p, spec, step_ns, qos), guard_(&guard) {}

  /// Whether the sample produced at step `due` has arrived (takes what was received).
  bool ready(int64_t due) {
    if (ring_[slot(due)].step == due) return true;
    drain();
    return ring_[slot(due)].step == due;
  }
  /// The sample produced at step `due`; only after ready(due).
  void get(int64_t due, SignalSample& out) const {
    const SignalSample& s = ring_[slot(due)];
    if (s.step != due)  // step_from asks ready() first: cannot happen
      throw LockstepError("lockstep: the sample of '" + spec_->name + "' for " + lockstep_step(due) + " is gone");
    out = s;
  }
  const SignalSpec& spec() const { return *spec_; }
  WireSubscriber& subscriber() { return sub_; }

 private:
  void drain() {
    while (const void* m = sub_.take()) {
      if (guard_->accept(sub_.wire(), m, scratch_)) ring_[slot(scratch_.step)] = scratch_;
    }
  }
  std::size_t slot(int64_t step) const {
    return static_cast<std::size_t>((step / spec_->period_steps) % static_cast<int64_t>(kRing));
  }
  static constexpr std::size_t kRing = 32;  // > 2 * kMaxLeadSteps: a producer is at most the lead ahead
  const SignalSpec* spec_;
  WireSubscriber sub_;
  detail::InputGuard* guard_;
  SignalSample scratch_;
  std::array<SignalSample, kRing> ring_{};
};

}  // namespace

struct LockstepHost::Impl {
  // Declared first, destroyed last: the readers' callbacks (destroyed before) use them.
  detail::PumpedRun run{[this] { advance(); }};
  // Written by the clock's callback, read by the pump and the run thread.
  std::atomic<int64_t> allowed{-1};  // the last step the clock allows
  std::atomic<bool> ended{false};    // the end-of-run tick arrived
  std::atomic<int64_t> last_tick_ns{0};
  // Written by the pump, read by the run thread for its messages.
  std::atomic<int64_t> expected{0};         // the step in progress
  std::atomic<int64_t> waiting_signal{-1};  // the remote input step `expected` waits for; -1: the clock
  std::atomic<int64_t> waiting_due{-1};

  scenario::Scenario& sc;
  scenario::StepExecutor exec;
  LockstepOptions opt;
  int64_t lead;
  detail::InputGuard guard{"lockstep host"};
  std::vector<std::unique_ptr<WirePublisher>> out;    // indexed by signal (null if not local)
  std::unique_ptr<ParamServer> params;                // plexus param, when the host has a service name
  std::vector<std::unique_ptr<RemoteSignal>> remote;  // indexed by signal (null if not remote)
  rt::Subscriber<msg::ClockStep> clock;
  // The pump's own.
  std::size_t cursor = 0;  // the component step `expected` resumes at
  int64_t served = -1;     // the last step whose parameter requests were served
  scenario::StepExecutor::RemoteInput read_remote;
  scenario::StepExecutor::OutputSink publish;

  Impl(scenario::Scenario& s, std::vector<bool> hosted, rt::Participant& p, const rt::QosProfile& qos,
       LockstepOptions o)
      : sc(s), exec(s, hosted), opt(o), lead(std::clamp<int64_t>(o.lead_steps, 0, kMaxLeadSteps)) {
    if (!opt.service.empty()) params = std::make_unique<ParamServer>(s, std::move(hosted), p, opt.service);
    const auto& signals = exec.signals();
    out.resize(signals.size());
    for (std::size_t i : exec.local_outputs())
      out[i] = std::make_unique<WirePublisher>(p, signals[i], step_ns(sc), qos);
    read_remote = [this](std::size_t signal, int64_t due, SignalSample& sample) { remote[signal]->get(due, sample); };
    publish = [this](std::size_t signal, const SignalSample& sample) {
      if (!out[signal]->publish(sample, 0))
        throw LockstepError("lockstep: cannot publish '" + exec.signals()[signal].name + "' at " +
                            lockstep_step(sample.step));
    };
    remote.resize(signals.size());
    for (std::size_t i : exec.remote_inputs()) {
      remote[i] = std::make_unique<RemoteSignal>(signals[i], p, qos, step_ns(sc), guard);
      remote[i]->subscriber().on_data([this] { run.poke(); });
    }
    clock = p.subscriber<msg::ClockStep>(kClockTopic, qos);
    clock.on_sample([this](const msg::ClockStep& tick, const rt::SampleMeta&) {
      last_tick_ns.store(monotonic_ns(), std::memory_order_relaxed);
      if (tick.step_index() == kEndOfRun) {
        ended.store(true);
      } else {  // ClockStep k allows steps up to k + lead; repeats (a late join) are harmless
        const auto k = static_cast<int64_t>(tick.step_index()) + lead;
        int64_t a = allowed.load();
        while (a < k && !allowed.compare_exchange_weak(a, k)) {}
      }
      run.poke();
    });
  }

  /// The pump's work: runs every step the clock allows as far as the inputs have arrived.
  /// A host runs ahead of the clock as far as its inputs allow (each remote input is the
  /// exact sample, so the result cannot change), which takes the clock's round trip off
  /// the critical path of a closed loop.
  void advance() noexcept {
    if (run.finished()) return;
    try {
      const auto have = [this](std::size_t signal, int64_t due) {
        if (remote[signal]->ready(due)) return true;
        waiting_signal.store(static_cast<int64_t>(signal), std::memory_order_relaxed);
        waiting_due.store(due, std::memory_order_relaxed);
        return false;
      };
      const std::size_t components = sc.components.size();
      int64_t k = expected.load(std::memory_order_relaxed);
      while (!ended.load() && k <= std::min(allowed.load(), sc.steps)) {
        if (cursor == 0 && served != k) {
          if (params) params->serve(k);  // a change takes effect at a step of the clock's
          served = k;
        }
        const std::size_t at = exec.step_from(k, cursor, have, read_remote, publish);
        if (at != cursor) run.progress();
        if (at < components) {
          cursor = at;
          return;  // the input's sample will poke again
        }
        cursor = 0;
        expected.store(++k, std::memory_order_relaxed);
        run.progress();
      }
      waiting_signal.store(-1, std::memory_order_relaxed);
      // The end of the run, or every step done and the clock's writer gone: the run ended
      // even if the end-of-run mark never reached us (the clock waits for its
      // acknowledgement, but bounded).
      if (ended.load() || (k > sc.steps && clock.matched_count() == 0)) run.finish();
    } catch (...) {
      run.finish(std::current_exception());
    }
  }
};

LockstepHost::LockstepHost(scenario::Scenario& scenario, std::vector<bool> hosted, rt::Participant& participant,
                           const rt::QosProfile& qos, LockstepOptions options)
    : impl_(std::make_unique<Impl>(scenario, std::move(hosted), participant, qos, options)) {}

LockstepHost::~LockstepHost() = default;

int64_t LockstepHost::run(const std::atomic<bool>& stop) {
  Impl& m = *impl_;
  const int64_t timeout = lockstep_ns(m.opt.timeout_s);
  m.last_tick_ns.store(monotonic_ns());
  m.run.watch(stop, [&m, timeout](int64_t stalled, bool tell) {
    const int64_t signal = m.waiting_signal.load(std::memory_order_relaxed);
    if (signal < 0) {
      // The clock waits for our outputs, so silence here means the clock is gone; the
      // launcher's timeout covers a slow run, this one a dead launcher.
      if (monotonic_ns() - m.last_tick_ns.load() > 3 * timeout) {
        const int64_t allowed = m.allowed.load();
        throw LockstepError((allowed < 0 ? "lockstep: no clock: no step on '" + std::string(kClockTopic) + "'"
                                         : "lockstep: the clock stopped at " + lockstep_step(m.expected.load())) +
                            " for more than " + lockstep_seconds(static_cast<double>(3 * timeout) * 1e-9));
      }
      return;
    }
    const auto& spec = m.exec.signals()[static_cast<std::size_t>(signal)];
    const int64_t due = m.waiting_due.load(std::memory_order_relaxed);
    if (stalled >= timeout)
      throw LockstepError(lockstep_wait_message({spec.name, spec.producer}, due, static_cast<double>(timeout) * 1e-9),
                          spec.producer);
    if (tell)  // every wait of a second or more, with its step and producer, to find a stall
      spdlog::warn("lockstep: host at {} has waited {:.1f} s for '{}' (produced by '{}') of {}",
                   lockstep_step(m.expected.load()), static_cast<double>(stalled) * 1e-9, spec.name, spec.producer,
                   lockstep_step(due));
  });
  return m.expected.load();  // the steps run (watch() closed the pump: no step runs any more)
}

}  // namespace plexus::distributed
