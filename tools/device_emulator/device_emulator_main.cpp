// device_emulator: the far end of a hardware bridge's link, for tests and demos without
// hardware (README.md). It runs a robot's plant and sensors, the same components as
// plant_simulator, in realtime, sends their samples as bridge-protocol frames on a
// pseudo-terminal or a UDP socket, takes the command frames the bridge sends, stops the
// robot when they stop coming (watchdog), paces its bytes at the line rate, and injects
// scripted faults.
//
//   device_emulator --params deploy/params/unicycle_robot.yaml --step 0.01 --pty /tmp/r1.tty
//   device_emulator --part run/parts/serial_bridge_r1.yaml --pty /tmp/r1.tty --fault flip@2:count=3
//   device_emulator --params robot.yaml --udp-bind 127.0.0.1:47002 --udp-peer 127.0.0.1:47001
//
// Runs until SIGINT/SIGTERM (or --duration), then prints one JSON line (counters, faults,
// the plant's last state) on stdout and exits 0. A bad option or parameter: one line
// `device_emulator: error: ...` on stderr, exit 2.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <memory>
#include <thread>

#include "cycle_follower.hpp"
#include "emulated_device.hpp"
#include "emulator_link.hpp"
#include "fault_script.hpp"
#include "plexus/base/cli_style.hpp"
#include "plexus/base/clock.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/base/logging.hpp"
#include "plexus/distributed/realtime.hpp"
#include "plexus/link/protocol.hpp"
#include "plexus/link/udp_socket.hpp"
#include "plexus/runtime/periodic_loop.hpp"
#include "plexus/scenario/overrides.hpp"
#include "plexus/service/standalone.hpp"
#include "timed_udp_port.hpp"

namespace {

using namespace plexus;

constexpr const char* kName = "device_emulator";
/// Most steps run back to back after an overrun (as the realtime host): the plant keeps
/// the grid's time without replaying a long stall.
constexpr int64_t kMaxCatchUpSteps = 10;
/// The fastest loop PeriodicLoop runs (100 kHz).
constexpr double kMinStep = 1e-5;

std::atomic<bool> g_stop{false};
void on_signal(int) { g_stop = true; }

/// A produced frame's way out: discarded while stalled or unplugged, else poisoned,
/// encoded, damaged as the faults say, and queued on the link (or on the timed UDP port).
class Transmitter final : public emulator::FrameOutput {
 public:
  Transmitter(emulator::FaultInjector& faults, emulator::EmulatorLink& link, emulator::TimedUdpPort* timed)
      : faults_(faults), link_(link), timed_(timed) {}
  void send(uint8_t id, uint16_t seq, uint8_t* payload, std::size_t n) override {
    if (!faults_.sending(link_)) {
      ++discarded;
      return;
    }
    faults_.on_payload(payload, n);
    std::size_t len = link::encode_frame(id, seq, payload, n, buf_);
    len = faults_.on_encoded(buf_, len);
    if (timed_)
      timed_->queue(buf_, len);
    else
      link_.queue(buf_, len, true);
  }
  uint64_t discarded = 0;  ///< produced while stalled or unplugged

 private:
  emulator::FaultInjector& faults_;
  emulator::EmulatorLink& link_;
  emulator::TimedUdpPort* timed_;
  uint8_t buf_[link::kMaxEncodedFrame] = {};
};

nlohmann::ordered_json rx_json(const link::DecoderCounters& d, uint64_t bytes) {
  return {{"bytes", bytes},
          {"frames", d.frames},
          {"crc_errors", d.crc_errors},
          {"cobs_errors", d.cobs_errors},
          {"short_frames", d.short_frames},
          {"version_errors", d.version_errors},
          {"oversize", d.oversize},
          {"resyncs", d.resyncs},
          {"bytes_discarded", d.bytes_discarded}};
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      std::string(kName) +
      ": a robot's device (plant and sensors, as plant_simulator runs them) on the far end of a bridge's link: "
      "bridge-protocol frames on a pty or UDP, with a command watchdog, line-rate pacing and scripted faults "
      "(tools/device_emulator/README.md)"};
  app.set_version_flag("--version", std::string(kName) + " " + PLEXUS_VERSION);
  scenario::StandaloneSpec alone;
  alone.program = kName;
  alone.robot_section = true;
  std::string part_file, pty, udp_bind, udp_peer, faults_file, truth_file, log_level = "info";
  bool device_time = false;
  bool hold_until_command = false, ignore_cycle = false;
  double clock_offset = 0.0, clock_drift_ppm = 0.0, jitter_ms = 0.0;
  std::vector<std::string> sets, fault_specs;
  long baud = 1000000;
  int64_t watchdog_ms = 100;
  int priority = 0, cpu = -1;
  double duration = 0.0;
  int64_t seed = 1;
  std::size_t tx_buffer = 64 * 1024;
  app.add_option("--params", alone.params_file,
                 "YAML robot section: plant and sensors (e.g. deploy/params/unicycle_robot.yaml)");
  app.add_option("--robot", alone.robot, "Robot name with --params (default r1)");
  app.add_option("--step", alone.step, "Base step in s with --params (default 0.001)");
  app.add_option("--set", sets,
                 "Override key=value (--params: a key of the robot section; --part: a dotted key of the part)");
  app.add_option("--part", part_file, "A robot's part of a scenario, written by plexus launch (in place of --params)");
  app.add_option("--pty", pty,
                 "Create a pseudo-terminal; LINKPATH becomes a symlink to its slave (the bridge's device)");
  app.add_option("--udp-bind", udp_bind, "ADDR:PORT the emulator receives on (with --udp-peer)");
  app.add_option("--udp-peer", udp_peer, "ADDR:PORT of the bridge (with --udp-bind)");
  app.add_option("--baud", baud,
                 "Line rate the output is paced at, 8N1: 115200 .. 1000000; 0: unpaced (default 1000000)");
  app.add_option("--tx-buffer", tx_buffer, "TX ring in bytes: frames that find it full are dropped (default 65536)");
  app.add_flag("--hold-until-command", hold_until_command,
               "The plant holds its initial state (sensors still report it) until the first valid command; its time "
               "starts then");
  app.add_flag("--ignore-cycle", ignore_cycle,
               "Do not follow the bridge's cycle frames (0x8D): a device whose steps keep their own phase (its "
               "phase against the run's steps is still reported)");
  app.add_option("--watchdog-ms", watchdog_ms, "No valid command for this long: zero command (default 100)");
  app.add_option("--fault", fault_specs,
                 "KIND@T[:key=value,...] (flip, drop, garbage, oversize, poison, stall, unplug); repeatable");
  app.add_option("--faults", faults_file, "YAML list of faults: - {kind: flip, at: 1.5, count: 3}");
  app.add_option("--seed", seed, "Seed of the faults' random choices (default 1)");
  app.add_option("--duration", duration, "Run this many seconds (default: until SIGINT/SIGTERM)");
  app.add_flag("--device-time", device_time,
               "Stamp every sample frame with the device's clock (also on when the part's source says device_time)");
  app.add_option("--clock-offset", clock_offset, "The device clock's reading at start, s (default 0)");
  app.add_option("--clock-drift-ppm", clock_drift_ppm,
                 "How fast the device clock runs, ppm, -1000 .. 1000 (default 0)");
  app.add_option("--jitter-ms", jitter_ms,
                 "UDP: a random delay per frame, 0 .. this many ms, each way, in order (default 0)");
  app.add_option("--truth-times", truth_file,
                 "CSV: per sample frame, id, seq, first field, device time (s), true host time (CLOCK_REALTIME ns), "
                 "every field's SI value before encoding");
  app.add_option("--priority", priority,
                 "SCHED_FIFO priority of its loop and link threads, 1 .. 99 (0: normal scheduling), as a device's "
                 "firmware runs")
      ->check(fifo_priority());
  app.add_option("--cpu", cpu, "Pin its loop and link threads to this CPU (0, 1, ...)")->check(cpu_index());
  app.add_option("--log-level", log_level, "trace, debug, info, warn, error, critical or off");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    std::fprintf(stderr, "%s: error: %s\n", kName, e.what());
    return kExitBadInput;
  }
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  std::signal(SIGPIPE, SIG_IGN);
  try {
    // --- options
    const bool udp = !udp_bind.empty() || !udp_peer.empty();
    if (pty.empty() == !udp)
      throw InputError("expected exactly one link: --pty LINKPATH, or --udp-bind and --udp-peer");
    emulator::LinkOptions lo;
    if (udp) {
      if (udp_bind.empty() || udp_peer.empty())
        throw InputError("--udp-bind and --udp-peer: both are required (ADDR:PORT each)");
      std::string error;
      if (!link::parse_endpoint(udp_bind, "--udp-bind", lo.bind, error) ||
          !link::parse_endpoint(udp_peer, "--udp-peer", lo.peer, error))
        throw InputError(error);
      lo.kind = emulator::LinkOptions::Kind::udp;
    } else {
      lo.pty_path = pty;
    }
    if (baud != 0 && (baud < 115200 || baud > 1000000))
      throw InputError("--baud " + std::to_string(baud) + ": expected 115200 .. 1000000, or 0 (unpaced)");
    lo.baud = baud;
    if (watchdog_ms <= 0 || watchdog_ms > 3'600'000)
      throw InputError("--watchdog-ms " + std::to_string(watchdog_ms) +
                       ": expected milliseconds > 0 (at most an hour)");
    if (duration < 0.0 || duration > 1e7 || !std::isfinite(duration))
      throw InputError("--duration " + app["--duration"]->as<std::string>() + ": expected seconds > 0 (at most 1e7)");
    if (app.count("--duration") && duration == 0.0) throw InputError("--duration 0: expected seconds > 0");
    if (seed < 0) throw InputError("--seed " + std::to_string(seed) + ": expected an integer >= 0");
    if (tx_buffer < 1024 || tx_buffer > 16 * 1024 * 1024)
      throw InputError("--tx-buffer " + std::to_string(tx_buffer) + ": expected bytes 1024 .. 16777216");
    lo.ring_bytes = tx_buffer;
    if (!(std::abs(clock_offset) <= 1e6))
      throw InputError("--clock-offset " + app["--clock-offset"]->as<std::string>() + ": expected seconds, |S| <= 1e6");
    if (!(std::abs(clock_drift_ppm) <= 1000))
      throw InputError("--clock-drift-ppm " + app["--clock-drift-ppm"]->as<std::string>() + ": expected -1000 .. 1000");
    if (!(jitter_ms >= 0 && jitter_ms <= 100))
      throw InputError("--jitter-ms " + app["--jitter-ms"]->as<std::string>() + ": expected 0 .. 100");
    if (jitter_ms > 0 && !udp) throw InputError("--jitter-ms: UDP only (--udp-bind, --udp-peer)");
    std::vector<emulator::Fault> faults;
    for (const auto& s : fault_specs) faults.push_back(emulator::parse_fault_spec(s));
    if (!faults_file.empty())
      for (auto& f : emulator::load_fault_file(faults_file)) faults.push_back(std::move(f));
    for (const auto& f : faults)
      if ((f.kind == emulator::FaultKind::garbage || f.kind == emulator::FaultKind::oversize) &&
          f.bytes + 1 > tx_buffer)
        throw InputError(f.origin + ": " + std::to_string(f.bytes) + " bytes do not fit the TX ring (--tx-buffer " +
                         std::to_string(tx_buffer) + ")");

    // --- the robot
    init_logging(kName, "", log_level);
    scenario::Scenario sc;
    if (!part_file.empty()) {
      if (!alone.params_file.empty())
        throw InputError("--part and --params: give one (a part holds its robot section)");
      if (app.count("--robot") || app.count("--step"))
        throw InputError("--part: the robot and the step come from the part; drop --robot and --step");
      std::vector<scenario::Override> overrides;
      for (const auto& s : sets) overrides.push_back(scenario::parse_override(s));
      sc = scenario::load_scenario(part_file, overrides, {.partial = true});
    } else {
      if (alone.params_file.empty())
        throw InputError("--params ROBOT.yaml or --part FILE: required (the robot to emulate)");
      if (app.count("--step") && !(alone.step >= kMinStep && std::isfinite(alone.step)))
        throw InputError("--step " + app["--step"]->as<std::string>() +
                         ": expected seconds >= 0.00001 (at most 100 kHz)");
      sc = scenario::load_standalone(alone, sets, true);
    }
    // A launched process keeps quiet about the scenario's warnings: `plexus launch` said them once.
    scenario::log_warnings(sc, {}, !part_file.empty());
    if (!(sc.step >= kMinStep))
      throw InputError(sc.file + ": step " + std::to_string(sc.step) +
                       ": expected seconds >= 0.00001 (at most 100 kHz)");
    const int64_t watchdog_ns = watchdog_ms * 1'000'000;
    emulator::EmulatedDevice device(sc, watchdog_ns);
    for (const auto& [robot, src] : sc.sources) device_time = device_time || src.device_time;
    if (device_time) device.enable_device_time();
    if (hold_until_command) device.hold_until_command();
    // UDP with device time or jitter: the timed port (two threads own the socket; the loop's
    // tick would add up to a step of one-sided delay to every time exchange).
    const bool timed_port = udp && (device_time || jitter_ms > 0);
    if (timed_port)
      for (const auto& f : faults)
        if (f.kind == emulator::FaultKind::unplug || f.kind == emulator::FaultKind::garbage ||
            f.kind == emulator::FaultKind::oversize)
          throw InputError(f.origin +
                           ": not with --device-time or --jitter-ms over UDP (the timed port sends whole frames only)");
    std::FILE* truth = nullptr;
    if (!truth_file.empty() && !(truth = std::fopen(truth_file.c_str(), "w")))
      throw InputError("--truth-times " + truth_file + ": cannot write it");
    if (truth) std::fprintf(truth, "id,seq,first_field,device_time_s,sample_time_ns,fields\n");
    device.set_truth_log(truth);

    // --- the link, the faults, the loop
    rt::LoopOptions loop_options;
    loop_options.rate_hz = 1.0 / sc.step;
    loop_options.priority = priority;  // the timed UDP port's threads, made after, inherit it
    loop_options.cpu = cpu;
    rt::PeriodicLoop loop(loop_options);
    lo.period_ns = loop.period_ns();
    emulator::EmulatorLink link(lo);
    std::string error;
    if (!link.open(error)) throw InputError(error);
    emulator::FaultInjector injector(std::move(faults), static_cast<uint64_t>(seed));
    const emulator::DeviceClockModel clock{wall_time_ns(), clock_offset, clock_drift_ppm};
    std::unique_ptr<emulator::TimedUdpPort> timed;
    if (timed_port)
      timed = std::make_unique<emulator::TimedUdpPort>(link.fd(), clock, jitter_ms * 1e-3, static_cast<uint64_t>(seed));
    Transmitter tx(injector, link, timed.get());
    uint16_t time_response_seq = 0;
    link::FrameDecoder decoder;

    spdlog::info("robot {} on {}, step {} s, {}; watchdog {} ms; {}; {} fault(s), seed {}", device.robot(),
                 link.describe(), sc.step, device.describe(), watchdog_ms,
                 baud ? "paced at " + std::to_string(baud) + " baud (8N1)" : std::string("unpaced"),
                 injector.faults().size(), seed);

    const int64_t period = loop.period_ns();
    // Step k's deadline is first_deadline + k periods: a cycle frame moves it onto the run's
    // steps (phase and numbering).
    int64_t first_deadline = monotonic_ns() + period;
    const int64_t t0 = first_deadline;  // t = 0: faults' times count from here
    emulator::CycleFollower cycle(period);
    uint8_t cycle_payload[link::kCyclePayload] = {};
    std::size_t cycle_bytes = SIZE_MAX;  // a cycle frame's payload size this tick; SIZE_MAX: none
    const auto end_ns = duration > 0.0 ? t0 + static_cast<int64_t>(std::llround(duration * 1e9)) : INT64_MAX;
    device.start(t0);
    int64_t steps = 0, last_k = -1;
    uint64_t reopens = 0;
    // What arrives on the link: a time request answered (the pty's responder: at the tick; the
    // timed UDP port answers on arrival), a cycle frame kept for the end of the tick, the rest
    // to the device.
    int64_t rx_now = 0;
    const auto on_bytes = [&](const uint8_t* bytes, std::size_t n) {
      decoder.feed(bytes, n, [&](const link::Frame& f) {
        if (f.id == link::kTimeRequestId && f.payload_size == 24) {
          uint8_t payload[24];
          clock.answer(f.payload, wall_time_ns(), payload);
          tx.send(link::kTimeResponseId, time_response_seq++, payload, sizeof payload);
          return;
        }
        if (f.id == link::kCycleId) {
          cycle_bytes = f.payload_size;
          std::memcpy(cycle_payload, f.payload, std::min<std::size_t>(f.payload_size, sizeof cycle_payload));
          return;
        }
        device.on_frame(f, rx_now);
      });
    };
    const auto receive = [&](int64_t now) {
      rx_now = now;
      if (timed)
        timed->poll(on_bytes);
      else
        link.poll(on_bytes);
    };
    // Following the run's cycle, the plant starts as plant_simulator's does
    // (distributed::StartupWait): in the run's first steps each waits, two periods at most,
    // for the command computed at the step before (a host's first DDS writes and deliveries
    // take up to 2 ms); afterwards it never waits.
    const int64_t startup_steps = distributed::StartupWait::ticks(sc.step);
    uint64_t commands_at_0 = 0, start_waits = 0;
    int64_t start_wait_ns = 0;
    const auto wait_at_start = [&](int64_t j) {
      if (!device.follows_run() || j < 0 || j >= startup_steps) return;
      if (j == 0) {
        commands_at_0 = device.counters().commands;
        return;
      }
      const int64_t from = monotonic_ns(), until = from + distributed::StartupWait::kWaitPeriods * period;
      if (device.counters().commands >= commands_at_0 + static_cast<uint64_t>(j)) return;
      ++start_waits;
      while (device.counters().commands < commands_at_0 + static_cast<uint64_t>(j) && monotonic_ns() < until &&
             !g_stop.load(std::memory_order_relaxed)) {
        std::this_thread::sleep_for(std::chrono::microseconds(20));
        receive(monotonic_ns());
      }
      start_wait_ns += monotonic_ns() - from;
    };
    loop.run(
        [&](const rt::PeriodicLoop::Tick& t) {
          const int64_t now = t.wake_ns;
          // After an unplug the link is new: a frame begun on the old one is no frame.
          if (link.counters().reopens != reopens) {
            reopens = link.counters().reopens;
            decoder.reset();
          }
          receive(now);
          device.check_watchdog(now);
          injector.tick(static_cast<double>(t.deadline_ns - t0) * 1e-9, link);
          // The step is the grid's, from the deadline; steps missed in an overrun run first.
          const int64_t k = (t.deadline_ns - first_deadline) / period;
          // Each step's samples are the plant's state at the step's time, its deadline (also a
          // catch-up step's: stamped with the time of the tick it ran in, every one of them
          // mapped to the same step and was dropped as a repeat).
          const int64_t wall_of_mono = wall_time_ns() - monotonic_ns();
          for (int64_t j = std::max(last_k + 1, k - kMaxCatchUpSteps); j <= k; ++j, ++steps) {
            const int64_t at = first_deadline + j * period + wall_of_mono;
            wait_at_start(j);
            device.set_sample_time(at, clock.at(at));
            device.step(j, tx);
          }
          last_k = k;
          if (cycle_bytes != SIZE_MAX) {
            // The next tick moves onto the run's cycle: its phase, and its step's number (a
            // new numbering runs no catch-up steps across it).
            const int64_t next_wall = t.deadline_ns + period + wall_of_mono;
            int64_t shift = 0, run_step = 0;
            if (cycle.shift_for(cycle_payload, cycle_bytes, clock, next_wall, shift, run_step) && !ignore_cycle) {
              loop.shift(shift);
              first_deadline = t.deadline_ns + period + shift - run_step * period;
              if (run_step != last_k + 1) last_k = run_step - 1;
              device.follow_run();
            }
            cycle_bytes = SIZE_MAX;
          }
          if (!timed && injector.sending(link)) link.flush(now);
          return !g_stop.load(std::memory_order_relaxed) && t.deadline_ns + period < end_ns;
        },
        first_deadline);

    const auto& lc = link.counters();
    const auto& dc = device.counters();
    const auto ls = loop.stats();
    nlohmann::ordered_json j{{"frames_sent", lc.frames_sent},
                             {"bytes_sent", lc.bytes_sent},
                             {"frames_dropped_tx", lc.frames_dropped_tx},
                             {"commands", dc.commands},
                             {"commands_refused", dc.commands_refused},
                             {"stops", dc.stops},
                             {"watchdog_trips", dc.watchdog_trips},
                             {"frames_unexpected", dc.frames_unexpected},
                             {"rx", rx_json(decoder.counters(), lc.bytes_received)},
                             {"faults", injector.summary()},
                             {"steps", steps},
                             {"state", device.state()},
                             {"link", link.describe()},
                             {"frames_produced", dc.frames_produced},
                             {"frames_discarded", tx.discarded},
                             {"write_drops", lc.write_drops},
                             {"bytes_dropped_tx", lc.bytes_dropped_tx},
                             {"link_errors", lc.link_errors},
                             {"reopens", lc.reopens},
                             {"watchdog_tripped", device.watchdog_tripped()},
                             {"run_s", static_cast<double>(monotonic_ns() - t0) * 1e-9},
                             {"overruns", ls.overruns},
                             {"jitter_p99_us", ls.jitter_p99_us},
                             {"jitter_max_us", ls.jitter_max_us},
                             {"device_time", device_time},
                             {"cycle",
                              {{"followed", !ignore_cycle},
                               {"syncs", cycle.syncs()},
                               {"refused", cycle.refused()},
                               {"first_shift_us", cycle.first_shift_us()},
                               {"max_shift_us_after_first", cycle.max_shift_us()},
                               {"start_waits", start_waits},
                               {"start_wait_us", static_cast<double>(start_wait_ns) * 1e-3}}}};
    if (timed) {
      const auto tc = timed->counters();
      j["timed_port"] = {{"time_requests", tc.time_requests}, {"datagrams_in", tc.datagrams_in},
                         {"datagrams_out", tc.datagrams_out}, {"ring_drops", tc.ring_drops},
                         {"send_errors", tc.send_errors},     {"jitter_ms", jitter_ms}};
    }
    timed.reset();
    if (truth) std::fclose(truth);
    link.close();
    std::printf("%s\n", j.dump().c_str());
    std::fflush(stdout);
    return 0;
  } catch (const InputError& e) {
    std::fprintf(stderr, "%s: error: %s\n", kName, e.what());
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: failed: %s\n", kName, e.what());
    return 1;
  }
}
