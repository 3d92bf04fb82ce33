#include "plexus/scenario/registry.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>

namespace plexus::scenario {
namespace {

std::map<std::string, ComponentType>& types() {
  static std::map<std::string, ComponentType> registry;  // constructed on first use: safe at static init
  return registry;
}

}  // namespace

ComponentRegistration::ComponentRegistration(std::string name, ComponentKind kind, std::string summary,
                                             ComponentFactory factory) {
  auto [it, added] = types().emplace(name, ComponentType{name, kind, std::move(summary), std::move(factory)});
  if (!added) {
    std::fprintf(stderr, "plexus: component type '%s' registered twice\n", name.c_str());
    std::abort();
  }
}

const ComponentType* find_component_type(const std::string& name) {
  auto it = types().find(name);
  return it == types().end() ? nullptr : &it->second;
}

std::vector<const ComponentType*> component_types() {
  std::vector<const ComponentType*> out;
  for (const auto& [name, type] : types()) out.push_back(&type);
  return out;
}

}  // namespace plexus::scenario
