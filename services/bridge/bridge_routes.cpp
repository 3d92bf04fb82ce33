#include "bridge_routes.hpp"

#include <algorithm>
#include <cmath>

#include "plexus/base/input_error.hpp"
#include "plexus/distributed/lockstep.hpp"
#include "plexus/distributed/realtime.hpp"
#include "plexus/scenario/step_executor.hpp"

namespace plexus::bridge {
namespace {

std::string suffix(const std::string& signal, const std::string& robot) { return signal.substr(robot.size() + 1); }

/// The signal with the layout's fields: the bridge publishes every member the frame carries.
std::unique_ptr<scenario::SignalSpec> framed_spec(const scenario::SignalSpec& s, const link::MessageLayout& l) {
  auto spec = std::make_unique<scenario::SignalSpec>(s);
  spec->fields.assign(l.fields.begin(), l.fields.end());
  return spec;
}

std::string where_of(const scenario::Scenario& sc, const std::string& component) {
  for (const auto& c : sc.components)
    if (c.component->name() == component) return c.where;
  return sc.file;
}

}  // namespace

BridgeRoutes make_routes(scenario::Scenario& sc, rt::Participant& p, const rt::QosProfiles& profiles) {
  BridgeRoutes r;
  r.sensor_by_id.fill(-1);
  for (const auto& c : sc.components) {
    if (c.kind != scenario::ComponentKind::plant && c.kind != scenario::ComponentKind::sensor)
      throw InputError(c.where + ": a bridge stands in for a robot's plant and sensors; '" + c.component->name() +
                       "' is a service");
    const std::string robot = c.component->name().substr(0, c.component->name().find('/'));
    if (!r.robot.empty() && robot != r.robot)
      throw InputError(c.where + ": a bridge serves one robot (" + r.robot + " and " + robot + " here)");
    r.robot = robot;
  }
  if (r.robot.empty()) throw InputError(sc.file + ": no robot to bridge");
  const scenario::StepExecutor wiring(sc);
  const auto& signals = wiring.signals();
  const int64_t step = distributed::step_ns(sc);
  for (std::size_t s : wiring.local_outputs()) {
    const auto& spec = signals[s];
    const std::string topic = suffix(spec.name, r.robot);
    const auto* layout = link::find_layout(topic, spec.message, link::Direction::to_host);
    if (!layout)
      throw InputError(where_of(sc, spec.producer) + ": " + spec.name + " (" + spec.message +
                       ") has no frame in the bridge protocol (docs/bridges.md lists the frames)");
    SensorRoute route;
    route.layout = layout;
    route.spec = framed_spec(spec, *layout);
    route.publisher = std::make_unique<distributed::WirePublisher>(p, *route.spec, step,
                                                                   distributed::signal_qos(sc, spec.producer, profiles));
    r.sensor_by_id[layout->id] = static_cast<int16_t>(r.sensors.size());
    r.sensors.push_back(std::move(route));
  }
  const auto commands = wiring.remote_inputs();
  if (commands.size() != 1)
    throw InputError(sc.file + ": robot " + r.robot + " reads " + std::to_string(commands.size()) +
                     " signals from other processes; a bridge forwards exactly one command");
  const auto& spec = signals[commands.front()];
  const std::string topic = suffix(spec.name, r.robot);
  const auto* layout = link::find_layout(topic, spec.message, link::Direction::to_device);
  if (!layout)
    throw InputError(sc.file + ": robot " + r.robot + ": " + spec.name + " (" + spec.message +
                     ") has no frame in the bridge protocol (docs/bridges.md lists the frames)");
  r.command.layout = layout;
  r.command.spec = framed_spec(spec, *layout);
  r.command.subscriber = std::make_unique<distributed::WireSubscriber>(p, *r.command.spec, step,
                                                                       distributed::input_qos(sc, spec, profiles));
  r.command.period_ns = spec.period_steps * step;
  r.command.deadline_ns = std::llround(sc.input_deadline_periods * static_cast<double>(r.command.period_ns));
  return r;
}

}  // namespace plexus::bridge
