// plexus deploy units SCENARIO [--host H] --out DIR [--bin DIR] [--config-dir DIR] [--set k=v ...]
//                      [--dds V] [--vendor PROCESS=V ...] [--domain N] [--qos-file FILE]
//
// Writes systemd units that start one host's share of a scenario at boot (systemd_units.hpp):
// DIR/<unit>.service per process, DIR/<target>.target, and DIR/config/ (each process's part of
// the scenario and the QoS profiles) to copy to --config-dir on the robot. docs/deployment.md.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>

#include "child_process.hpp"
#include "command.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/runtime/qos.hpp"
#include "plexus/runtime/vendor.hpp"
#include "plexus/scenario/scenario.hpp"
#include "systemd_units.hpp"

namespace plexus::cli {
namespace {

struct DeployOptions {
  std::string scenario, host, out, bin, config_dir, dds, qos_file;
  std::vector<std::string> sets, vendors;
  int domain = -1;
};

void write_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream f(path, std::ios::binary | std::ios::trunc);
  f << text;
  f.close();
  if (!f) throw InputError(path.string() + ": cannot write");
}

int run_units(const DeployOptions& o) {
  std::vector<scenario::Override> overrides;
  for (const auto& s : o.sets) overrides.push_back(scenario::parse_override(s));
  const scenario::Scenario sc = scenario::load_scenario(o.scenario, overrides);
  UnitOptions u;
  u.host = o.host;
  u.bin_dir = o.bin.empty() ? bin_dir() : o.bin;
  u.config_dir = o.config_dir.empty() ? "/etc/plexus/" + unit_word(sc.name) : o.config_dir;
  for (const auto& [opt, path] : {std::pair{"--bin", u.bin_dir}, std::pair{"--config-dir", u.config_dir}})
    if (!std::filesystem::path(path).is_absolute() || path.find_first_of("\n\r") != std::string::npos)
      throw InputError(std::string(opt) + " " + path + ": must be an absolute path (systemd runs the units from /)");
  if (!o.dds.empty()) rt::parse_vendor(o.dds, "--dds");
  u.dds = o.dds;
  for (const auto& v : o.vendors) {
    const auto eq = v.find('=');
    if (eq == std::string::npos) throw InputError("--vendor " + v + ": expected PROCESS=fast|cyclone");
    rt::parse_vendor(v.substr(eq + 1), "--vendor " + v);
    u.vendor_of[v.substr(0, eq)] = v.substr(eq + 1);
  }
  u.domain = o.domain;
  const std::string qos_file = o.qos_file.empty() ? rt::default_qos_file() : o.qos_file;
  rt::QosProfiles::load(qos_file);  // a bad QoS file: exit 2 now, not on the robot
  const UnitSet set = make_units(sc, u);

  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(fs::path(o.out) / "config", ec);
  if (ec) throw InputError("--out " + o.out + ": cannot create the folder (" + ec.message() + ")");
  for (const auto& f : set.units) write_file(fs::path(o.out) / f.name, f.text);
  for (const auto& f : set.config) write_file(fs::path(o.out) / "config" / f.name, f.text);
  fs::copy_file(qos_file, fs::path(o.out) / "config" / "qos.yaml", fs::copy_options::overwrite_existing, ec);
  if (ec) throw InputError(qos_file + ": cannot copy to " + o.out + "/config (" + ec.message() + ")");
  std::printf(
      "%s: %zu units for %s (%zu processes); install: copy %s/config/* to %s and the units to "
      "/etc/systemd/system, then systemctl daemon-reload && systemctl enable --now %s (docs/deployment.md)\n",
      o.out.c_str(), set.units.size(), o.host.empty() ? sc.name.c_str() : ("host " + o.host).c_str(),
      set.units.size() - 1, o.out.c_str(), u.config_dir.c_str(), set.target.c_str());
  return 0;
}

}  // namespace

Command add_deploy_command(CLI::App& root) {
  auto o = std::make_shared<DeployOptions>();
  Command c;
  c.app = root.add_subcommand("deploy", "Deployment files for running a scenario without plexus launch");
  c.app->require_subcommand(1);
  auto* units = c.app->add_subcommand("units", "systemd units for one host's processes, and a target grouping them");
  units->add_option("scenario", o->scenario, "Scenario file (YAML)")->required();
  units->add_option("--host", o->host,
                    "The host whose processes the units start (required when the scenario has hosts)");
  units->add_option("-o,--out", o->out, "Folder to write the units and their config/ folder to")->required();
  units->add_option("--bin", o->bin, "Folder of the plexus executables on the robot (default: this plexus's own)");
  units->add_option("--config-dir", o->config_dir, "Folder of config/ on the robot (default /etc/plexus/<scenario>)");
  units->add_option("--set", o->sets, "Override a scenario value: dotted.key=value (repeatable)");
  units->add_option("--dds", o->dds,
                    "DDS vendor of every process without a `dds` key (default: dds.vendor, else fast)");
  units->add_option("--vendor", o->vendors, "Vendor of one process: PROCESS=fast|cyclone (repeatable)");
  units->add_option("--domain", o->domain, "DDS domain id (default: the scenario's)")->check(CLI::Range(0, 232));
  units->add_option("--qos-file", o->qos_file, "QoS profiles to install with the units (default deploy/qos.yaml)");
  c.run = [o] { return run_units(*o); };
  return c;
}

}  // namespace plexus::cli
