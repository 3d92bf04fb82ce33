#include "systemd_units.hpp"

#include <algorithm>
#include <cctype>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "launch/launch_plan.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/scenario/registry.hpp"

namespace plexus::cli {

std::string unit_word(const std::string& s) {
  std::string out;
  for (char c : s) out += std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '-' ? c : '-';
  return out;
}

std::string exec_argument(const std::string& s) {
  std::string body;
  bool quote = s.empty();
  for (char c : s) {
    if (c == '%')
      body += "%%";  // systemd specifier
    else if (c == '$')
      body += "$$";  // environment variable expansion
    else if (c == '"' || c == '\\')
      body += std::string("\\") + c, quote = true;
    else
      body += c;
    quote = quote || c == ' ' || c == '\t' || c == '\'' || c == ';';
  }
  return quote ? "\"" + body + "\"" : body;
}

namespace {

const char* restart_of(const Process& p) {
  const scenario::ServiceDeclaration* service = scenario::find_service(p.program);
  // A plant-side service holds the physical state: never restarted, as under plexus launch.
  if (service && service->role == scenario::ServiceRole::plant) return "no";
  if (!service && p.select.front() == "--robots") return "on-failure";  // a bridge or replay
  if (p.restart == "always") return "always";
  if (p.restart == "never") return "no";
  return "on-failure";
}

std::string join(const std::vector<std::string>& v, const std::string& sep) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : sep) + x;
  return s;
}

}  // namespace

UnitSet make_units(const scenario::Scenario& sc, const UnitOptions& o) {
  if (!o.host.empty() && std::find(sc.hosts.begin(), sc.hosts.end(), o.host) == sc.hosts.end())
    throw InputError("--host " + o.host + ": no such host in " + sc.file);
  if (o.host.empty() && !sc.hosts.empty())
    throw InputError("--host: needed: " + sc.file + " has hosts (units are written for one host)");
  std::vector<Process> procs = plan(sc, o.host);
  if (procs.empty()) throw InputError("--host " + o.host + ": no process of " + sc.file + " runs there");
  const std::string vendor = !o.dds.empty() ? o.dds : !sc.dds_vendor.empty() ? sc.dds_vendor : "fast";
  auto unknown = o.vendor_of;
  for (const auto& p : plan(sc, "")) unknown.erase(p.name);
  if (!unknown.empty()) throw InputError("--vendor " + unknown.begin()->first + ": no such process");
  const int domain = o.domain >= 0 ? o.domain : sc.dds_domain;
  const int participants = participants_per_host(sc);
  std::string interface_address, peers;
  if (!o.host.empty() && !sc.host_address.at(o.host).empty()) {
    interface_address = sc.host_address.at(o.host);
    std::vector<std::string> all;
    for (const auto& h : sc.hosts) {
      if (sc.host_address.at(h).empty())
        throw InputError(sc.file + ": hosts." + h + ".address: needed when hosts have addresses");
      all.push_back(sc.host_address.at(h));
    }
    peers = join(all, ",");
  }
  UnitSet set;
  const std::string prefix = "plexus-" + unit_word(sc.name) + (o.host.empty() ? "" : "-" + unit_word(o.host));
  set.target = prefix + ".target";
  const std::string qos = o.config_dir + "/qos.yaml";
  std::vector<std::string> names;
  for (const auto& p : procs) {
    const std::string v = o.vendor_of.count(p.name) ? o.vendor_of.at(p.name) : p.vendor.empty() ? vendor : p.vendor;
    const std::string file = unit_word(p.name) + ".yaml";
    // Its part of the scenario, as plexus launch writes it, without `duration`: a unit runs until stopped.
    YAML::Node part = part_document(sc, p);
    part.remove("duration");
    part["base_dir"] = o.config_dir;  // relative file parameters: next to the part files
    YAML::Emitter yaml;
    yaml << part;
    set.config.push_back({file, std::string("# ") + p.service() + " on host " + (o.host.empty() ? "(any)" : o.host) +
                                    ": its part of scenario " + sc.name + " (plexus deploy units)\n" + yaml.c_str() +
                                    "\n"});
    std::vector<std::string> args;
    if (p.program == "replay") {
      args = replay_args(sc, p);
      args.insert(args.begin(), o.bin_dir + "/plexus");
    } else {
      args = {o.bin_dir + "/" + p.executable(),
              "--part",
              o.config_dir + "/" + file,
              "--service",
              p.service(),
              "--mode",
              "realtime"};
      if (p.priority > 0) args.insert(args.end(), {"--priority", std::to_string(p.priority)});
      if (p.cpu >= 0) args.insert(args.end(), {"--cpu", std::to_string(p.cpu)});
    }
    args.insert(args.end(), {"--dds", v, "--domain", std::to_string(domain), "--qos-file", qos});
    if (!interface_address.empty()) args.insert(args.end(), {"--interface", interface_address, "--peers", peers});
    // The scenario's transport (plexus launch passes it the same way); auto is every program's default.
    if (sc.dds_transport != "auto") args.insert(args.end(), {"--transport", sc.dds_transport});
    if (sc.dds_naming != "plexus") args.insert(args.end(), {"--naming", sc.dds_naming});
    if (participants != kDefaultParticipantsPerHost)  // as plexus launch gives its processes
      args.insert(args.end(), {"--max-participants", std::to_string(participants)});
    std::string exec;
    for (const auto& a : args) exec += (exec.empty() ? "" : " ") + exec_argument(a);
    std::ostringstream u;
    u << "# " << p.service() << ": process of scenario " << sc.name << " on host "
      << (o.host.empty() ? "(any)" : o.host) << ", written by plexus deploy units (docs/deployment.md)\n"
      << "[Unit]\n"
      << "Description=plexus " << sc.name << ": " << p.service() << "\n"
      << "PartOf=" << set.target << "\n"
      << "Wants=network-online.target\n"
      << "After=network-online.target\n\n"
      << "[Service]\n"
      << "Type=exec\n"
      << "ExecStart=" << exec << "\n"
      << "Restart=" << restart_of(p) << "\n";
    if (p.restart_delay_ns > 0) u << "RestartSec=" << static_cast<double>(p.restart_delay_ns) * 1e-9 << "s\n";
    u << "KillSignal=SIGTERM\n"
      << "TimeoutStopSec=10s\n";
    if (p.priority > 0) u << "LimitRTPRIO=" << p.priority << "\nLimitMEMLOCK=infinity\n";
    if (p.cpu >= 0) u << "CPUAffinity=" << p.cpu << "\n";
    u << "\n[Install]\n"
      << "WantedBy=" << set.target << "\n";
    const std::string name = prefix + "-" + unit_word(p.name) + ".service";
    names.push_back(name);
    set.units.push_back({name, u.str()});
  }
  std::ostringstream t;
  t << "# Scenario " << sc.name << " on host " << (o.host.empty() ? "(any)" : o.host) << ": " << procs.size()
    << " processes, written by plexus deploy units (docs/deployment.md)\n"
    << "[Unit]\n"
    << "Description=plexus " << sc.name << (o.host.empty() ? "" : " on host " + o.host) << "\n"
    << "Wants=" << join(names, " ") << "\n"
    << "After=network-online.target\n\n"
    << "[Install]\n"
    << "WantedBy=multi-user.target\n";
  set.units.push_back({set.target, t.str()});
  return set;
}

}  // namespace plexus::cli
