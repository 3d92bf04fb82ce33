// Which deployable service executable hosts which component types (docs/architecture.md,
// services/).
// `plexus launch` starts each service component in the executable its type belongs to;
// each executable refuses component types that are not its own. Types not listed run in
// the generic `component_host` (references, test drivers, user components).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace plexus::distributed {

struct ServiceExecutable {
  const char* name;                     ///< executable in build/bin
  std::vector<std::string_view> types;  ///< component types it hosts
};

/// The catalogue (algorithm variants are parameters of these types, not other executables).
inline const std::vector<ServiceExecutable>& service_catalog() {
  static const std::vector<ServiceExecutable> catalog{
      {"localisation_observer", {"heading_observer", "velocity_heading_observer"}},
      {"motion_controller", {"trajectory_tracking", "path_following", "reference_feedforward", "skid_steer_driver"}},
      {"terrain_classifier", {"terrain_classifier", "terrain_recorder"}},
      {"icr_estimator", {"icr_ekf", "icr_odometry", "icr_library_recorder"}},
      // The attitude filter service also runs the balancing controller when the scenario
      // puts one on it; as separate components they can still be split over processes.
      {"attitude_filter", {"attitude_filter", "balancing_controller", "motion_profile"}},
      {"joint_controller", {"arm_vdc", "arm_ct_pd", "arm_ekf"}},
  };
  return catalog;
}

/// The executable that hosts a component type: its catalogue entry, else "component_host".
inline std::string executable_for(std::string_view type) {
  for (const auto& s : service_catalog())
    for (auto t : s.types)
      if (t == type) return s.name;
  return "component_host";
}

}  // namespace plexus::distributed
