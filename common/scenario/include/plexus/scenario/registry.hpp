// The component registry: component types by name, so a scenario composes plants,
// sensors, reference generators, estimators and controllers without code changes.
//
// A component type lives in the folder of the service executable that hosts it,
// services/<executable>/<type>.cpp (service_catalog.hpp; plants and sensors in
// plant_simulator/, other types in component_host/), with one static registration per type:
//
//   namespace {
//   class MyObserver final : public plexus::scenario::Component { ... };
//   const plexus::scenario::ComponentRegistration kMyObserver{
//       "my_observer", plexus::scenario::ComponentKind::estimator,
//       "one-line description shown by `plexus sim --list`",
//       [](const plexus::scenario::ComponentConfig& c) { return std::make_unique<MyObserver>(c); }};
//   }  // namespace
//
// The factory validates its parameters from `c.params()` (YamlMap: errors name file, line
// and key) and declares its ports in the component's constructor.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "plexus/scenario/component.hpp"

namespace plexus::scenario {

using ComponentFactory = std::function<std::unique_ptr<Component>(const ComponentConfig&)>;

struct ComponentType {
  std::string name;
  ComponentKind kind{};
  std::string summary;
  ComponentFactory factory;
};

/// Registers a component type at static-initialisation time. A second type with the
/// same name aborts the program at start-up (a programming error, found by any test).
struct ComponentRegistration {
  ComponentRegistration(std::string name, ComponentKind kind, std::string summary, ComponentFactory factory);
};

/// The registered type, or nullptr.
const ComponentType* find_component_type(const std::string& name);

/// All registered types, sorted by name.
std::vector<const ComponentType*> component_types();

}  // namespace plexus::scenario
