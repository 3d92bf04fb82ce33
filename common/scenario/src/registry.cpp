#include "plexus/scenario/registry.hpp"

#include <algorithm>

#include <cstdio>
#include <cstdlib>

#include "named_registry.hpp"

namespace plexus::scenario {
namespace {

detail::NamedRegistry<ComponentType>& component_type_registry() {
  static detail::NamedRegistry<ComponentType> registry("component type");  // built on first use
  return registry;
}

detail::NamedRegistry<ServiceDeclaration>& service_registry() {
  static detail::NamedRegistry<ServiceDeclaration> registry("service");
  return registry;
}

}  // namespace

ComponentRegistration::ComponentRegistration(std::string name, ComponentKind kind, std::string summary,
                                             ComponentFactory factory, std::vector<std::string> figures) {
  component_type_registry().add(
      ComponentType{std::move(name), kind, std::move(summary), std::move(factory), std::move(figures)});
}

bool takes_part_in(const std::string& type, const std::string& figure) {
  const ComponentType* t = find_component_type(type);
  return t && std::find(t->figures.begin(), t->figures.end(), figure) != t->figures.end();
}

const ComponentType* find_component_type(const std::string& name) { return component_type_registry().find(name); }

std::vector<const ComponentType*> component_types() { return component_type_registry().all(); }

const char* to_string(ServiceRole role) {
  switch (role) {
    case ServiceRole::plant: return "plant";
    case ServiceRole::service: return "service";
    case ServiceRole::host: return "host";
  }
  return "?";
}

ServiceRegistration::ServiceRegistration(ServiceDeclaration declaration) {
  for (const auto& t : declaration.component_types)
    if (const ServiceDeclaration* other = service_declaring(t)) {
      std::fprintf(stderr, "plexus: component type '%s' is declared by both services %s and %s\n", t.c_str(),
                   other->name.c_str(), declaration.name.c_str());
      std::abort();
    }
  service_registry().add(std::move(declaration));
}

const ServiceDeclaration* find_service(const std::string& name) { return service_registry().find(name); }

const ServiceDeclaration* service_declaring(const std::string& type) {
  for (const ServiceDeclaration* s : service_registry().all())
    for (const auto& t : s->component_types)
      if (t == type) return s;
  return nullptr;
}

const ServiceDeclaration* host_service() {
  for (const ServiceDeclaration* s : service_registry().all())
    if (s->role == ServiceRole::host) return s;
  return nullptr;
}

std::string executable_for(const std::string& type) {
  if (const ServiceDeclaration* s = service_declaring(type)) return s->name;
  const ServiceDeclaration* host = host_service();
  return host ? host->name : "";
}

std::string plant_executable_for(const std::string& plant_type, const std::vector<std::string>& sensor_types) {
  const ServiceDeclaration* plant = service_declaring(plant_type);
  bool fits = plant && plant->role == ServiceRole::plant;
  for (const auto& t : sensor_types) {
    const ServiceDeclaration* s = service_declaring(t);
    fits = fits && (!s || s == plant);  // a plant service hosts the sensors no other service declares
  }
  if (fits) return plant->name;
  const ServiceDeclaration* host = host_service();
  return host ? host->name : "";
}

std::vector<const ServiceDeclaration*> services() { return service_registry().all(); }

}  // namespace plexus::scenario
