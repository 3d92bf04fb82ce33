#include "plexus/scenario/component.hpp"

namespace plexus::scenario {

const char* to_string(ComponentKind kind) {
  switch (kind) {
    case ComponentKind::plant: return "plant";
    case ComponentKind::sensor: return "sensor";
    case ComponentKind::reference: return "reference";
    case ComponentKind::estimator: return "estimator";
    case ComponentKind::controller: return "controller";
  }
  return "?";
}

namespace {

std::string resolve_signal(const std::string& robot, const std::map<std::string, std::string>& remap,
                           const std::string& port) {
  if (auto it = remap.find(port); it != remap.end()) return it->second;
  if (robot.empty() || (port.find('/') != std::string::npos && port.rfind("truth/", 0) != 0)) return port;
  return robot + "/" + port;
}

}  // namespace

std::string ComponentConfig::signal_for(const std::string& port) const { return resolve_signal(robot, remap, port); }

std::string Component::default_signal(const std::string& port) const { return resolve_signal(robot_, {}, port); }

void ComponentConfig::warn(std::string text, std::string detail) const {
  if (warnings) warnings->push_back({std::move(text), std::move(detail)});
}

Component::Component(const ComponentConfig& config) : name_(config.name), robot_(config.robot), remap_(config.remap) {}

InputPort& Component::add_input(const std::string& port, std::vector<std::string> fields, std::string message) {
  inputs_.push_back(
      std::make_unique<InputPort>(port, resolve_signal(robot_, remap_, port), std::move(fields), std::move(message)));
  return *inputs_.back();
}

OutputPort& Component::add_output(const std::string& port, std::vector<std::string> fields, std::string message) {
  outputs_.push_back(
      std::make_unique<OutputPort>(port, resolve_signal(robot_, remap_, port), std::move(fields), std::move(message)));
  return *outputs_.back();
}

std::string Component::signal_of(const std::string& port) const { return resolve_signal(robot_, remap_, port); }

void Component::add_tunable(std::string key, std::string description, std::function<double()> get,
                            std::function<void(double)> set) {
  tunables_.push_back({std::move(key), std::move(description), std::move(get), std::move(set)});
}

const TunableParameter* Component::tunable(const std::string& key) const {
  for (const auto& t : tunables_)
    if (t.key == key) return &t;
  return nullptr;
}

void Component::hold(int64_t, double) {
  for (auto& out : outputs_) out->clear();
}

}  // namespace plexus::scenario
