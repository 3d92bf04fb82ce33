#include "plexus/distributed/realtime.hpp"

#include <spdlog/spdlog.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <numeric>
#include <optional>
#include <string_view>
#include <thread>

#include "input_guard.hpp"
#include "plexus/base/bounded_name.hpp"
#include "plexus/base/clock.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/distributed/lockstep.hpp"
#include "plexus/distributed/param_server.hpp"
#include "plexus/msg/fixed_text.hpp"
#include "plexus/runtime/naming.hpp"
#include "plexus/scenario/format.hpp"
#include "plexus/scenario/step_executor.hpp"

namespace plexus::distributed {
namespace {

using scenario::SignalSample;

/// Most ticks a host runs back to back after an overrun (more are skipped: a host that far
/// behind would only fall further behind by catching up).
constexpr int64_t kMaxCatchUpTicks = 10;

/// Most steps a deferred estimator runs behind the grid: one of its own periods. A sample
/// later than that is read late (the newest older one) and the algorithm's own rule for a
/// late sample applies (docs/distributed.md, "Late samples").
constexpr int64_t kEstimatorWaitPeriods = 1;

/// History depth of a realtime input's reader (at least): samples received between two reads.
constexpr int32_t kReaderDepth = 8;

/// The recent samples of a signal produced in another process, in step order: a read gets
/// the sample of the step it asks for when it has arrived, not merely the newest one, so a
/// sample that arrived after its tick is still read at its own step by a deferred estimator
/// or a catch-up step.
struct RemoteSamples {
  static constexpr std::size_t kKept = 32;  ///< samples kept per signal (32 periods of its producer)
  struct Entry {
    SignalSample sample;
    int64_t origin_ns = 0;  // header origin time (wall clock)
  };
  RemoteSamples(const scenario::SignalSpec& spec, rt::Participant& p, const rt::QosProfile& qos, int64_t step_ns)
      : sub(p, spec, step_ns, qos), ring(kKept) {}
  WireSubscriber sub;
  std::vector<Entry> ring;  // ring[(first + i) % kKept], i < count: oldest first
  std::size_t first = 0, count = 0;
  SignalSample scratch;
  int64_t received_ns = 0;  // monotonic, of the newest sample
  int64_t deadline_ns = 0;  // stale after this age

  /// Step of the newest sample, -1 before the first.
  int64_t newest_step() const { return count == 0 ? -1 : ring[(first + count - 1) % kKept].sample.step; }
  /// The newest sample at or before step `due`; the oldest kept if every one is newer; nullptr if none.
  const Entry* at_or_before(int64_t due) const {
    for (std::size_t i = count; i-- > 0;) {
      const Entry& e = ring[(first + i) % kKept];
      if (e.sample.step <= due) return &e;
    }
    return count == 0 ? nullptr : &ring[first];
  }
  /// Appends the decoded sample in `scratch` (a newer step than every kept one), dropping the oldest.
  void push(int64_t origin_ns) {
    if (count == kKept) {
      first = (first + 1) % kKept;
      --count;
    }
    Entry& e = ring[(first + count) % kKept];
    e.sample = scratch;
    e.origin_ns = origin_ns;
    ++count;
  }
};

/// True if a signal comes from a plant or a sensor (a measurement): its producer's kind in
/// this document, else the stage its `inputs:` entry gives (unstaged: read as a measurement).
bool physical_producer(const scenario::Scenario& sc, const scenario::SignalSpec& spec) {
  for (const auto& c : sc.components)
    if (c.component->name() == spec.producer)
      return c.kind == scenario::ComponentKind::plant || c.kind == scenario::ComponentKind::sensor;
  const auto it = sc.inputs.find(spec.name);
  if (it == sc.inputs.end() || !it->second.staged) return true;
  return it->second.stage == scenario::ComponentKind::plant || it->second.stage == scenario::ComponentKind::sensor;
}

}  // namespace

std::string health_topic(const std::string& service) {
  std::string name = service;
  for (char& c : name)
    if (!rt::topic_name_char(c)) c = '_';
  // Within the discovery limit (rt::Participant::kMaxDiscoveryName) under either naming (ROS 2
  // names put "rt/" in front): a process hosting many components has a long name; every
  // process derives the same shortened one.
  constexpr std::string_view prefix = "health/";
  const std::size_t room = rt::Participant::kMaxDiscoveryName - rt::kRos2TopicPrefix.size() - prefix.size();
  return std::string(prefix) + bounded_name(name, room);
}

namespace {
int64_t heartbeat_epoch_ns() {
  static const int64_t epoch = monotonic_ns();
  return epoch;
}
}  // namespace

msg::Heartbeat heartbeat_of(const std::string& service, const std::string& robot) {
  heartbeat_epoch_ns();
  const auto copy = [](auto& dst, const std::string& src) { msg::set_text(dst, src); };
  msg::Heartbeat hb;
  copy(hb.service(), service);
  copy(hb.robot(), robot);
  hb.pid(static_cast<uint32_t>(getpid()));
  std::array<char, 256> host{};
  if (gethostname(host.data(), host.size() - 1) != 0) host[0] = '\0';
  copy(hb.host(), host.data());
  return hb;
}

double heartbeat_uptime_s() { return static_cast<double>(monotonic_ns() - heartbeat_epoch_ns()) * 1e-9; }

double stage_phase(const scenario::Scenario& sc, const std::vector<bool>& hosted) {
  double phase = 0.0;
  for (std::size_t i = 0; i < sc.components.size() && i < hosted.size(); ++i) {
    if (!hosted[i]) continue;
    switch (sc.components[i].kind) {
      case scenario::ComponentKind::plant:
      case scenario::ComponentKind::sensor: return 0.0;  // the plants define the grid
      case scenario::ComponentKind::reference:
      case scenario::ComponentKind::estimator: phase = std::max(phase, 0.25); break;
      case scenario::ComponentKind::controller: phase = 0.5; break;
    }
  }
  return phase;
}

const rt::QosProfile& signal_qos(const scenario::Scenario& sc, const std::string& producer,
                                 const rt::QosProfiles& profiles) {
  for (const auto& c : sc.components)
    if (c.component->name() == producer && !c.qos.empty()) return profiles.get(c.qos);
  return profiles.get("state");
}

const rt::QosProfile& input_qos(const scenario::Scenario& sc, const scenario::SignalSpec& spec,
                                const rt::QosProfiles& profiles) {
  // Produced in another process: the profile its part of the scenario names (inputs:).
  if (const auto it = sc.inputs.find(spec.name); it != sc.inputs.end() && !it->second.qos.empty())
    return profiles.get(it->second.qos);
  return signal_qos(sc, spec.producer, profiles);
}

struct RealtimeHost::Impl {
  scenario::Scenario& sc;
  double phase;  // of the base period, on the run's grid (stage_phase)
  scenario::StepExecutor exec;
  RealtimeOptions opt;
  detail::InputGuard guard{opt.service};
  std::vector<std::unique_ptr<RemoteSamples>> remote;  // by signal
  std::vector<std::unique_ptr<WirePublisher>> out;     // by signal
  std::vector<int64_t> local_origin;                   // by signal: origin of the latest local sample
  std::vector<std::vector<std::size_t>> local_inputs;  // by component: the signals it reads from this process
  std::vector<bool> stop_when_stale;                   // by signal: a plant's command (zeroed when stale)
  // An estimator none of whose measurements has been fresh for its blind_after_s (its own
  // key, else clock.blind_after_s) is blind: it keeps stepping, but its outputs are not
  // published (nor passed on as fresh in this process), so that staleness reaches the
  // controllers downstream and they hold (a dead plant simulator stops them all). Shorter
  // gaps (a late sample on a loaded machine, a lost one) it bridges with its prediction.
  std::vector<std::vector<std::size_t>> measurements;  // by component: its remote inputs from plants and sensors
  std::vector<std::vector<std::size_t>> outputs_of;    // by component: the signals it produces here
  // A read is late when its newest sample is older than the step `plexus sim` would read,
  // less this slack: 0 for an input whose producer's stage is known (a part of a launch, or
  // `inputs: {stage}`), one period of the signal when it is not (a service alone), which
  // then reads the newest sample there is and counts a read late only past one period.
  std::vector<int64_t> late_slack;        // by signal
  std::vector<bool> fresh;                // by signal: the last read found it fresh
  std::vector<bool> blind;                // by signal: its producer here is blind
  std::vector<int64_t> last_measured_ns;  // by component: last tick with a fresh measurement (0: never)
  std::vector<int64_t> blind_after_ns;    // by component: its grace
  int64_t stride = 1;                     // the loop period in base steps (gcd of the hosted periods)
  std::vector<bool> deferred;             // by component: an estimator that waits for its remote samples
  std::vector<int64_t> next_step;         // by component (deferred): its next step to run
  // A host of plants and their sensors (the plant simulator) publishes the sensors' samples
  // of a step before the plants' states: the estimators in other processes read the
  // sensors a quarter period after the plant's tick, and a plant's state (the truth, which
  // the recorder reads) published first delayed each sensor sample by one write per plant
  // (each write to a socket: about 35 us on this machine, four plants in the main job).
  std::vector<bool> publish_last;  // by signal: a plant's output in a host with sensors
  std::vector<std::pair<std::size_t, const SignalSample*>> pending;  // held back this step (reserved)
  rt::Subscriber<msg::ClockStep> start;
  rt::Publisher<msg::Heartbeat> heartbeat;
  msg::Heartbeat hb;
  std::unique_ptr<ParamServer> params;  // plexus param
  // Per component being stepped: set while its inputs are read.
  bool stale = false;
  int64_t origin = 0;            // newest origin among the inputs read so far
  int64_t component_origin = 0;  // origin of the component being stepped
  RealtimeReport report;

  Impl(scenario::Scenario& s, std::vector<bool> hosted, rt::Participant& p, const rt::QosProfiles& profiles,
       RealtimeOptions o)
      : sc(s), phase(stage_phase(s, hosted)), exec(s, hosted), opt(std::move(o)) {
    const auto& signals = exec.signals();
    remote.resize(signals.size());
    out.resize(signals.size());
    local_origin.assign(signals.size(), 0);
    const auto produced = exec.local_outputs();
    local_inputs.resize(sc.components.size());
    for (std::size_t c = 0; c < sc.components.size(); ++c)
      if (exec.hosted(c))
        for (std::size_t in : exec.inputs_of(c))
          if (std::find(produced.begin(), produced.end(), in) != produced.end()) local_inputs[c].push_back(in);
    // A plant's command that goes stale is replaced by the zero command, as a motor
    // controller's watchdog does on hardware (docs/bridges.md): the robot stops.
    stop_when_stale.assign(signals.size(), false);
    for (std::size_t c = 0; c < sc.components.size(); ++c)
      if (exec.hosted(c) && sc.components[c].kind == scenario::ComponentKind::plant)
        for (std::size_t in : exec.inputs_of(c)) stop_when_stale[in] = true;
    measurements.resize(sc.components.size());
    outputs_of.resize(sc.components.size());
    late_slack.assign(signals.size(), 0);
    for (std::size_t i = 0; i < signals.size(); ++i)
      if (const auto it = sc.inputs.find(signals[i].name); sc.partial && (it == sc.inputs.end() || !it->second.staged))
        late_slack[i] = signals[i].period_steps;
    fresh.assign(signals.size(), false);
    blind.assign(signals.size(), false);
    last_measured_ns.assign(sc.components.size(), 0);
    blind_after_ns.resize(sc.components.size());
    for (std::size_t c = 0; c < sc.components.size(); ++c)
      blind_after_ns[c] = static_cast<int64_t>(sc.components[c].blind_after_s * 1e9);
    for (std::size_t i : produced)
      for (std::size_t c = 0; c < sc.components.size(); ++c)
        if (sc.components[c].component->name() == signals[i].producer) outputs_of[c].push_back(i);
    const auto remote_ins = exec.remote_inputs();
    for (std::size_t c = 0; c < sc.components.size(); ++c)
      if (exec.hosted(c))
        for (std::size_t in : exec.inputs_of(c))
          if (std::find(remote_ins.begin(), remote_ins.end(), in) != remote_ins.end() &&
              physical_producer(sc, signals[in]))
            measurements[c].push_back(in);
    stride = 0;
    deferred.assign(sc.components.size(), false);
    next_step.assign(sc.components.size(), 0);
    // A host that also runs a controller (a `process` group of estimator and controller) steps
    // its estimators in their turn, before the controller of the same tick: a deferred
    // estimator would leave that controller the previous step's estimate, one period of delay
    // inside the group's own loop (a 1 kHz arm's EKF and VDC diverged with it).
    bool hosts_controller = false;
    for (std::size_t c = 0; c < sc.components.size(); ++c)
      hosts_controller =
          hosts_controller || (exec.hosted(c) && sc.components[c].kind == scenario::ComponentKind::controller);
    for (std::size_t c = 0; c < sc.components.size(); ++c) {
      if (!exec.hosted(c)) continue;
      stride = std::gcd(stride, sc.components[c].period_steps);
      if (hosts_controller || sc.components[c].kind != scenario::ComponentKind::estimator) continue;
      for (std::size_t in : exec.inputs_of(c))
        if (std::find(remote_ins.begin(), remote_ins.end(), in) != remote_ins.end()) deferred[c] = true;
    }
    if (stride < 1) stride = 1;
    for (std::size_t i : exec.remote_inputs()) {
      // The reader keeps the last few samples, not only the newest: a producer that catches up
      // after an overrun publishes several steps at once, and each is read at its own step. A
      // plant's command keeps its profile's depth (the bridge contract's newest command,
      // docs/bridges.md): a plant applies the newest command, never an older one.
      rt::QosProfile qos = input_qos(sc, signals[i], profiles);
      if (qos.history == rt::QosProfile::History::keep_last && !stop_when_stale[i])
        qos.depth = std::max(qos.depth, kReaderDepth);
      auto r = std::make_unique<RemoteSamples>(signals[i], p, qos, step_ns(sc));
      r->deadline_ns = static_cast<int64_t>(sc.input_deadline_periods * static_cast<double>(signals[i].period_steps) *
                                            sc.step * 1e9);
      remote[i] = std::move(r);
    }
    for (std::size_t i : exec.local_outputs())
      out[i] =
          std::make_unique<WirePublisher>(p, signals[i], step_ns(sc), signal_qos(sc, signals[i].producer, profiles));
    publish_last.assign(signals.size(), false);
    bool has_sensor = false;
    for (std::size_t c = 0; c < sc.components.size(); ++c)
      has_sensor = has_sensor || (exec.hosted(c) && sc.components[c].kind == scenario::ComponentKind::sensor);
    for (std::size_t c = 0; has_sensor && c < sc.components.size(); ++c)
      if (exec.hosted(c) && sc.components[c].kind == scenario::ComponentKind::plant)
        for (std::size_t i : outputs_of[c]) publish_last[i] = true;
    pending.reserve(signals.size());
    start = p.subscriber<msg::ClockStep>(kClockTopic, profiles.get("lockstep"));
    heartbeat = p.publisher<msg::Heartbeat>(health_topic(opt.service), profiles.get("health"));
    hb = heartbeat_of(opt.service);
    params = std::make_unique<ParamServer>(s, std::move(hosted), p, opt.service);
  }

  /// True when every input read from another process has at least one matched writer.
  bool inputs_matched() const {
    for (const auto& r : remote)
      if (r && r->sub.matched_count() == 0) return false;
    return true;
  }

  void drain(std::size_t signal) {
    RemoteSamples& r = *remote[signal];
    while (const void* m = r.sub.take()) {
      if (!guard.accept(r.sub.wire(), m, r.scratch)) continue;  // refused: counted and logged
      if (r.scratch.step <= r.newest_step()) continue;          // not newer than what we have
      r.push(r.sub.header().origin_time_ns());
      r.received_ns = monotonic_ns();
    }
  }

  /// Has the sample of `signal` due at step `due` arrived (or a newer one, when it never will)?
  bool arrived(std::size_t signal, int64_t due) {
    drain(signal);
    return remote[signal]->newest_step() >= due;
  }

  void publish_heartbeat(msg::ServiceState state, const rt::LoopStats& ls) {
    hb.state(state);
    hb.loop_count(ls.iterations);
    hb.overruns(ls.overruns);
    hb.rejected_inputs(guard.rejected());
    hb.stale_inputs(report.stale_inputs);
    hb.late_inputs(report.late_inputs);
    hb.jitter_p50_us(ls.jitter_p50_us);
    hb.jitter_p99_us(ls.jitter_p99_us);
    hb.jitter_max_us(ls.jitter_max_us);
    hb.compute_p50_us(ls.compute_p50_us);
    hb.compute_p99_us(ls.compute_p99_us);
    hb.compute_max_us(ls.compute_max_us);
    hb.uptime_s(heartbeat_uptime_s());
    hb.header().origin_time_ns(0);
    heartbeat.publish(hb);
  }
};

RealtimeHost::RealtimeHost(scenario::Scenario& scenario, std::vector<bool> hosted, rt::Participant& participant,
                           const rt::QosProfiles& profiles, RealtimeOptions options)
    : impl_(std::make_unique<Impl>(scenario, std::move(hosted), participant, profiles, std::move(options))) {}

RealtimeHost::~RealtimeHost() = default;

RealtimeReport RealtimeHost::run(const std::atomic<bool>& stop) {
  Impl& m = *impl_;
  // Wait for the start signal, announcing ourselves with heartbeats meanwhile.
  const int64_t give_up = monotonic_ns() + static_cast<int64_t>(m.opt.start_timeout_s * 1e9);
  msg::ClockStep go;
  go.sim_time_ns(0);  // alone: the grid starts now
  int64_t next_hb = 0;
  bool was_ready = false;
  if (m.opt.wait_for_start)
    spdlog::info("{}: waiting up to {} s for the start signal of plexus launch", m.opt.service,
                 scenario::format_number(m.opt.start_timeout_s));
  while (m.opt.wait_for_start && !m.start.take(go)) {
    if (stop) return m.report;
    const int64_t now = monotonic_ns();
    if (now > give_up)
      throw InputError(m.opt.service + ": no start signal from plexus launch within " +
                       scenario::format_number(m.opt.start_timeout_s) +
                       " s (--start-signal waits for a launcher; without it the service starts at once)");
    // Ready (WAITING) only once every input from another process has a matched writer: the
    // launcher starts the run when every process is ready, so that no loop starts on inputs
    // whose discovery is still under way (on a lossy link, seconds) and holds its safe output
    // meanwhile. Until then CONFIGURING; the change is announced at once.
    const bool ready = m.inputs_matched();
    if (now >= next_hb || ready != was_ready) {
      m.publish_heartbeat(ready ? msg::SERVICE_WAITING : msg::SERVICE_CONFIGURING, {});
      next_hb = now + 200'000'000;
      was_ready = ready;
    }
    m.start.wait(50'000'000);
  }

  // The start signal carries the run's start T0 (wall clock). Step k is due at
  // T0 + (k + phase) base periods. The loop ticks at the host's own period, `stride` base
  // steps (the greatest common divisor of its components' periods: a host of 100 Hz services
  // on a 1 kHz grid wakes 100 times a second, not 1000), on the steps that are multiples of
  // it. The first such step still ahead is this host's first, so a host restarted mid-run
  // joins at the current tick instead of replaying the run from 0.
  const int64_t step_ns = std::llround(m.sc.step * 1e9);  // the base period, as PeriodicLoop rounds it
  const int64_t stride = m.stride;
  const auto offset_ns = static_cast<int64_t>(m.phase * static_cast<double>(step_ns));
  const int64_t wall_now = wall_time_ns(), mono_now = monotonic_ns();
  // Without a launcher (a service started by hand) the run starts at the wall clock's next
  // whole second: every such service of the host (of every host whose clock is synchronised)
  // then steps on one grid, with the phases above, as under plexus launch. Each starting at
  // its own moment, their grids were offset at random, and so was the delay from a sample to
  // the loop that reads it: the balancing robot's loop, run by hand from deploy/params, went
  // into a 10 Hz oscillation and fell in 1 of 6 runs (services.standalone_life_cycle; issue 33).
  const int64_t t0 = go.sim_time_ns() > 0 ? go.sim_time_ns() : (wall_now / 1'000'000'000 + 1) * 1'000'000'000;
  const int64_t late_ns = wall_now - t0 - offset_ns;  // past this host's step 0 by
  const int64_t k0 = late_ns < 0 ? 0 : (late_ns / step_ns / stride + 1) * stride;
  const int64_t first_deadline = mono_now + (t0 + k0 * step_ns + offset_ns - wall_now);
  // Data times are wall-clock times on the run's grid (wire.hpp): step k is at t0 + k periods.
  for (auto& w : m.out)
    if (w) w->wire().set_epoch(t0);
  m.params->set_epoch(t0);  // a reply's data time is its step's, on the run's grid
  m.params->set_pending_step([&m](std::size_t c) -> std::optional<int64_t> {
    if (m.deferred[c]) return m.next_step[c];  // a waiting estimator runs its older steps first
    return std::nullopt;
  });
  for (auto& r : m.remote)
    if (r) r->sub.wire().set_epoch(t0);
  rt::LoopOptions lo = m.opt.loop;
  lo.rate_hz = 1.0 / (m.sc.step * static_cast<double>(stride));
  rt::PeriodicLoop loop(lo);
  const scenario::StepExecutor::RemoteInput read = [&m](std::size_t signal, int64_t due, SignalSample& s) {
    m.drain(signal);
    const RemoteSamples& r = *m.remote[signal];
    const RemoteSamples::Entry* e = r.at_or_before(due);
    if (e == nullptr) {
      s = SignalSample{};  // never received
    } else {
      s = e->sample;
      if (s.step < due - m.late_slack[signal]) ++m.report.late_inputs;  // the sample it expects has not arrived
      m.origin = std::max(m.origin, e->origin_ns);
    }
    const bool stale = e == nullptr || monotonic_ns() - r.received_ns > r.deadline_ns;
    m.fresh[signal] = !stale;
    if (stale) {
      m.stale = true;
      ++m.report.stale_inputs;
      if (m.stop_when_stale[signal]) std::fill(s.values.begin(), s.values.end(), 0.0);
    }
  };
  const scenario::StepExecutor::Gate gate = [&m](std::size_t component) {
    const auto kind = m.sc.components[component].kind;
    bool stale = m.stale;
    for (std::size_t s : m.local_inputs[component]) stale = stale || m.blind[s];  // a blind estimator in this process
    const bool hold = stale && kind == scenario::ComponentKind::controller;
    m.stale = false;
    if (kind == scenario::ComponentKind::estimator) {
      const auto& ms = m.measurements[component];
      const int64_t now = monotonic_ns();
      if (std::any_of(ms.begin(), ms.end(), [&m](std::size_t s) { return m.fresh[s]; }))
        m.last_measured_ns[component] = now;
      const int64_t last = m.last_measured_ns[component];
      const bool blind = !ms.empty() && (last == 0 || now - last > m.blind_after_ns[component]);
      for (std::size_t s : m.outputs_of[component]) m.blind[s] = blind;
      if (blind) ++m.report.blind_steps;
    }
    // Its inputs are read: its outputs carry the newest origin among them, local or remote.
    // A measurement starts a chain (origin 0: set when published); a component that read no
    // measurement (a reference) marks its outputs as such.
    int64_t origin = m.origin;
    for (std::size_t s : m.local_inputs[component]) origin = std::max(origin, m.local_origin[s]);
    if (kind == scenario::ComponentKind::plant || kind == scenario::ComponentKind::sensor)
      origin = 0;
    else if (origin == 0)
      origin = kNoMeasurementOrigin;
    m.component_origin = origin;
    m.origin = 0;  // the next component starts afresh
    if (hold) ++m.report.holds;
    return !hold;
  };
  const scenario::StepExecutor::OutputSink publish = [&](std::size_t signal, const SignalSample& s) {
    if (m.blind[signal]) return;  // computed from no fresh measurement: not published
    if (m.publish_last[signal]) {
      m.pending.push_back({signal, &s});  // after the step's sensor samples (Impl::publish_last)
      return;
    }
    m.out[signal]->publish(s, m.component_origin);          // origin 0: this sample starts a chain (stamped now)
    m.local_origin[signal] = m.out[signal]->last_origin();  // for readers in this process
  };
  // The plants' states held back by `publish`, once the step's sensor samples are out (the
  // samples stay in their output ports until the plant's next step).
  const auto publish_pending = [&m] {
    for (const auto& [signal, sample] : m.pending) {
      m.out[signal]->publish(*sample, 0);
      m.local_origin[signal] = m.out[signal]->last_origin();
    }
    m.pending.clear();
  };
  const int64_t ticks = m.sc.steps + 1;
  if (k0 >= ticks) return m.report;  // joined after the end of the run
  // Runs step j of every hosted component. An estimator that reads samples from another
  // process runs its step once they have arrived (each at the step it belongs to, as in
  // `plexus sim`), at most kEstimatorWaitPeriods of its periods behind the grid; then with
  // what has arrived (late reads, counted). Its output is that step's, published later.
  const auto arrived = [&m](std::size_t sig, int64_t due) { return m.arrived(sig, due); };
  const int64_t startup_ticks = StartupWait::ticks(m.sc.step * static_cast<double>(stride));
  const auto run_step = [&](int64_t j) {
    m.params->serve(j);  // between two ticks: a change takes effect at step j, acknowledged with it
    const bool starting = k0 == 0 && j < startup_ticks * stride;
    const int64_t wait_until = starting ? monotonic_ns() + StartupWait::kWaitPeriods * loop.period_ns() : 0;
    for (std::size_t c = 0; c < m.sc.components.size(); ++c) {
      if (!m.exec.hosted(c)) continue;
      if (starting) {  // the run's start: wait for this step's samples, two periods at most for the step
        while (!m.exec.remote_inputs_ready(c, j, arrived) && monotonic_ns() < wait_until && !stop.load())
          std::this_thread::sleep_for(std::chrono::microseconds(20));
      }
      if (!m.deferred[c]) {
        m.exec.step_component(c, j, read, publish, gate);
        continue;
      }
      const int64_t period = m.sc.components[c].period_steps;
      int64_t& next = m.next_step[c];
      // Steps lost to an overrun beyond the catch-up are skipped, as for every component.
      const int64_t oldest = j - kMaxCatchUpTicks * stride - kEstimatorWaitPeriods * period;
      if (next < oldest) next = (oldest + period - 1) / period * period;
      while (next <= j) {
        const bool ready = m.exec.remote_inputs_ready(c, next, arrived);
        if (!ready && j < ticks - 1 && j - next < kEstimatorWaitPeriods * period) break;  // wait for its samples
        if (next < j) ++m.report.deferred_steps;
        m.exec.step_component(c, next, read, publish, gate);
        next += period;
      }
    }
    publish_pending();
  };
  for (std::size_t c = 0; c < m.sc.components.size(); ++c) {
    const int64_t period = m.sc.components[c].period_steps;
    m.next_step[c] = (k0 + period - 1) / period * period;
  }
  const int64_t hb_every = std::max<int64_t>(1, static_cast<int64_t>(1.0 / m.sc.step));
  int64_t next_beat = k0;
  uint64_t holds_at_beat = m.report.holds;  // DEGRADED: a hold since the previous heartbeat
  int64_t last_k = k0 - stride;
  loop.run(
      [&](const rt::PeriodicLoop::Tick& t) {
        // The step is the grid's, from the deadline: after an overrun the loop skips the periods
        // it missed, and so does the step, so every host keeps the same step at the same time.
        // The steps skipped (up to kMaxCatchUpTicks ticks) still run first, back to back: a plant
        // integrates them with the command it holds and an estimator predicts over them, so
        // neither falls behind the grid's time by the periods it lost.
        const int64_t k = std::min(ticks - 1, k0 + (t.deadline_ns - first_deadline) / loop.period_ns() * stride);
        for (int64_t j = std::max(last_k + stride, k - kMaxCatchUpTicks * stride); j < k; j += stride) run_step(j);
        last_k = k;
        run_step(k);
        if (k >= next_beat) {
          m.publish_heartbeat(m.report.holds > holds_at_beat ? msg::SERVICE_DEGRADED : msg::SERVICE_RUNNING,
                              loop.stats());
          holds_at_beat = m.report.holds;
          next_beat = k + hb_every;
        }
        m.report.ticks = k + 1;
        return k + 1 < ticks && !stop.load(std::memory_order_relaxed);
      },
      first_deadline);
  m.report.loop = loop.stats();
  for (std::size_t c = 0; c < m.sc.components.size(); ++c)
    if (m.exec.hosted(c)) m.report.dropped_late_samples += m.sc.components[c].component->dropped_late_samples();
  m.report.rejected_inputs = m.guard.rejected();
  m.publish_heartbeat(msg::SERVICE_DRAINING, m.report.loop);
  // The last beat carries the final loop figures, and the launcher waits for it: delivered
  // before this host's writer goes away (bounded: a launcher that is gone does not ack).
  m.heartbeat.wait_for_acks(1'000'000'000);
  return m.report;
}

}  // namespace plexus::distributed
