#include "emulated_device.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "plexus/base/input_error.hpp"

namespace plexus::emulator {
namespace {

std::string where_of(const scenario::Scenario& sc, const std::string& component) {
  for (const auto& c : sc.components)
    if (c.component->name() == component) return c.where;
  return sc.file;
}

std::string type_text(const scenario::SignalSpec& s) { return s.message.empty() ? "no IDL type" : s.message; }

std::string hex(uint8_t id) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "0x%02X", id);
  return buf;
}

int16_t index_of(const std::vector<std::string>& names, const char* name) {
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return static_cast<int16_t>(i);
  return -1;
}

}  // namespace

EmulatedDevice::EmulatedDevice(scenario::Scenario& sc, int64_t watchdog_ns)
    : sc_(sc), exec_(sc), watchdog_ns_(watchdog_ns) {
  for (const auto& c : sc.components) {
    if (c.kind != scenario::ComponentKind::plant && c.kind != scenario::ComponentKind::sensor)
      throw InputError(c.where + ": a device has a robot's plant and sensors; '" + c.component->name() + "' is a " +
                       scenario::to_string(c.kind));
    const std::string robot = c.component->name().substr(0, c.component->name().find('/'));
    if (!robot_.empty() && robot != robot_)
      throw InputError(c.where + ": the emulator is one robot's device (" + robot_ + " and " + robot + " here)");
    robot_ = robot;
  }
  if (robot_.empty()) throw InputError(sc.file + ": no robot (plant and sensors) to emulate");
  const auto& signals = exec_.signals();
  const auto topic_of = [&](const scenario::SignalSpec& s) {
    const std::string prefix = robot_ + "/";
    return s.name.compare(0, prefix.size(), prefix) == 0 ? s.name.substr(prefix.size()) : s.name;
  };

  route_of_.assign(signals.size(), -1);
  for (std::size_t s : exec_.local_outputs()) {
    const auto& spec = signals[s];
    const auto* layout = link::find_layout(topic_of(spec), spec.message, link::Direction::to_host);
    if (!layout)
      throw InputError(where_of(sc, spec.producer) + ": " + spec.name + " (" + type_text(spec) +
                       ") has no frame in the bridge protocol (docs/bridges.md)");
    OutputRoute r;
    r.layout = layout;
    r.field.fill(-1);
    for (std::size_t i = 0; i < layout->fields.size() && i < r.field.size(); ++i)
      r.field[i] = index_of(spec.fields, layout->fields[i]);
    route_of_[s] = static_cast<int16_t>(routes_.size());
    routes_.push_back(r);
    if (spec.plant_state && truth_signal_ == SIZE_MAX) truth_signal_ = s;
  }

  const auto remote = exec_.remote_inputs();
  if (remote.size() > 1) {
    std::string names;
    for (std::size_t s : remote) names += (names.empty() ? "" : ", ") + signals[s].name;
    throw InputError(sc.file + ": robot " + robot_ + " reads " + std::to_string(remote.size()) + " signals (" + names +
                     "); a device takes exactly one command");
  }
  if (remote.size() == 1) {
    cmd_signal_ = remote.front();
    const auto& spec = signals[cmd_signal_];
    cmd_layout_ = link::find_layout(topic_of(spec), spec.message, link::Direction::to_device);
    if (!cmd_layout_)
      throw InputError(sc.file + ": robot " + robot_ + ": " + spec.name + " (" + type_text(spec) +
                       ") has no frame in the bridge protocol (docs/bridges.md)");
    cmd_field_.assign(spec.fields.size(), -1);
    for (std::size_t f = 0; f < spec.fields.size(); ++f)
      for (std::size_t i = 0; i < cmd_layout_->fields.size(); ++i)
        if (spec.fields[f] == cmd_layout_->fields[i]) cmd_field_[f] = static_cast<int16_t>(i);
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
    for (std::size_t i = 0; i < nf; ++i)
      link::put_f64_le(payload_ + 8 * i, r.field[i] >= 0 ? sample.values[static_cast<std::size_t>(r.field[i])] : 0.0);
    ++c_.frames_produced;
    out_->send(r.layout->id, r.seq++, payload_, 8 * nf);
  };
}

void EmulatedDevice::start(int64_t now_ns) { last_cmd_ns_ = now_ns; }

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
  double v[link::kMaxPayload / 8];
  for (std::size_t i = 0; i < cmd_layout_->fields.size(); ++i) {
    v[i] = link::get_f64_le(f.payload + 8 * i);
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
  for (std::size_t i = 0; i < spec.fields.size() && i < scenario::kMaxSignalFields; ++i) j[spec.fields[i]] = truth_.values[i];
  return j;
}

}  // namespace plexus::emulator
