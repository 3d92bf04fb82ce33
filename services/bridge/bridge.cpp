#include "bridge.hpp"

#include <fcntl.h>
#include <poll.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <thread>
#include <vector>

#include "bridge_routes.hpp"
#include "plexus/base/clock.hpp"
#include "plexus/base/logging.hpp"
#include "plexus/distributed/lockstep.hpp"
#include "plexus/distributed/realtime.hpp"
#include "plexus/link/device_clock.hpp"
#include "plexus/link/frame.hpp"
#include "plexus/link/protocol.hpp"

namespace plexus::bridge {
namespace {

constexpr int64_t kSecond = 1'000'000'000;
constexpr std::size_t kLatencyWindow = 16384;  // most recent frames kept for percentiles
constexpr std::size_t kMaxCommandFields = link::kMaxFields;

/// A command on its way from the command thread to the I/O thread (through a pipe: one
/// write of a trivially copyable record below PIPE_BUF is atomic, and neither side locks).
struct CommandMessage {
  int64_t expires_mono;  ///< the command is stale after this (CLOCK_MONOTONIC ns)
  double values[kMaxCommandFields];
};
static_assert(sizeof(CommandMessage) <= PIPE_BUF);

int64_t ns_of(double s) { return static_cast<int64_t>(s * 1e9); }

/// Counters shared between the two threads (relaxed: each has one writer).
struct SharedCounters {
  std::atomic<bool> up{false};
  std::atomic<uint64_t> frames_in{0}, frames_out{0}, crc_errors{0}, framing_errors{0}, oversize{0}, resyncs{0},
      bytes_discarded{0}, rejected_frames{0}, reconnects{0}, disconnects{0}, stale_commands{0}, stop_frames{0},
      tx_errors{0}, commands_forwarded{0}, commands_refused{0}, unsynced_frames{0}, clock_exchanges{0},
      clock_restarts{0}, cycle_syncs{0};
  std::atomic<double> latency_p50_us{0}, latency_p99_us{0}, latency_max_us{0}, clock_offset_s{0}, clock_drift_ppm{0},
      clock_uncertainty_us{0};
};

}  // namespace

struct Bridge::Impl {
  BridgeRoutes routes;
  std::unique_ptr<DeviceLink> link;
  BridgeOptions opt;
  rt::Publisher<msg::Heartbeat> heartbeat;
  msg::Heartbeat hb;
  int pipe_r = -1, pipe_w = -1;
  SharedCounters c;

  // I/O thread only.
  link::FrameDecoder decoder;
  std::array<uint16_t, 256> tx_seq{};
  std::array<uint8_t, 4096> rx{};
  std::array<uint8_t, link::kMaxEncodedFrame> tx{};
  scenario::SignalSample sample;
  std::vector<int64_t> latency = std::vector<int64_t>(kLatencyWindow), scratch = std::vector<int64_t>(kLatencyWindow);
  std::size_t latency_count = 0;
  int64_t latency_max = 0;
  int64_t last_frame_mono = 0;  // last valid frame (0: none since the link opened)
  RateLimiter log_limit;
  // Device time: host times in the exchanges are s since epoch_wall (CLOCK_REALTIME ns).
  link::DeviceClock clock;
  const int64_t epoch_wall = wall_time_ns();

  // Cycle sync (docs/bridges.md, "Cycle sync"): the run's grid, step k at grid_t0 + k
  // grid_step (CLOCK_REALTIME ns). Set once (the command thread, from the start signal), then read.
  std::atomic<int64_t> grid_t0{0};
  const int64_t grid_step_ns;
  rt::Subscriber<msg::ClockStep> start;  // the launcher's start signal (cycle_sync with start_signal)

  // Command thread only.
  scenario::SignalSample command;

  Impl(scenario::Scenario& sc, rt::Participant& p, const rt::QosProfiles& profiles, std::unique_ptr<DeviceLink> l,
       BridgeOptions o)
      : routes(make_routes(sc, p, profiles)),
        link(std::move(l)),
        opt(std::move(o)),
        grid_step_ns(std::llround(sc.step * 1e9)) {
    if (routes.command.layout->fields.size() > kMaxCommandFields)
      throw InputError(routes.command.spec->name + ": more command fields than a frame carries");
    if (opt.device_time)
      for (const SensorRoute& r : routes.sensors)
        if (r.layout->payload_size() + 8 > link::kMaxPayload)
          throw InputError(r.spec->name + ": frame " + fmt::format("0x{:02x}", r.layout->id) +
                           " has no room for the device time (" + std::to_string(link::kMaxPayload) +
                           " bytes at most, the time included)");
    heartbeat = p.publisher<msg::Heartbeat>(distributed::health_topic(opt.service), profiles.get("health"));
    hb = distributed::heartbeat_of(opt.service, routes.robot);
    if (opt.cycle_sync && !opt.device_time) throw InputError(opt.service + ": cycle_sync needs device_time");
    // The grid: the launcher's start, or (started by hand) whole seconds of the wall clock, as
    // a realtime service started by hand steps (distributed/realtime.cpp).
    if (opt.cycle_sync && opt.start_signal)
      start = p.subscriber<msg::ClockStep>(distributed::kClockTopic, profiles.get("lockstep"));
    else if (opt.cycle_sync)
      grid_t0.store((wall_time_ns() / kSecond + 1) * kSecond, std::memory_order_relaxed);
    int fds[2];
    if (pipe2(fds, O_NONBLOCK | O_CLOEXEC) != 0)
      throw std::runtime_error(std::string("pipe2: ") + std::strerror(errno));
    pipe_r = fds[0];
    pipe_w = fds[1];
  }
  ~Impl() {
    ::close(pipe_r);
    ::close(pipe_w);
    link->close();
  }

  // --- I/O thread --------------------------------------------------------------

  /// False if there is no device or it did not take the frame.
  bool send_frame(uint8_t id, const uint8_t* payload, std::size_t n) {
    if (!link->is_open()) return false;
    const std::size_t len = link::encode_frame(id, tx_seq[id]++, payload, n, tx.data());
    const ssize_t w = ::write(link->fd(), tx.data(), len);
    if (w != static_cast<ssize_t>(len)) {
      c.tx_errors.fetch_add(1, std::memory_order_relaxed);  // buffer full, no listener, lost device
      return false;
    }
    c.frames_out.fetch_add(1, std::memory_order_relaxed);
    return true;
  }

  /// Device time: a request carrying its own departure time t1 (s since epoch_wall).
  void send_time_request() {
    uint8_t payload[24] = {};
    link::put_f64_le(payload, static_cast<double>(wall_time_ns() - epoch_wall) * 1e-9);
    (void)send_frame(link::kTimeRequestId, payload, sizeof payload);
  }

  void on_time_response(const link::Frame& f, int64_t arrived_wall) {
    if (f.payload_size != 24) {
      c.framing_errors.fetch_add(1, std::memory_order_relaxed);
      warn("{}: time response with {} payload bytes, expected 24: dropped", opt.service, f.payload_size);
      return;
    }
    const double t1 = link::get_f64_le(f.payload), t2 = link::get_f64_le(f.payload + 8),
                 t3 = link::get_f64_le(f.payload + 16), t4 = static_cast<double>(arrived_wall - epoch_wall) * 1e-9;
    if (!clock.add(t1, t2, t3, t4)) {
      c.rejected_frames.fetch_add(1, std::memory_order_relaxed);
      warn("{}: time response refused: t1 {} t2 {} t3 {} t4 {} cannot be one exchange", opt.service, t1, t2, t3, t4);
      return;
    }
    last_frame_mono = monotonic_ns();
    c.clock_exchanges.store(clock.exchanges(), std::memory_order_relaxed);
    c.clock_restarts.store(clock.restarts(), std::memory_order_relaxed);
    // The clock's host times count from epoch_wall: the offset against CLOCK_REALTIME itself.
    c.clock_offset_s.store(clock.offset_s() - static_cast<double>(epoch_wall) * 1e-9, std::memory_order_relaxed);
    c.clock_drift_ppm.store(clock.drift_ppm(), std::memory_order_relaxed);
    c.clock_uncertainty_us.store(clock.uncertainty_s() * 1e6, std::memory_order_relaxed);
  }

  /// Device time: the host time (CLOCK_REALTIME ns) of a sample the device stamped at
  /// `device_s`; false (counted) if there is no map yet or the time cannot be the sample's.
  bool sample_time(double device_s, const SensorRoute& r, int64_t arrived_wall, int64_t& data_time) {
    if (!clock.valid()) {
      c.unsynced_frames.fetch_add(1, std::memory_order_relaxed);
      return false;
    }
    const double host_s = std::isfinite(device_s) ? clock.to_host(device_s) : NAN;
    const double ahead_s = host_s - static_cast<double>(arrived_wall - epoch_wall) * 1e-9;
    // A sample is taken before it arrives (within the map's uncertainty, and 1 ms), and
    // not longer ago than the link timeout.
    if (!(ahead_s <= std::max(2 * clock.uncertainty_s(), 1e-3) && ahead_s >= -opt.link_timeout_s)) {
      c.rejected_frames.fetch_add(1, std::memory_order_relaxed);
      warn("{}: frame for {} refused: device time {} s maps to {} ms from its arrival", opt.service, r.spec->name,
           device_s, ahead_s * 1e3);
      return false;
    }
    data_time = epoch_wall + static_cast<int64_t>(std::llround(host_s * 1e9));
    return true;
  }

  /// Cycle sync: the run's step nearest now (negative before the start) and its time in the
  /// device's clock, and the step's length in it (the host's step times the device clock's
  /// rate). Requires a valid clock map.
  void send_cycle(int64_t t0) {
    const int64_t since = wall_time_ns() - t0;
    const int64_t k =
        since >= 0 ? (since + grid_step_ns / 2) / grid_step_ns : -((-since + grid_step_ns / 2) / grid_step_ns);
    const double host_s = static_cast<double>(t0 - epoch_wall + k * grid_step_ns) * 1e-9;
    uint8_t payload[link::kCyclePayload];
    link::put_f64_le(payload, clock.to_device(host_s));
    link::put_f64_le(payload + 8, static_cast<double>(grid_step_ns) * 1e-9 * (1.0 + clock.drift_ppm() * 1e-6));
    link::put_f64_le(payload + 16, static_cast<double>(k));
    if (send_frame(link::kCycleId, payload, sizeof payload)) c.cycle_syncs.fetch_add(1, std::memory_order_relaxed);
  }

  void send_stop() {
    if (send_frame(link::kStopId, nullptr, 0)) c.stop_frames.fetch_add(1, std::memory_order_relaxed);
  }

  void send_command(const CommandMessage& m) {
    uint8_t payload[link::kMaxPayload];
    const std::size_t n = routes.command.layout->encode(m.values, payload);
    if (send_frame(routes.command.layout->id, payload, n)) c.commands_forwarded.fetch_add(1, std::memory_order_relaxed);
  }

  template <class... Args>
  void warn(spdlog::format_string_t<Args...> fmt, Args&&... args) {
    uint64_t held = 0;
    if (log_limit.allow(monotonic_ns(), held)) {
      spdlog::warn(fmt, std::forward<Args>(args)...);
      if (held) spdlog::warn("{}: {} more link messages held back", opt.service, held);
    }
  }

  void on_frame(const link::Frame& f, int64_t arrived_wall) {
    if (f.id == link::kTimeResponseId && opt.device_time) {
      on_time_response(f, arrived_wall);
      return;
    }
    const int16_t idx = routes.sensor_by_id[f.id];
    if (idx < 0) {  // not a frame this robot's device sends (unknown id, a host -> device id)
      c.framing_errors.fetch_add(1, std::memory_order_relaxed);
      warn("{}: frame id 0x{:02x} is not one this robot's device sends: dropped", opt.service, f.id);
      return;
    }
    SensorRoute& r = routes.sensors[static_cast<std::size_t>(idx)];
    const std::size_t expected = r.layout->payload_size() + (opt.device_time ? 8 : 0);  // + the device time
    if (f.payload_size != expected) {
      c.framing_errors.fetch_add(1, std::memory_order_relaxed);
      warn("{}: frame 0x{:02x} ({}) has {} payload bytes, expected {}{}: dropped", opt.service, f.id, r.spec->name,
           f.payload_size, expected, opt.device_time ? " (with the device time)" : "");
      return;
    }
    r.layout->decode(f.payload, sample.values.data());
    std::size_t bad = 0;
    if (const auto why = r.publisher->wire().check(sample, bad); why != distributed::Rejection::none) {
      c.rejected_frames.fetch_add(1, std::memory_order_relaxed);
      warn("{}: frame 0x{:02x} for {} refused: {} ({} = {})", opt.service, f.id, r.spec->name,
           distributed::to_string(why), r.layout->fields[bad].name, sample.values[bad]);
      return;
    }
    int64_t data_time = arrived_wall;
    if (opt.device_time &&
        !sample_time(link::get_f64_le(f.payload + r.layout->payload_size()), r, arrived_wall, data_time))
      return;
    r.publisher->publish_at(sample, data_time, data_time);
    ++r.published;
    const int64_t lat = wall_time_ns() - arrived_wall;
    latency[latency_count++ % kLatencyWindow] = lat;
    latency_max = std::max(latency_max, lat);
    c.frames_in.fetch_add(1, std::memory_order_relaxed);
    last_frame_mono = monotonic_ns();
  }

  void lose_device(const char* why) {
    link->close();
    decoder.reset();
    last_frame_mono = 0;
    c.disconnects.fetch_add(1, std::memory_order_relaxed);
    warn("{}: lost the device ({}): {}; retrying every {} s", opt.service, link->describe(), why, opt.retry_s);
  }

  /// Reads what the device sent; false if the device is gone.
  void read_device() {
    for (;;) {
      const ssize_t n = ::read(link->fd(), rx.data(), rx.size());
      if (n > 0) {
        const int64_t arrived = wall_time_ns();
        decoder.feed(rx.data(), static_cast<std::size_t>(n), [&](const link::Frame& f) { on_frame(f, arrived); });
        if (!link->reports_loss()) continue;  // UDP: one datagram per read, read them all
        if (static_cast<std::size_t>(n) < rx.size()) return;
        continue;
      }
      if (n < 0 && (errno == EAGAIN || errno == EINTR)) return;
      if (n < 0 && errno == ECONNREFUSED) return;  // UDP: nobody at the device's port yet (silence shows it)
      lose_device(n == 0 ? "end of file" : std::strerror(errno));
      return;
    }
  }

  void publish_decoder_counters() {
    const auto& d = decoder.counters();
    c.crc_errors.store(d.crc_errors, std::memory_order_relaxed);
    c.oversize.store(d.oversize, std::memory_order_relaxed);
    c.resyncs.store(d.resyncs, std::memory_order_relaxed);
    c.bytes_discarded.store(d.bytes_discarded, std::memory_order_relaxed);
    decoder_framing_ = d.cobs_errors + d.short_frames + d.version_errors;
  }

  void publish_latency() {
    const std::size_t n = std::min(latency_count, kLatencyWindow);
    if (n == 0) return;
    std::copy(latency.begin(), latency.begin() + static_cast<std::ptrdiff_t>(n), scratch.begin());
    const auto at = [&](double q) {
      const auto k = static_cast<std::ptrdiff_t>(q * static_cast<double>(n - 1));
      std::nth_element(scratch.begin(), scratch.begin() + k, scratch.begin() + static_cast<std::ptrdiff_t>(n));
      return static_cast<double>(scratch[static_cast<std::size_t>(k)]) * 1e-3;
    };
    c.latency_p50_us.store(at(0.5), std::memory_order_relaxed);
    c.latency_p99_us.store(at(0.99), std::memory_order_relaxed);
    c.latency_max_us.store(static_cast<double>(latency_max) * 1e-3, std::memory_order_relaxed);
  }

  void io_loop(const std::atomic<bool>& stop) {
    const int64_t period = routes.command.period_ns;
    const int64_t timeout = ns_of(opt.link_timeout_s), retry = ns_of(opt.retry_s);
    int64_t expires = INT64_MIN;  // of the command held; none yet
    int64_t now = monotonic_ns();
    int64_t next_stop_check = now + period, next_open = now, next_stats = now + kSecond, next_sync = now,
            next_cycle = now;
    const int64_t sync_period = ns_of(1.0 / opt.time_sync_hz);
    bool opened_before = false;
    std::string error;
    while (!stop.load(std::memory_order_relaxed)) {
      now = monotonic_ns();
      if (!link->is_open() && now >= next_open) {
        if (link->open(error)) {
          if (opened_before) c.reconnects.fetch_add(1, std::memory_order_relaxed);
          spdlog::info("{}: {} {}", opt.service, opened_before ? "reopened" : "opened", link->describe());
          opened_before = true;
          decoder.reset();
        } else {
          warn("{}: {}; retrying every {} s", opt.service, error, opt.retry_s);
          next_open = now + retry;
        }
      }
      c.up.store(link->is_open() && last_frame_mono > 0 && now - last_frame_mono <= timeout, std::memory_order_relaxed);
      pollfd fds[2] = {{pipe_r, POLLIN, 0}, {link->fd(), POLLIN, 0}};
      int64_t wake = std::min(next_stop_check, next_stats);
      if (opt.device_time && link->is_open()) wake = std::min(wake, next_sync);
      const bool cycle_known = opt.cycle_sync && link->is_open() && clock.valid() && grid_t0.load() > 0;
      if (cycle_known) wake = std::min(wake, next_cycle);
      if (!link->is_open()) wake = std::min(wake, next_open);
      const int wait_ms = static_cast<int>(std::clamp<int64_t>((wake - now + 999'999) / 1'000'000, 0, 100));
      const int ready = ::poll(fds, link->is_open() ? 2 : 1, wait_ms);
      if (ready > 0 && (fds[0].revents & POLLIN)) {
        CommandMessage m;
        while (::read(pipe_r, &m, sizeof m) == static_cast<ssize_t>(sizeof m)) {
          expires = m.expires_mono;
          if (monotonic_ns() <= expires) send_command(m);
        }
      }
      if (ready > 0 && link->is_open() && fds[1].revents) {
        if (fds[1].revents & (POLLIN | POLLHUP | POLLERR)) read_device();
        if (link->is_open() && (fds[1].revents & POLLNVAL)) lose_device("invalid descriptor");
      }
      now = monotonic_ns();
      if (opt.device_time && link->is_open() && now >= next_sync) {
        send_time_request();
        next_sync = std::max(next_sync + sync_period, now);
      }
      // The cycle, as soon as the clock is mapped and the run's start is known (before the
      // start: the device holds its plant until step 0), then twice a second (a device
      // re-phases on each: its clock drifts, and the map improves with every exchange).
      if (cycle_known && now >= next_cycle) {
        send_cycle(grid_t0.load(std::memory_order_relaxed));
        next_cycle = now + kSecond / 2;
      }
      if (now >= next_stop_check) {
        next_stop_check = std::max(next_stop_check + period, now - period + 1);
        if (now > expires) send_stop();  // no fresh command: stop explicitly, once per command period
      }
      if (now >= next_stats) {
        publish_decoder_counters();
        publish_latency();
        next_stats = now + kSecond;
      }
    }
    send_stop();  // leave the robot stopped
    publish_decoder_counters();
    publish_latency();
  }

  // --- command thread ----------------------------------------------------------

  void forward_commands() {
    CommandRoute& r = routes.command;
    while (const void* m = r.subscriber->take()) {
      std::size_t bad = 0;
      if (const auto why = r.subscriber->wire().decode(m, command, bad); why != distributed::Rejection::none) {
        c.commands_refused.fetch_add(1, std::memory_order_relaxed);
        warn("{}: command on {} refused: {}", opt.service, r.spec->name, distributed::to_string(why));
        continue;
      }
      const int64_t age = wall_time_ns() - r.subscriber->header().data_time_ns();
      if (age > r.deadline_ns) {  // never forwarded: the I/O thread keeps sending stops
        c.stale_commands.fetch_add(1, std::memory_order_relaxed);
        continue;
      }
      CommandMessage cm{};
      cm.expires_mono = monotonic_ns() + (r.deadline_ns - std::max<int64_t>(age, 0));
      std::copy(command.values.begin(), command.values.begin() + static_cast<std::ptrdiff_t>(r.layout->fields.size()),
                cm.values);
      // Full pipe (the I/O thread stalled 100+ commands behind): this one is dropped, the
      // next one carries the newer value.
      (void)::write(pipe_w, &cm, sizeof cm);
    }
  }

  msg::LinkStatus link_status() const {
    msg::LinkStatus s;
    const auto get = [](const std::atomic<uint64_t>& a) { return a.load(std::memory_order_relaxed); };
    s.state(c.up.load(std::memory_order_relaxed) ? msg::LINK_UP : msg::LINK_DOWN);
    s.frames_in(get(c.frames_in));
    s.frames_out(get(c.frames_out));
    s.crc_errors(get(c.crc_errors));
    s.framing_errors(get(c.framing_errors) + decoder_framing_.load(std::memory_order_relaxed));
    s.oversize(get(c.oversize));
    s.resyncs(get(c.resyncs));
    s.bytes_discarded(get(c.bytes_discarded));
    s.rejected_frames(get(c.rejected_frames));
    s.reconnects(get(c.reconnects));
    s.disconnects(get(c.disconnects));
    s.stale_commands(get(c.stale_commands));
    s.stop_frames(get(c.stop_frames));
    s.tx_errors(get(c.tx_errors));
    s.latency_p50_us(c.latency_p50_us.load(std::memory_order_relaxed));
    s.latency_p99_us(c.latency_p99_us.load(std::memory_order_relaxed));
    s.latency_max_us(c.latency_max_us.load(std::memory_order_relaxed));
    s.unsynced_frames(get(c.unsynced_frames));
    s.clock_exchanges(get(c.clock_exchanges));
    s.clock_restarts(get(c.clock_restarts));
    s.clock_offset_s(c.clock_offset_s.load(std::memory_order_relaxed));
    s.clock_drift_ppm(c.clock_drift_ppm.load(std::memory_order_relaxed));
    s.clock_uncertainty_us(c.clock_uncertainty_us.load(std::memory_order_relaxed));
    s.cycle_syncs(get(c.cycle_syncs));
    return s;
  }

  void beat(msg::ServiceState state) {
    hb.state(state);
    hb.link(link_status());
    hb.loop_count(hb.link().frames_in());
    hb.rejected_inputs(c.commands_refused.load(std::memory_order_relaxed) + hb.link().rejected_frames());
    hb.stale_inputs(hb.link().stale_commands());
    hb.compute_p50_us(hb.link().latency_p50_us());
    hb.compute_p99_us(hb.link().latency_p99_us());
    hb.compute_max_us(hb.link().latency_max_us());
    hb.uptime_s(distributed::heartbeat_uptime_s());
    hb.header().origin_time_ns(0);
    heartbeat.publish(hb);
  }

  std::atomic<uint64_t> decoder_framing_{0};  // cobs, short and version errors (I/O thread writes)
};

Bridge::Bridge(scenario::Scenario& sc, rt::Participant& participant, const rt::QosProfiles& profiles,
               std::unique_ptr<DeviceLink> link, BridgeOptions options)
    : impl_(std::make_unique<Impl>(sc, participant, profiles, std::move(link), std::move(options))) {}

Bridge::~Bridge() = default;

BridgeReport Bridge::run(const std::atomic<bool>& stop) {
  Impl& m = *impl_;
  const int64_t start = monotonic_ns();
  // This thread forwards the commands; the I/O thread, started below, inherits its priority
  // and CPU (bridge_main.cpp sets them before the participant).
  std::atomic<bool> io_stop{false};
  std::thread io([&] { m.io_loop(io_stop); });
  int64_t next_beat = 0;
  // CONFIGURING until the device first answers (with device time: its clock is mapped), so
  // that plexus launch starts the run with the device there; then RUNNING while valid frames
  // arrive, DEGRADED while the device is absent or silent. A change is announced at once.
  bool was_up = false, ever_up = false;
  while (!stop.load(std::memory_order_relaxed)) {
    m.routes.command.subscriber->wait(50'000'000);
    m.forward_commands();
    if (m.start && m.grid_t0.load(std::memory_order_relaxed) == 0) {
      msg::ClockStep go;
      if (m.start.take(go) && go.sim_time_ns() > 0) m.grid_t0.store(go.sim_time_ns(), std::memory_order_relaxed);
    }
    const bool up = m.c.up.load(std::memory_order_relaxed);
    ever_up = ever_up || up;
    if (const int64_t now = monotonic_ns(); now >= next_beat || up != was_up) {
      m.beat(up ? msg::SERVICE_RUNNING : ever_up ? msg::SERVICE_DEGRADED : msg::SERVICE_CONFIGURING);
      next_beat = now + kSecond;
      was_up = up;
    }
  }
  io_stop = true;
  io.join();
  m.beat(msg::SERVICE_DRAINING);
  BridgeReport r;
  r.link = m.link_status();
  r.commands_forwarded = m.c.commands_forwarded.load();
  r.commands_refused = m.c.commands_refused.load();
  r.run_s = static_cast<double>(monotonic_ns() - start) * 1e-9;
  return r;
}

}  // namespace plexus::bridge
