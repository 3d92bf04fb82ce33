#include "services/common/balancing_params.hpp"

namespace plexus::scenario {

algorithms::WheeledPendulumParams pendulum_params(const YamlMap& p) {
  algorithms::WheeledPendulumParams w;
  w.body_mass = p.optional<double>("body_mass", w.body_mass);
  w.com_height = p.optional<double>("com_height", w.com_height);
  w.body_inertia = p.optional<double>("body_inertia", w.body_inertia);
  w.wheel_mass = p.optional<double>("wheel_mass", w.wheel_mass);
  w.wheel_radius = p.optional<double>("wheel_radius", w.wheel_radius);
  w.wheel_inertia = p.optional<double>("wheel_inertia", w.wheel_inertia);
  w.gravity = p.optional<double>("gravity", w.gravity);
  w.max_torque = p.optional<double>("max_torque", w.max_torque);
  return w;
}

}  // namespace plexus::scenario
