#include "robot_frames.hpp"

#include <cstdio>

#include "plexus/base/input_error.hpp"
#include "plexus/link/frame.hpp"

namespace plexus::bridge {
namespace {

std::string where_of(const scenario::Scenario& sc, const std::string& component) {
  for (const auto& c : sc.components)
    if (c.component->name() == component) return c.where;
  return sc.file;
}

std::string no_frame(const scenario::SignalSpec& s, bool declared) {
  return s.name + " (" + (s.message.empty() ? "no IDL type" : s.message) + ") has no frame in " +
         (declared ? "the source's own `frames`" : "the bridge protocol (docs/bridges.md lists the frames)");
}

/// The built-in table sized for the robot's arm (its per-joint frames, link::for_joints): the
/// joints its signals carry, which every per-joint frame must agree on. The table itself when
/// the robot has none of them.
std::shared_ptr<const link::FrameTable> sized_for_joints(const scenario::Scenario& sc,
                                                         const scenario::StepExecutor& wiring,
                                                         const std::string& robot) {
  const link::FrameTable& builtin = link::message_layouts();
  const auto& signals = wiring.signals();
  std::size_t joints = 0;
  std::string first;
  const auto consider = [&](std::size_t s, link::Direction direction) {
    const auto& spec = signals[s];
    const auto* l = link::find_layout(builtin, robot_topic(spec.name, robot), spec.message, direction);
    if (!l || !link::per_joint(*l)) return;
    const std::size_t n = link::joints_in(*l, spec.fields);
    const std::string where = spec.producer.empty() ? sc.file : where_of(sc, spec.producer);
    if (n == 0 || n > link::kMaxJoints)
      throw InputError(where + ": " + spec.name + " carries " + std::to_string(n) +
                       " joints; the bridge protocol's joint frames carry 1 .. " + std::to_string(link::kMaxJoints));
    if (joints != 0 && n != joints)
      throw InputError(where + ": " + spec.name + " carries " + std::to_string(n) + " joints and " + first + " " +
                       std::to_string(joints) + "; one robot's joint frames agree");
    joints = n;
    first = spec.name;
  };
  for (std::size_t s : wiring.local_outputs()) consider(s, link::Direction::to_host);
  for (std::size_t s : wiring.remote_inputs()) consider(s, link::Direction::to_device);
  if (joints == 0) return {&builtin, [](const link::FrameTable*) {}};  // static: not owned
  auto table = std::make_shared<link::FrameTable>();
  for (const auto& l : builtin) table->push_back(link::per_joint(l) ? link::for_joints(l, joints) : l);
  return table;
}

}  // namespace

std::shared_ptr<const link::FrameTable> frame_table(const std::vector<scenario::DeclaredFrame>& frames,
                                                    std::size_t extra_bytes) {
  if (frames.empty()) return {&link::message_layouts(), [](const link::FrameTable*) {}};  // static: not owned
  auto table = std::make_shared<link::FrameTable>();
  for (const auto& d : frames) {
    const auto id = static_cast<uint8_t>(d.id);
    char hex[8];
    std::snprintf(hex, sizeof hex, "0x%02X", id);
    if (link::is_link_id(id))
      throw InputError(d.where + ": id " + hex +
                       " is the link's own (STOP 0x8F, time exchange 0x0E and 0x8E, cycle 0x8D)");
    if ((id >= 0x80) != d.to_device)
      throw InputError(d.where + ": id " + hex + ": " + (d.to_device ? "host -> device" : "device -> host") +
                       " ids are " + (d.to_device ? "0x80 .. 0xFF" : "0x00 .. 0x7F"));
    link::MessageLayout l;
    l.id = id;
    l.direction = d.to_device ? link::Direction::to_device : link::Direction::to_host;
    l.topic = d.topic;
    l.idl_type = d.type;
    l.meaning = d.meaning;
    for (const auto& f : d.fields) {
      link::WireField w{f.name, link::WireKind::f64, f.scale};
      link::parse_wire_kind(f.wire, w.kind);  // checked by the scenario loader
      l.fields.push_back(w);
    }
    if (l.fields.size() > link::kMaxFields)
      throw InputError(d.where + ": " + std::to_string(l.fields.size()) + " fields; a frame carries " +
                       std::to_string(link::kMaxFields) + " at most");
    const std::size_t extra = d.to_device ? 0 : extra_bytes;
    if (l.payload_size() + extra > link::kMaxPayload)
      throw InputError(d.where + ": a payload of " + std::to_string(l.payload_size()) + " bytes" +
                       (extra ? " and the device time's 8" : "") + " is longer than a frame's " +
                       std::to_string(link::kMaxPayload));
    table->push_back(std::move(l));
  }
  return table;
}

std::string robot_topic(const std::string& signal, const std::string& robot) {
  const std::string prefix = robot + "/";
  return signal.compare(0, prefix.size(), prefix) == 0 ? signal.substr(prefix.size()) : signal;
}

RobotFrames robot_frames(const scenario::Scenario& sc, const scenario::StepExecutor& wiring, const std::string& who) {
  RobotFrames f;
  for (const auto& c : sc.components) {
    if (c.kind != scenario::ComponentKind::plant && c.kind != scenario::ComponentKind::sensor)
      throw InputError(c.where + ": " + who + " stands in for one robot's plant and sensors; '" + c.component->name() +
                       "' is a " + scenario::to_string(c.kind));
    const std::string robot = c.component->name().substr(0, c.component->name().find('/'));
    if (!f.robot.empty() && robot != f.robot)
      throw InputError(c.where + ": " + who + " serves one robot (" + f.robot + " and " + robot + " here)");
    f.robot = robot;
  }
  if (f.robot.empty()) throw InputError(sc.file + ": no robot (plant and sensors) for " + who);
  const auto src = sc.sources.find(f.robot);
  const bool declared = src != sc.sources.end() && !src->second.frames.empty();
  f.table = declared ? frame_table(src->second.frames, src->second.device_time ? 8 : 0)
                     : sized_for_joints(sc, wiring, f.robot);
  const auto& signals = wiring.signals();
  for (std::size_t s : wiring.local_outputs()) {
    const auto& spec = signals[s];
    const auto* layout =
        link::find_layout(*f.table, robot_topic(spec.name, f.robot), spec.message, link::Direction::to_host);
    if (!layout) throw InputError(where_of(sc, spec.producer) + ": " + no_frame(spec, declared));
    f.outputs.push_back({s, layout});
  }
  const auto commands = wiring.remote_inputs();
  if (commands.size() > 1) {
    std::string names;
    for (std::size_t s : commands) names += (names.empty() ? "" : ", ") + signals[s].name;
    throw InputError(sc.file + ": robot " + f.robot + " reads " + std::to_string(commands.size()) + " signals (" +
                     names + ") from other processes; " + who + " takes exactly one command");
  }
  if (commands.size() == 1) {
    const auto& spec = signals[commands.front()];
    const auto* layout =
        link::find_layout(*f.table, robot_topic(spec.name, f.robot), spec.message, link::Direction::to_device);
    if (!layout) throw InputError(sc.file + ": robot " + f.robot + ": " + no_frame(spec, declared));
    f.command = RobotFrames::Route{commands.front(), layout};
  }
  return f;
}

}  // namespace plexus::bridge
