#include "emulated_device.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "plexus/base/input_error.hpp"
#include "plexus/scenario/member_of.hpp"
#include "robot_frames.hpp"

namespace plexus::emulator {
namespace {

std::string hex(uint8_t id) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "0x%02X", id);
  return buf;
}

/// Where a frame field's value is among a signal's fields: the same name, or another name of
/// the same member of the signal's IDL type (the frames name each member once; a component may
/// use an alias). -1: the signal does not carry it.
int16_t index_of(const std::vector<std::string>& names, const std::string& name, const std::string& message) {
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return static_cast<int16_t>(i);
  const std::string member = scenario::member_of(message, name);
  if (member.empty()) return -1;
  for (std::size_t i = 0; i < names.size(); ++i)
    if (scenario::member_of(message, names[i]) == member) return static_cast<int16_t>(i);
  return -1;
}

}  // namespace

EmulatedDevice::EmulatedDevice(scenario::Scenario& sc, int64_t watchdog_ns)
    : sc_(sc), exec_(sc), watchdog_ns_(watchdog_ns) {
  // Which frame carries which signal: the bridge's own answer (services/bridge/robot_frames).
  const bridge::RobotFrames frames = bridge::robot_frames(sc, exec_, "the device emulator");
  robot_ = frames.robot;
  table_ = frames.table;
  const auto& signals = exec_.signals();
  route_of_.assign(signals.size(), -1);
  for (const auto& [s, layout] : frames.outputs) {
    const auto& spec = signals[s];
    OutputRoute r;
    r.layout = layout;
    r.field.fill(-1);
    for (std::size_t i = 0; i < layout->fields.size() && i < r.field.size(); ++i)
      r.field[i] = index_of(spec.fields, layout->fields[i].name, spec.message);
    route_of_[s] = static_cast<int16_t>(routes_.size());
    routes_.push_back(r);
    if (spec.plant_state && truth_signal_ == SIZE_MAX) truth_signal_ = s;
  }
  if (frames.command) {
    cmd_signal_ = frames.command->signal;
    cmd_layout_ = frames.command->layout;
    const auto& spec = signals[cmd_signal_];
    cmd_field_.assign(spec.fields.size(), -1);
    std::vector<std::string> frame_fields;
    for (const auto& w : cmd_layout_->fields) frame_fields.push_back(w.name);
    for (std::size_t f = 0; f < spec.fields.size(); ++f)
      cmd_field_[f] = index_of(frame_fields, spec.fields[f], spec.message);
  }

  // The callbacks are built once: std::function copies nothing per step, and neither
  // lambda allocates.
  remote_ = [this](std::size_t /*signal*/, int64_t due, scenario::SignalSample& s) {
    // Never a command yet: the input is invalid (step -1), and the plant holds still, as
    // plant_simulator does before its first command. After one: the last command, or zero
    // while stopped or tripped.
    s.step = have_cmd_ ? due : -1;
    if (have_cmd_ && !stopped_ && !tripped_)
      s.values = cmd_.values;
    else
      s.values.fill(0.0);
  };
  sink_ = [this](std::size_t signal, const scenario::SignalSample& sample) {
    if (signal == truth_signal_) truth_ = sample;
    const int16_t ri = route_of_[signal];
    if (ri < 0) return;
    OutputRoute& r = routes_[static_cast<std::size_t>(ri)];
    const std::size_t nf = r.layout->fields.size();
    double values[link::kMaxFields];
    for (std::size_t i = 0; i < nf; ++i)
      values[i] = r.field[i] >= 0 ? sample.values[static_cast<std::size_t>(r.field[i])] : 0.0;
    std::size_t n = r.layout->encode(values, payload_);
    if (truth_log_) {
      std::fprintf(truth_log_, "%u,%u,%.17g,%.17g,%lld,", r.layout->id, r.seq, nf ? values[0] : 0.0, sample_time_,
                   static_cast<long long>(sample_wall_ns_));
      for (std::size_t i = 0; i < nf; ++i) std::fprintf(truth_log_, i ? " %.17g" : "%.17g", values[i]);
      std::fputc('\n', truth_log_);
    }
    if (device_time_) {
      link::put_f64_le(payload_ + n, sample_time_);
      n += 8;
    }
    ++c_.frames_produced;
    out_->send(r.layout->id, r.seq++, payload_, n);
  };
}

void EmulatedDevice::start(int64_t now_ns) { last_cmd_ns_ = now_ns; }

void EmulatedDevice::enable_device_time() {
  for (const OutputRoute& r : routes_)
    if (r.layout->payload_size() + 8 > link::kMaxPayload)
      throw InputError("frame " + hex(r.layout->id) + " has no room for the device time (" +
                       std::to_string(link::kMaxPayload) + " bytes at most, the time included)");
  device_time_ = true;
}

void EmulatedDevice::on_frame(const link::Frame& f, int64_t now_ns) {
  if (f.id == link::kStopId) {
    if (f.payload_size != 0) {
      ++c_.commands_refused;
      return;
    }
    ++c_.stops;
    stopped_ = true;
    return;
  }
  if (cmd_layout_ == nullptr || f.id != cmd_layout_->id) {
    ++c_.frames_unexpected;  // a device -> host id, another robot's command, or no id at all
    return;
  }
  if (f.payload_size != cmd_layout_->payload_size()) {
    ++c_.commands_refused;
    return;
  }
  double v[link::kMaxFields];
  cmd_layout_->decode(f.payload, v);
  for (std::size_t i = 0; i < cmd_layout_->fields.size(); ++i) {
    if (!std::isfinite(v[i])) {
      ++c_.commands_refused;
      return;
    }
  }
  for (std::size_t fi = 0; fi < cmd_field_.size(); ++fi)
    cmd_.values[fi] = cmd_field_[fi] >= 0 ? v[static_cast<std::size_t>(cmd_field_[fi])] : 0.0;
  ++c_.commands;
  have_cmd_ = true;
  stopped_ = false;
  tripped_ = false;
  last_cmd_ns_ = now_ns;
}

void EmulatedDevice::check_watchdog(int64_t now_ns) {
  if (!tripped_ && now_ns - last_cmd_ns_ > watchdog_ns_) {
    tripped_ = true;
    ++c_.watchdog_trips;
  }
}

void EmulatedDevice::step(int64_t k, FrameOutput& out) {
  out_ = &out;
  if (run_steps_) {
    k = std::max<int64_t>(k, 0);  // before the run: its initial state again
  } else if (hold_) {
    if (!have_cmd_)
      k = 0;  // held: the initial state again
    else {
      if (first_k_ < 0) first_k_ = k;
      k = k - first_k_ + 1;
    }
  }
  exec_.step(k, remote_, sink_);
  out_ = nullptr;
}

std::string EmulatedDevice::describe() const {
  const auto& signals = exec_.signals();
  std::string sends;
  for (std::size_t s = 0; s < signals.size(); ++s) {
    if (route_of_[s] < 0) continue;
    const double hz = 1.0 / (static_cast<double>(signals[s].period_steps) * sc_.step);
    char rate[32];
    std::snprintf(rate, sizeof rate, "%g Hz", hz);
    sends += (sends.empty() ? "" : ", ") + signals[s].name + " as " +
             hex(routes_[static_cast<std::size_t>(route_of_[s])].layout->id) + " (" + signals[s].message + ", " + rate +
             ")";
  }
  const std::string cmd = cmd_layout_ ? signals[cmd_signal_].name + " from " + hex(cmd_layout_->id) + " (" +
                                            signals[cmd_signal_].message + ")"
                                      : "none";
  return "sends " + sends + "; command " + cmd + "; STOP " + hex(link::kStopId);
}

nlohmann::ordered_json EmulatedDevice::state() const {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  if (truth_signal_ == SIZE_MAX) return j;
  const auto& spec = exec_.signals()[truth_signal_];
  for (std::size_t i = 0; i < spec.fields.size() && i < scenario::kMaxSignalFields; ++i)
    j[spec.fields[i]] = truth_.values[i];
  return j;
}

}  // namespace plexus::emulator
