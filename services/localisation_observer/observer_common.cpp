#include "services/localisation_observer/observer_common.hpp"

#include <string>

namespace plexus::scenario {

algorithms::ObserverDiscretisation discretisation(const YamlMap& p) {
  const auto s = p.optional<std::string>("discretisation", "exact_arc");
  if (s == "exact_arc") return algorithms::ObserverDiscretisation::kExactArc;
  if (s == "held_position") return algorithms::ObserverDiscretisation::kHeldPosition;
  p.fail("discretisation", "expected exact_arc or held_position, got '" + s + "'");
}

}  // namespace plexus::scenario
