#include "plexus/scenario/registry.hpp"

#include "named_registry.hpp"

namespace plexus::scenario {
namespace {

detail::NamedRegistry<ComponentType>& types() {
  static detail::NamedRegistry<ComponentType> registry("component type");  // built on first use
  return registry;
}

}  // namespace

ComponentRegistration::ComponentRegistration(std::string name, ComponentKind kind, std::string summary,
                                             ComponentFactory factory) {
  types().add(ComponentType{std::move(name), kind, std::move(summary), std::move(factory)});
}

const ComponentType* find_component_type(const std::string& name) { return types().find(name); }

std::vector<const ComponentType*> component_types() { return types().all(); }

}  // namespace plexus::scenario
