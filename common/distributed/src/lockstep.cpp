#include "plexus/distributed/lockstep.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <thread>

#include "input_guard.hpp"
#include "plexus/base/clock.hpp"
#include "plexus/distributed/param_server.hpp"
#include "plexus/scenario/format.hpp"

namespace plexus::distributed {
namespace {

using scenario::SignalSample;
using scenario::SignalSpec;

int64_t to_ns(double s) { return static_cast<int64_t>(s * 1e9); }

std::string step_text(int64_t k) { return "step " + std::to_string(k); }
/// "0.5 s", "30 s": a duration as set, not truncated to whole seconds.
std::string seconds_text(double s) { return scenario::format_number(s) + " s"; }

/// The latest samples received of one remote signal, by step.
class RemoteSignal {
 public:
  RemoteSignal(const SignalSpec& spec, rt::Participant& p, const rt::QosProfile& qos, int64_t step_ns,
               detail::InputGuard& guard)
      : spec_(&spec), sub_(p, spec, step_ns, qos), guard_(&guard) {}

  /// Copies the sample produced at step `due` into `out`, waiting for it up to `timeout_ns`.
  void get(int64_t due, int64_t timeout_ns, SignalSample& out) {
    const int64_t deadline = monotonic_ns() + timeout_ns;
    for (;;) {
      const Entry& e = ring_[slot(due)];
      if (e.sample.step == due) {
        out = e.sample;
        return;
      }
      drain();
      if (ring_[slot(due)].sample.step == due) continue;
      const int64_t now = monotonic_ns();
      if (now >= deadline)
        throw LockstepError("lockstep: no sample of '" + spec_->name + "' (produced by '" + spec_->producer +
                            "') for " + step_text(due) + " within " +
                            seconds_text(static_cast<double>(timeout_ns) * 1e-9));
      sub_.wait(deadline - now);
    }
  }

  /// Takes every received sample into the ring.
  void drain() {
    while (const void* m = sub_.take()) {
      if (guard_->accept(sub_.wire(), m, scratch_)) ring_[slot(scratch_.step)].sample = scratch_;
    }
  }

  const SignalSpec& spec() const { return *spec_; }

 private:
  struct Entry {
    SignalSample sample;
  };
  std::size_t slot(int64_t step) const {
    return static_cast<std::size_t>((step / spec_->period_steps) % static_cast<int64_t>(kRing));
  }
  static constexpr std::size_t kRing = 32;
  const SignalSpec* spec_;
  WireSubscriber sub_;
  detail::InputGuard* guard_;
  SignalSample scratch_;
  std::array<Entry, kRing> ring_{};
};

}  // namespace

int64_t step_ns(const scenario::Scenario& sc) { return std::llround(sc.step * 1e9); }

// --- host -------------------------------------------------------------------

struct LockstepHost::Impl {
  scenario::Scenario& sc;
  scenario::StepExecutor exec;
  LockstepOptions opt;
  detail::InputGuard guard{"lockstep host"};
  rt::Subscriber<msg::ClockStep> clock;
  std::vector<std::unique_ptr<RemoteSignal>> remote;  // indexed by signal (null if not remote)
  std::vector<std::unique_ptr<WirePublisher>> out;    // indexed by signal (null if not local)
  std::unique_ptr<ParamServer> params;                // plexus param, when the host has a service name

  Impl(scenario::Scenario& s, std::vector<bool> hosted, rt::Participant& p, const rt::QosProfile& qos,
       LockstepOptions o)
      : sc(s), exec(s, hosted), opt(o) {
    clock = p.subscriber<msg::ClockStep>(kClockTopic, qos);
    if (!opt.service.empty()) params = std::make_unique<ParamServer>(s, std::move(hosted), p, opt.service);
    const auto& signals = exec.signals();
    remote.resize(signals.size());
    out.resize(signals.size());
    for (std::size_t i : exec.remote_inputs())
      remote[i] = std::make_unique<RemoteSignal>(signals[i], p, qos, step_ns(sc), guard);
    for (std::size_t i : exec.local_outputs())
      out[i] = std::make_unique<WirePublisher>(p, signals[i], step_ns(sc), qos);
  }
};

LockstepHost::LockstepHost(scenario::Scenario& scenario, std::vector<bool> hosted, rt::Participant& participant,
                           const rt::QosProfile& qos, LockstepOptions options)
    : impl_(std::make_unique<Impl>(scenario, std::move(hosted), participant, qos, options)) {}

LockstepHost::~LockstepHost() = default;

int64_t LockstepHost::run(const std::atomic<bool>& stop) {
  Impl& m = *impl_;
  const int64_t timeout = to_ns(m.opt.timeout_s);
  const scenario::StepExecutor::RemoteInput remote = [&m, timeout](std::size_t signal, int64_t due, SignalSample& s) {
    m.remote[signal]->get(due, timeout, s);
  };
  const scenario::StepExecutor::OutputSink publish = [&m](std::size_t signal, const SignalSample& s) {
    if (!m.out[signal]->publish(s, 0))
      throw LockstepError("lockstep: cannot publish '" + m.exec.signals()[signal].name + "' at " + step_text(s.step));
  };
  // ClockStep k allows steps up to k + lead: a host runs ahead of the clock as far as its
  // inputs allow (each remote input is waited for exactly, so the result cannot change), which
  // takes the clock's round trip off the critical path of a closed loop.
  const int64_t lead = std::clamp<int64_t>(m.opt.lead_steps, 0, kMaxLeadSteps);
  msg::ClockStep tick;
  int64_t steps = 0;
  int64_t expected = 0;
  int64_t allowed = -1;  // the last step the clock allows
  int64_t last_tick = monotonic_ns();
  while (!stop.load(std::memory_order_relaxed)) {
    bool ended = false;
    while (m.clock.take(tick)) {
      last_tick = monotonic_ns();
      if (tick.step_index() == kEndOfRun) {
        ended = true;
        break;
      }
      allowed = std::max(allowed, static_cast<int64_t>(tick.step_index()) + lead);  // repeats (late join) are harmless
    }
    if (ended) break;
    if (expected <= std::min(allowed, m.sc.steps)) {
      if (m.params) m.params->serve(expected);  // a change takes effect at a step of the clock's
      m.exec.step(expected, remote, publish);
      ++expected;
      ++steps;
      continue;
    }
    // Every step done and the clock's writer gone: the run ended even if the end-of-run
    // mark never reached us (the clock waits for its acknowledgement, but bounded).
    if (expected > m.sc.steps && m.clock.matched_count() == 0) break;
    // The clock waits for our outputs, so silence here means the clock is gone; the
    // launcher's timeout covers a slow run, this one a dead launcher.
    if (monotonic_ns() - last_tick > 3 * timeout)
      throw LockstepError((allowed < 0 ? "lockstep: no clock: no step on '" + std::string(kClockTopic) + "'"
                                       : "lockstep: the clock stopped at " + step_text(expected)) +
                          " for more than " + seconds_text(static_cast<double>(3 * timeout) * 1e-9));
    m.clock.wait(100'000'000);
  }
  return steps;
}

// --- clock ------------------------------------------------------------------

struct LockstepClock::Impl {
  scenario::Scenario& sc;
  scenario::StepExecutor exec;  // wiring only (nothing hosted): the signal list, same indices everywhere
  LockstepOptions opt;
  rt::Publisher<msg::ClockStep> clock;
  std::vector<std::unique_ptr<WireSubscriber>> subs;  // by signal
  detail::InputGuard guard{"lockstep clock"};
  // Response times (ns) since the last producer_status(), per producer.
  std::vector<std::string> producers;
  std::vector<std::size_t> producer_of;  // by signal
  std::vector<std::vector<int64_t>> response;
  std::vector<std::size_t> response_count;
  std::vector<int64_t> scratch;
  static constexpr std::size_t kWindow = 4096;

  Impl(scenario::Scenario& s, rt::Participant& p, const rt::QosProfile& qos, LockstepOptions o)
      : sc(s), exec(s, std::vector<bool>(s.components.size(), false)), opt(o) {
    clock = p.publisher<msg::ClockStep>(kClockTopic, qos);
    for (const auto& spec : exec.signals()) {
      subs.push_back(std::make_unique<WireSubscriber>(p, spec, step_ns(sc), qos));
      auto it = std::find(producers.begin(), producers.end(), spec.producer);
      producer_of.push_back(static_cast<std::size_t>(it - producers.begin()));
      if (it == producers.end()) producers.push_back(spec.producer);
    }
    response.assign(producers.size(), std::vector<int64_t>(kWindow));
    response_count.assign(producers.size(), 0);
    scratch.resize(kWindow);
  }

  void note_response(std::size_t signal, int64_t ns) {
    const std::size_t p = producer_of[signal];
    response[p][response_count[p]++ % kWindow] = ns;
  }
};

LockstepClock::LockstepClock(scenario::Scenario& scenario, rt::Participant& participant, const rt::QosProfile& qos,
                             LockstepOptions options)
    : impl_(std::make_unique<Impl>(scenario, participant, qos, options)) {}

LockstepClock::~LockstepClock() = default;

void LockstepClock::wait_ready(int hosts, double timeout_s, const std::atomic<bool>& stop) {
  Impl& m = *impl_;
  const int64_t deadline = monotonic_ns() + to_ns(timeout_s);
  for (;;) {
    std::string missing;
    if (m.clock.matched_count() < hosts)
      missing = std::to_string(hosts - m.clock.matched_count()) + " of " + std::to_string(hosts) + " hosts";
    for (std::size_t i = 0; i < m.subs.size() && missing.empty(); ++i)
      if (m.subs[i]->matched_count() == 0)
        missing = "the producer of '" + m.exec.signals()[i].name + "' ('" + m.exec.signals()[i].producer + "')";
    if (missing.empty()) return;
    if (stop) throw LockstepError("lockstep: stopped while waiting for " + missing);
    if (monotonic_ns() > deadline)
      throw LockstepError("lockstep: " + missing + " did not join within " + seconds_text(timeout_s));
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

const std::vector<SignalSpec>& LockstepClock::signals() const { return impl_->exec.signals(); }

void LockstepClock::producer_status(std::vector<ProducerStatus>& out) {
  Impl& m = *impl_;
  out.resize(m.producers.size());
  for (std::size_t p = 0; p < m.producers.size(); ++p) {
    ProducerStatus& st = out[p];
    if (st.producer != m.producers[p]) st.producer = m.producers[p];
    const std::size_t n = std::min(m.response_count[p], Impl::kWindow);
    st.samples = m.response_count[p];
    std::copy_n(m.response[p].begin(), n, m.scratch.begin());
    auto at = [&](double q) {
      if (n == 0) return 0.0;
      const auto i = static_cast<std::ptrdiff_t>(q * static_cast<double>(n - 1));
      std::nth_element(m.scratch.begin(), m.scratch.begin() + i, m.scratch.begin() + static_cast<std::ptrdiff_t>(n));
      return static_cast<double>(m.scratch[static_cast<std::size_t>(i)]) * 1e-3;
    };
    st.response_p50_us = at(0.5);
    st.response_p99_us = at(0.99);
    st.response_max_us = at(1.0);
    m.response_count[p] = 0;
  }
}

scenario::RunLog LockstepClock::run(const std::atomic<bool>& stop, const scenario::StepObserver& observer,
                                    const SampleTap& tap) {
  Impl& m = *impl_;
  const auto& signals = m.exec.signals();
  scenario::RunLog log;
  log.base_step = m.sc.step;
  log.steps = m.sc.steps;
  log.signals.resize(signals.size());
  for (std::size_t s = 0; s < signals.size(); ++s) {
    auto& trace = log.signals[s];
    trace.spec = signals[s];
    const auto samples = static_cast<std::size_t>(m.sc.steps / trace.spec.period_steps + 1);
    trace.steps.reserve(samples);
    trace.values.reserve(samples * trace.width());
  }
  const int64_t timeout = to_ns(m.opt.timeout_s);
  const int64_t step_ns = to_ns(m.sc.step);
  const int64_t stride = clock_stride(m.opt);
  msg::ClockStep tick;
  SignalSample sample;
  rt::SampleMeta meta;
  if (tap)
    for (auto& sub : m.subs) sub->keep_raw();  // the tap gets the bytes as received
  // A producer's response runs from the tick that released its step: a host may run `lead`
  // steps past the latest tick, so step k is released by the first tick at or after k - lead
  // (ticks come every `stride` steps). Timed from tick k itself instead, a host that had run
  // ahead answered "before" the tick: negative responses (launch.json, response_p50_us -470).
  // The first `lead` steps are left out: every host is still joining, and tick 0 releases them all.
  const int64_t lead = std::clamp<int64_t>(m.opt.lead_steps, 0, kMaxLeadSteps);
  std::vector<int64_t> tick_wall(static_cast<std::size_t>(lead + 2 * stride + 1), 0);  // by tick step, a ring
  const auto released_at = [&](int64_t k) {
    const int64_t first = std::max<int64_t>(0, k - lead);
    const int64_t j = std::min(k, (first + stride - 1) / stride * stride);
    return tick_wall[static_cast<std::size_t>(j) % tick_wall.size()];
  };
  for (int64_t k = 0; k <= m.sc.steps; ++k) {
    if (stop.load(std::memory_order_relaxed)) throw LockstepError("lockstep: stopped at " + step_text(k));
    tick.step_index(static_cast<uint64_t>(k));
    tick.sim_time_ns(k * step_ns);
    tick.step_ns(step_ns);
    tick.header().origin_time_ns(0);
    tick.header().data_time_ns(k * step_ns);
    if (k % stride == 0 || k == m.sc.steps) {
      // Stamped before it is sent (producers stamp their samples' publish time on the wall
      // clock): a producer waiting for this tick can answer before publish() returns here.
      tick_wall[static_cast<std::size_t>(k) % tick_wall.size()] = wall_time_ns();
      m.clock.publish(tick);
    }
    const int64_t published = released_at(k);
    // Every signal due at step k, from every host: then step k is complete everywhere.
    for (std::size_t s = 0; s < signals.size(); ++s) {
      if (k % signals[s].period_steps != 0) continue;
      const int64_t deadline = monotonic_ns() + timeout;
      for (;;) {
        if (const void* in = m.subs[s]->take(&meta)) {
          if (k > lead) m.note_response(s, m.subs[s]->header().publish_time_ns() - published);
          if (tap) tap(s, m.subs[s]->wire().support(), in, meta, m.subs[s]->raw());
          if (!m.guard.accept(m.subs[s]->wire(), in, sample))
            throw LockstepError("lockstep: refused the sample of '" + signals[s].name + "' from '" +
                                signals[s].producer + "' for " + step_text(k) + " (reason logged above)");
          if (sample.step != k)
            throw LockstepError("lockstep: '" + signals[s].name + "' sent step " + std::to_string(sample.step) +
                                " while the clock is at " + step_text(k));
          log.record(s, sample);
          break;
        }
        const int64_t now = monotonic_ns();
        if (now >= deadline || stop.load(std::memory_order_relaxed))
          throw LockstepError("lockstep: no sample of '" + signals[s].name + "' from '" + signals[s].producer +
                              "' for " + step_text(k) + " within " + seconds_text(m.opt.timeout_s));
        m.subs[s]->wait(std::min<int64_t>(deadline - now, 100'000'000));
      }
    }
    if (observer && (k % 128 == 0 || k == m.sc.steps)) observer(k, m.sc.steps);
  }
  tick.step_index(kEndOfRun);
  m.clock.publish(tick);
  // Deleting the writer drops an unacknowledged sample: without this wait a host could miss
  // the end of the run and wait for a step that never comes.
  if (!m.clock.wait_for_acks(timeout))
    spdlog::warn("lockstep: not every host acknowledged the end of the run within {} s", m.opt.timeout_s);
  return log;
}

}  // namespace plexus::distributed
