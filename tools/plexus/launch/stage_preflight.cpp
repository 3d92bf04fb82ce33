// Stage 2 of plexus launch: every check that needs more than this host, before anything
// starts (stages.hpp; the checks themselves: preflight.hpp, remote_share.hpp).
#include "preflight.hpp"
#include "qos_names.hpp"
#include "stages.hpp"

namespace plexus::cli {

bool preflight_launch(const LaunchOptions& o, LaunchPlan& plan, LaunchRun& run) {
  // Every QoS profile the scenario names must exist before anything starts.
  check_qos_names(plan.sc, plan.profiles, plan.qos_file);
  // Every host reachable, the same version, the same scenario digest, its address on an
  // interface, clocks that agree.
  const std::string digest = scenario_digest(plan.sc, plan.qos_file);
  const std::string& address = plan.net.interface_address;
  if (plan.session) {
    const RemoteReady ready{digest, plan.qos_file, address, address_on_interface(address),
                            static_cast<int>(plan.procs.size())};
    return plan.session->ready_and_wait_go(ready, plan.request.clock_injection_ns);
  }
  if (plan.one_command)
    run.remotes = preflight_hosts(plan.sc, o.host, address, plan.remote_hosts,
                                  {o.scenario, o.ssh_config, o.out, o.dds, o.qos_file, o.sets, o.vendors, o.externals,
                                   o.clock_injections, plan.domain, o.timeout, o.allow_clock_offset},
                                  PLEXUS_VERSION, digest);
  return true;
}

}  // namespace plexus::cli
