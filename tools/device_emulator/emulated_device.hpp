// The emulated device: a robot's plant and sensors (the components plant_simulator runs,
// built from the same robot section), stepped by the emulator's loop, with the device side
// of the bridge protocol: each output signal leaves as its frame, the command arrives as
// its frame, and a watchdog stops the robot when commands stop coming, as a motor
// controller does.
//
// Fields travel by name: a frame's payload takes each of its layout's fields from the
// signal's field of that name (0.0 if the signal has none), and a command frame's fields
// land in the plant input's fields of the same names.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "plexus/link/frame.hpp"
#include "plexus/link/protocol.hpp"
#include "plexus/scenario/scenario.hpp"
#include "plexus/scenario/step_executor.hpp"

namespace plexus::emulator {

/// Where produced frames go: the fault injector and the link (device_emulator_main.cpp).
class FrameOutput {
 public:
  virtual ~FrameOutput() = default;
  /// A frame to send: `payload` (n bytes) may be changed (a poison fault) before encoding.
  virtual void send(uint8_t id, uint16_t seq, uint8_t* payload, std::size_t n) = 0;
};

struct DeviceCounters {
  uint64_t commands = 0;           ///< valid command frames, now the plant's command
  uint64_t commands_refused = 0;   ///< command (or STOP) frames of the wrong length, or with a non-finite value
  uint64_t stops = 0;              ///< STOP frames
  uint64_t watchdog_trips = 0;     ///< times the watchdog went from armed to tripped
  uint64_t frames_unexpected = 0;  ///< device -> host ids, other robots' commands, unknown ids
  uint64_t frames_produced = 0;    ///< output samples framed (sent or not)
};

class EmulatedDevice {
 public:
  /// Builds the routes: every output of the scenario's components needs a device -> host
  /// frame, the one command they read a host -> device frame. Throws InputError naming the
  /// component (or the file) otherwise. `watchdog_ns` > 0.
  EmulatedDevice(scenario::Scenario& sc, int64_t watchdog_ns);

  /// Starts the watchdog's clock (the device powers up with the zero command).
  void start(int64_t now_ns);
  /// A frame from the host.
  void on_frame(const link::Frame& f, int64_t now_ns);
  /// Trips the watchdog when the last valid command is older than its timeout.
  void check_watchdog(int64_t now_ns);
  /// Runs base step k; every sample produced goes to `out` as its frame.
  void step(int64_t k, FrameOutput& out);
  /// Powered but held until the first valid command (`--hold-until-command`), as a drive
  /// with its brakes on: until then every step is the plant's step 0 again (its initial
  /// state, sampled by the sensors each tick), and the plant's time starts at the tick
  /// the first command arrived on. So a run's services, started apart from the device,
  /// meet the plant at its initial state whenever the device came up.
  void hold_until_command() { hold_ = true; }
  /// The steps are the run's from now on (a cycle frame, docs/bridges.md "Cycle sync"): before
  /// the run's step 0 the plant holds its initial state, then steps with the run, as
  /// plant_simulator's; the first command no longer starts the plant's time.
  void follow_run() { run_steps_ = true; }
  bool follows_run() const { return run_steps_; }
  /// Device time (docs/bridges.md, "Device time"): from now on every device -> host frame
  /// carries one more f64 after its fields, the time set by set_sample_time().
  /// Throws InputError if a frame has no room for it (link::kMaxPayload bytes, the time included).
  void enable_device_time();
  bool device_time() const { return device_time_; }
  /// The host time (CLOCK_REALTIME ns) and the device clock's reading (s) of the samples
  /// of the next step().
  void set_sample_time(int64_t wall_ns, double device_s) { sample_wall_ns_ = wall_ns, sample_time_ = device_s; }
  /// Where each sample frame's record goes (`--truth-times`): id, seq, first field, device
  /// time, true host time, and every field's SI value before encoding. nullptr: none.
  void set_truth_log(std::FILE* f) { truth_log_ = f; }

  const std::string& robot() const { return robot_; }
  /// One line: the frames it sends and the command it reads.
  std::string describe() const;
  const DeviceCounters& counters() const { return c_; }
  bool watchdog_tripped() const { return tripped_; }
  /// The plant's truth signal, last sample, by field name.
  nlohmann::ordered_json state() const;

 private:
  struct OutputRoute {
    const link::MessageLayout* layout = nullptr;
    std::array<int16_t, link::kMaxFields> field{};  ///< per layout field: the signal's field index, -1: none
    uint16_t seq = 0;
  };

  scenario::Scenario& sc_;
  scenario::StepExecutor exec_;
  std::shared_ptr<const link::FrameTable> table_;  // what the routes' layouts point into
  std::string robot_;
  std::vector<int16_t> route_of_;  // by signal: index in routes_, -1 if not an output
  std::vector<OutputRoute> routes_;
  std::size_t cmd_signal_ = 0;
  const link::MessageLayout* cmd_layout_ = nullptr;
  std::vector<int16_t> cmd_field_;  // per command signal field: its index in the frame's fields, -1: none
  std::size_t truth_signal_ = SIZE_MAX;
  scenario::SignalSample truth_;

  // The command as the plant sees it.
  scenario::SignalSample cmd_;  // values of the last valid command frame
  bool have_cmd_ = false;       // a valid command has arrived since start
  bool stopped_ = false;        // a STOP frame came after the last command
  bool tripped_ = false;        // the watchdog holds the zero command
  int64_t watchdog_ns_;
  int64_t last_cmd_ns_ = 0;

  bool hold_ = false;
  bool run_steps_ = false;
  int64_t first_k_ = -1;  // with hold_: the emulator's step of the first command (the plant's step 1)

  FrameOutput* out_ = nullptr;  // during step()
  bool device_time_ = false;
  double sample_time_ = 0.0;
  int64_t sample_wall_ns_ = 0;
  std::FILE* truth_log_ = nullptr;
  uint8_t payload_[link::kMaxPayload + 8] = {};  // + the device time
  scenario::StepExecutor::RemoteInput remote_;
  scenario::StepExecutor::OutputSink sink_;
  DeviceCounters c_;
};

}  // namespace plexus::emulator
