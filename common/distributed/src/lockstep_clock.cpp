// LockstepClock (lockstep.hpp): the clock records every signal on the DDS receive threads.
// Each sample that arrives pokes the pump, and the thread that received it records as many
// samples, in step and signal order, as have arrived, publishing a tick as each step
// completes; the next sample resumes where it stopped (docs/performance.md, section 4). The
// run thread only watches: the stop flag, the bounded wait for each sample, the end.
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <thread>

#include "input_guard.hpp"
#include "lockstep_text.hpp"
#include "plexus/base/clock.hpp"
#include "plexus/distributed/lockstep.hpp"
#include "pumped_run.hpp"

namespace plexus::distributed {

using scenario::SignalSample;
using scenario::SignalSpec;

int64_t step_ns(const scenario::Scenario& sc) { return std::llround(sc.step * 1e9); }

struct LockstepClock::Impl {
  // Declared first, destroyed last: the readers' callbacks (destroyed before) use them.
  detail::PumpedRun run{[this] { advance(); }};
  // Written by the pump, read by the run thread for its messages: the sample awaited.
  std::atomic<int64_t> at_step{0};
  std::atomic<std::size_t> at_signal{0};

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

  // The run, as the pump's thread goes through it.
  scenario::RunLog* log = nullptr;
  const scenario::StepObserver* observer = nullptr;
  const SampleTap* tap = nullptr;
  int64_t lead = 0, stride = 1;
  int64_t k = 0;                   // the step being recorded
  std::size_t s = 0;               // the signal of step k awaited
  bool ticked = false;             // whether step k's tick (if it has one) went out
  int64_t released = 0;            // wall time of the tick that released step k
  std::vector<int64_t> tick_wall;  // by tick step, a ring
  msg::ClockStep tick;
  SignalSample sample;
  rt::SampleMeta meta;

  Impl(scenario::Scenario& s, rt::Participant& p, const rt::QosProfile& qos, LockstepOptions o)
      : sc(s), exec(s, std::vector<bool>(s.components.size(), false)), opt(o) {
    clock = p.publisher<msg::ClockStep>(kClockTopic, qos);
    for (const auto& spec : exec.signals()) {
      subs.push_back(std::make_unique<WireSubscriber>(p, spec, step_ns(sc), qos));
      subs.back()->on_data([this] { run.poke(); });
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

  /// A producer's response runs from the tick that released its step: a host may run `lead`
  /// steps past the latest tick, so step k is released by the first tick at or after k - lead
  /// (ticks come every `stride` steps). Timed from tick k itself instead, a host that had run
  /// ahead answered "before" the tick: negative responses (launch.json, response_p50_us -470).
  int64_t released_at(int64_t step) const {
    const int64_t first = std::max<int64_t>(0, step - lead);
    const int64_t j = std::min(step, (first + stride - 1) / stride * stride);
    return tick_wall[static_cast<std::size_t>(j) % tick_wall.size()];
  }

  /// The pump's work: records every sample that has arrived, in step and signal order, and
  /// ticks as the steps complete. Every signal due at step k, from every host: then step k
  /// is complete everywhere.
  void advance() noexcept {
    if (run.finished()) return;
    try {
      const auto& signals = exec.signals();
      const int64_t step_ns = lockstep_ns(sc.step);
      for (; k <= sc.steps; ++k, s = 0, ticked = false) {
        if (!ticked) {
          if (k % stride == 0 || k == sc.steps) {
            tick.step_index(static_cast<uint64_t>(k));
            tick.sim_time_ns(k * step_ns);
            tick.step_ns(step_ns);
            tick.header().origin_time_ns(0);
            tick.header().data_time_ns(k * step_ns);
            // Stamped before it is sent (producers stamp their samples' publish time on the
            // wall clock): a producer waiting for this tick can answer before publish() returns.
            tick_wall[static_cast<std::size_t>(k) % tick_wall.size()] = wall_time_ns();
            clock.publish(tick);
          }
          released = released_at(k);
          ticked = true;
        }
        for (; s < signals.size(); ++s) {
          if (k % signals[s].period_steps != 0) continue;
          const void* in = subs[s]->take(&meta);
          if (in == nullptr) {
            at_step.store(k, std::memory_order_relaxed);
            at_signal.store(s, std::memory_order_relaxed);
            return;  // the sample will poke again
          }
          // The first `lead` steps are left out: every host is still joining, and tick 0 releases them all.
          if (k > lead) note_response(s, subs[s]->header().publish_time_ns() - released);
          if (*tap) (*tap)(s, subs[s]->wire().support(), in, meta, subs[s]->raw());
          if (!guard.accept(subs[s]->wire(), in, sample))
            throw LockstepError("lockstep: refused the sample of '" + signals[s].name + "' from '" +
                                signals[s].producer + "' for " + lockstep_step(k) + " (reason logged above)");
          if (sample.step != k)
            throw LockstepError("lockstep: '" + signals[s].name + "' sent step " + std::to_string(sample.step) +
                                " while the clock is at " + lockstep_step(k));
          log->record(s, sample);
          run.progress();
        }
        if (*observer && (k % 128 == 0 || k == sc.steps)) (*observer)(k, sc.steps);
      }
      run.finish();
    } catch (...) {
      run.finish(std::current_exception());
    }
  }
};

LockstepClock::LockstepClock(scenario::Scenario& scenario, rt::Participant& participant, const rt::QosProfile& qos,
                             LockstepOptions options)
    : impl_(std::make_unique<Impl>(scenario, participant, qos, options)) {}

LockstepClock::~LockstepClock() = default;

void LockstepClock::wait_ready(int hosts, double timeout_s, const std::atomic<bool>& stop) {
  Impl& m = *impl_;
  const int64_t deadline = monotonic_ns() + lockstep_ns(timeout_s);
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
      throw LockstepError("lockstep: " + missing + " did not join within " + lockstep_seconds(timeout_s));
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
  if (tap)
    for (auto& sub : m.subs) sub->keep_raw();  // the tap gets the bytes as received
  m.log = &log;
  m.observer = &observer;
  m.tap = &tap;
  m.lead = std::clamp<int64_t>(m.opt.lead_steps, 0, kMaxLeadSteps);
  m.stride = clock_stride(m.opt);
  m.tick_wall.assign(static_cast<std::size_t>(m.lead + 2 * m.stride + 1), 0);
  const int64_t timeout = lockstep_ns(m.opt.timeout_s);
  const auto awaited = [&m, &signals]() -> const SignalSpec& {
    return signals[m.at_signal.load(std::memory_order_relaxed)];
  };
  const bool done = m.run.watch(stop, [&m, &awaited, timeout](int64_t stalled, bool tell) {
    const int64_t k = m.at_step.load(std::memory_order_relaxed);
    const SignalSpec& spec = awaited();
    if (stalled >= timeout)
      throw LockstepError("lockstep: no sample of '" + spec.name + "' from '" + spec.producer + "' for " +
                              lockstep_step(k) + " within " + lockstep_seconds(m.opt.timeout_s),
                          spec.producer);
    if (tell)  // every wait of a second or more, with its step and producer, to find a stall
      spdlog::warn("lockstep: the clock has waited {:.1f} s for '{}' (produced by '{}') of {}",
                   static_cast<double>(stalled) * 1e-9, spec.name, spec.producer, lockstep_step(k));
  });
  if (!done)
    throw LockstepError("lockstep: stopped at " + lockstep_step(m.at_step.load(std::memory_order_relaxed)) +
                        ", waiting for the sample of '" + awaited().name + "' from '" + awaited().producer + "'");
  m.tick.step_index(kEndOfRun);
  m.clock.publish(m.tick);
  // Deleting the writer drops an unacknowledged sample: without this wait a host could miss
  // the end of the run and wait for a step that never comes.
  if (!m.clock.wait_for_acks(timeout))
    spdlog::warn("lockstep: not every host acknowledged the end of the run within {} s", m.opt.timeout_s);
  return log;
}

}  // namespace plexus::distributed
