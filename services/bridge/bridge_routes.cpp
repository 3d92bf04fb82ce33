#include "bridge_routes.hpp"

#include <algorithm>
#include <cmath>

#include "plexus/base/input_error.hpp"
#include "plexus/distributed/lockstep.hpp"
#include "plexus/distributed/realtime.hpp"
#include "plexus/scenario/step_executor.hpp"
#include "robot_frames.hpp"

namespace plexus::bridge {
namespace {

/// The signal with the layout's fields: the bridge publishes every member the frame carries.
std::unique_ptr<scenario::SignalSpec> framed_spec(const scenario::SignalSpec& s, const link::MessageLayout& l) {
  auto spec = std::make_unique<scenario::SignalSpec>(s);
  spec->fields.clear();
  for (const auto& f : l.fields) spec->fields.push_back(f.name);
  return spec;
}

}  // namespace

BridgeRoutes make_routes(scenario::Scenario& sc, rt::Participant& p, const rt::QosProfiles& profiles) {
  BridgeRoutes r;
  r.sensor_by_id.fill(-1);
  const scenario::StepExecutor wiring(sc);
  const RobotFrames frames = robot_frames(sc, wiring, "a bridge");
  r.robot = frames.robot;
  r.table = frames.table;
  if (!frames.command)
    throw InputError(sc.file + ": robot " + r.robot + " reads no command; a bridge forwards exactly one");
  const auto& signals = wiring.signals();
  const int64_t step = distributed::step_ns(sc);
  for (const auto& [s, layout] : frames.outputs) {
    const auto& spec = signals[s];
    SensorRoute route;
    route.layout = layout;
    route.spec = framed_spec(spec, *layout);
    route.publisher = std::make_unique<distributed::WirePublisher>(
        p, *route.spec, step, distributed::signal_qos(sc, spec.producer, profiles));
    r.sensor_by_id[layout->id] = static_cast<int16_t>(r.sensors.size());
    r.sensors.push_back(std::move(route));
  }
  const auto& spec = signals[frames.command->signal];
  r.command.layout = frames.command->layout;
  r.command.spec = framed_spec(spec, *r.command.layout);
  r.command.subscriber = std::make_unique<distributed::WireSubscriber>(p, *r.command.spec, step,
                                                                       distributed::input_qos(sc, spec, profiles));
  r.command.period_ns = spec.period_steps * step;
  r.command.deadline_ns = std::llround(sc.input_deadline_periods * static_cast<double>(r.command.period_ns));
  return r;
}

}  // namespace plexus::bridge
