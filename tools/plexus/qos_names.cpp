#include "qos_names.hpp"

#include "plexus/base/input_error.hpp"

namespace plexus::cli {

void check_qos_names(const scenario::Scenario& sc, const rt::QosProfiles& profiles, const std::string& qos_file) {
  for (const auto& c : sc.components)
    if (!c.qos.empty() && !profiles.contains(c.qos))
      throw InputError(c.where + ".qos: unknown QoS profile '" + c.qos + "' in " + qos_file);
}

}  // namespace plexus::cli
