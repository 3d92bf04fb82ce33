// The QoS profiles a scenario names: checked the same way by `plexus sim` and `plexus launch`
// before anything runs, so that a scenario `sim` accepts also launches.
#pragma once

#include <string>

#include "plexus/runtime/qos.hpp"
#include "plexus/scenario/scenario.hpp"

namespace plexus::cli {

/// Throws InputError "file:line: services.<name>.qos: unknown QoS profile 'x' in <qos_file>"
/// for the first component whose `qos` is not a profile of `profiles`.
void check_qos_names(const scenario::Scenario& sc, const rt::QosProfiles& profiles, const std::string& qos_file);

}  // namespace plexus::cli
