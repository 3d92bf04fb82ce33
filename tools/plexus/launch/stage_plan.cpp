// Stage 1 of plexus launch: what runs where, decided before anything starts (stages.hpp).
#include <algorithm>
#include <csignal>
#include <map>
#include <set>

#include "plexus/base/clock.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/runtime/transport.hpp"
#include "plexus/runtime/vendor.hpp"
#include "preflight.hpp"
#include "stages.hpp"

namespace plexus::cli {
namespace {

/// --remote: started over ssh, the scenario and the options come from the launcher.
void take_remote_request(LaunchOptions& o, LaunchPlan& plan) {
  stop_on_signal(SIGHUP);
  plan.session = std::make_unique<RemoteSession>(PLEXUS_VERSION);
  const RemoteRequest& r = plan.request = plan.session->read_request();
  o.host = r.host, o.scenario = r.scenario_origin, o.sets = r.sets, o.vendors = r.vendors;
  o.externals = r.externals, o.dds = r.dds, o.qos_file = r.qos_file, o.out = r.out;
  o.domain = r.domain, o.timeout = r.timeout;
}

/// The scenario with its overrides; one command over many hosts when its hosts name ssh
/// destinations and no --host is given (this host is then the first).
void load_launch_scenario(LaunchOptions& o, LaunchPlan& plan) {
  // --transport is dds.transport overridden: as a --set it reaches the hosts over ssh too.
  if (!o.remote && !o.transport.empty()) {
    rt::parse_transport(o.transport, "--transport");
    o.sets.push_back("dds.transport=" + o.transport);
    o.transport.clear();
  }
  if (!o.remote && !o.naming.empty()) {  // --naming likewise
    rt::parse_naming(o.naming, "--naming");
    o.sets.push_back("dds.naming=" + o.naming);
    o.naming.clear();
  }
  for (const auto& s : o.sets) plan.overrides.push_back(scenario::parse_override(s));
  plan.sc = plan.session ? scenario::load_scenario_text(plan.request.scenario_text, o.scenario, plan.overrides)
                         : scenario::load_scenario(o.scenario, plan.overrides);
  const scenario::Scenario& sc = plan.sc;
  plan.one_command = o.host.empty() && !o.remote && uses_ssh(sc);
  if (plan.one_command) plan.remote_hosts = ssh_hosts(sc);
  if (plan.one_command) o.host = sc.hosts.front();
  for (const auto& [robot, src] : sc.sources)
    if (sc.clock != scenario::ClockMode::realtime)
      throw InputError(src.where + ": robot " + robot + "'s source is " + scenario::to_string(src.type) +
                       ", which keeps its own time: set clock.mode: realtime (or --set clock.mode=realtime)");
}

/// Loopback, or this host's address with every host of the scenario as a peer.
rt::NetworkOptions network_of(const LaunchOptions& o, const scenario::Scenario& sc) {
  rt::NetworkOptions net;
  net.max_participants_per_host = cli::participants_per_host(sc);
  net.transport = rt::parse_transport(sc.dds_transport, o.scenario + ": dds.transport");
  if (!o.host.empty() && !sc.host_address.at(o.host).empty()) {
    net.interface_address = sc.host_address.at(o.host);
    net.peers.clear();
    for (const auto& h : sc.hosts) {
      if (sc.host_address.at(h).empty())
        throw InputError(o.scenario + ": hosts." + h + ".address: needed when hosts have addresses");
      net.peers.push_back(sc.host_address.at(h));
    }
  }
  return net;
}

/// Vendor, domain, QoS profiles, this host's processes and the network.
void resolve_settings(const LaunchOptions& o, LaunchPlan& plan) {
  const scenario::Scenario& sc = plan.sc;
  plan.vendor = !o.dds.empty() ? o.dds : (!sc.dds_vendor.empty() ? sc.dds_vendor : "fast");
  rt::parse_vendor(plan.vendor, "--dds");
  plan.domain = o.domain >= 0 ? o.domain : sc.dds_domain;
  plan.qos_file = o.qos_file.empty() ? rt::default_qos_file() : o.qos_file;
  plan.profiles = rt::QosProfiles::load(plan.qos_file);
  plan.lockstep_qos = plan.profiles.get("lockstep");
  if (!o.host.empty() && std::find(sc.hosts.begin(), sc.hosts.end(), o.host) == sc.hosts.end())
    throw InputError("--host " + o.host + ": no such host in " + o.scenario);
  plan.procs = cli::plan(sc, o.host);  // launch_plan.hpp
  plan.net = network_of(o, sc);
  for (const auto& p : plan.net.peers) plan.peers += (plan.peers.empty() ? "" : ",") + p;
  plan.runs_clock = o.host.empty() || o.host == sc.hosts.front();
  plan.everywhere = cli::plan(sc, "");
  plan.realtime = sc.clock == scenario::ClockMode::realtime;
}

/// --vendor PROCESS=VENDOR, by process name (checked against every host's processes later).
std::map<std::string, std::string> vendor_overrides(const std::vector<std::string>& vendors) {
  std::map<std::string, std::string> vendor_of;
  for (const auto& v : vendors) {
    const auto eq = v.find('=');
    if (eq == std::string::npos) throw InputError("--vendor " + v + ": expected PROCESS=fast|cyclone");
    rt::parse_vendor(v.substr(eq + 1), "--vendor " + v);
    vendor_of[v.substr(0, eq)] = v.substr(eq + 1);
  }
  return vendor_of;
}

/// --external, --vendor and each process's vendor: --vendor, else its scenario `dds` key,
/// else --dds / dds.vendor.
void resolve_processes(const LaunchOptions& o, LaunchPlan& plan) {
  std::map<std::string, std::string> vendor_of = vendor_overrides(o.vendors);
  std::string names;  // the scenario's processes, for the error that names none of them
  for (const auto& p : plan.everywhere) names += (names.empty() ? "" : ", ") + p.name;
  // --external: a process the scenario declares but something else provides (plexus replay,
  // a hardware bridge) on the same topics. Not started; the lockstep clock still waits for it.
  plan.externals = o.externals;
  auto& procs = plan.procs;
  for (const auto& e : o.externals) {
    const auto& all = plan.everywhere;
    if (std::none_of(all.begin(), all.end(), [&](const Process& p) { return p.name == e; }))
      throw InputError("--external " + e + ": no such process (this scenario's: " + names + ")");
    procs.erase(std::remove_if(procs.begin(), procs.end(), [&](const Process& p) { return p.name == e; }), procs.end());
  }
  for (auto& p : procs)
    p.vendor = vendor_of.count(p.name) ? vendor_of[p.name] : p.vendor.empty() ? plan.vendor : p.vendor;
  std::set<std::string> used{plan.vendor};  // for the headline
  for (const auto& p : procs) used.insert(p.vendor);
  plan.vendors_label = used.size() == 1 ? plan.vendor : "mixed: fast + cyclone";
  for (const auto& p : plan.everywhere) vendor_of.erase(p.name);  // names of processes on any host are fine
  if (!vendor_of.empty())
    throw InputError("--vendor " + vendor_of.begin()->first + ": no such process (this scenario's: " + names + ")");
}

/// DDS Security: every participant's identity checked, and a mixed deployment whose
/// handshakes would fail refused, before anything starts (launch_security.hpp).
LaunchSecurity security_of(const LaunchOptions& o, const LaunchPlan& plan) {
  std::vector<Process> all_vendors = plan.everywhere;
  for (auto& p : all_vendors) {
    const auto named = std::find_if(o.vendors.begin(), o.vendors.end(),
                                    [&](const std::string& v) { return v.rfind(p.name + "=", 0) == 0; });
    p.vendor = named != o.vendors.end() ? named->substr(p.name.size() + 1) : p.vendor.empty() ? plan.vendor : p.vendor;
  }
  all_vendors.erase(
      std::remove_if(all_vendors.begin(), all_vendors.end(), [&](const Process& p) { return plan.is_external(p); }),
      all_vendors.end());
  try {
    return plan_security(plan.sc, all_vendors, plan.vendor);
  } catch (const InputError& e) {  // a section set by --set has no line: name the override
    throw InputError(scenario::attribute_to_override(e.what(), o.scenario, plan.overrides));
  }
}

}  // namespace

LaunchPlan plan_launch(LaunchOptions& o) {
  LaunchPlan plan;
  plan.command_ns = monotonic_ns();
  if (!o.remote && o.scenario.empty()) throw InputError("scenario: required (the scenario file)");
  if (o.remote) take_remote_request(o, plan);
  load_launch_scenario(o, plan);
  resolve_settings(o, plan);
  resolve_processes(o, plan);
  plan.security = security_of(o, plan);
  return plan;
}

}  // namespace plexus::cli
