#include "launch_security.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "plexus/base/input_error.hpp"

namespace plexus::cli {
namespace {

struct Participant {
  std::string process;  // process name, or plexus_launch
  std::string vendor;
  const rt::SecurityOptions* security;
  uint64_t rank;
};

std::string describe(const Participant& p) {
  return std::string(p.vendor == "fast" ? "Fast DDS" : "Cyclone DDS") + " " +
         (p.process == kLauncherIdentity ? std::string("launcher") : "process '" + p.process + "'") + " (identity " +
         p.security->identity + ")";
}

}  // namespace

std::string default_identity(const std::string& process) {
  std::string id = process;
  for (char& c : id)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.')) c = '_';
  return id;
}

std::vector<std::string> LaunchSecurity::args(const std::string& process) const {
  if (!enabled) return {};
  std::vector<std::string> out{"--security", pki, "--identity", identity_of.at(process)};
  if (!governance.empty()) out.insert(out.end(), {"--governance", governance});
  return out;
}

nlohmann::ordered_json LaunchSecurity::to_json() const {
  nlohmann::ordered_json j;
  j["pki"] = pki;
  j["governance"] = launcher.governance;
  nlohmann::ordered_json ids = nlohmann::ordered_json::object();
  ids[kLauncherIdentity] = {{"identity", launcher.identity},
                            {"subject", rt::certificate_subject(launcher.certificate)}};
  for (const auto& [process, s] : processes)
    ids[process] = {{"identity", s.identity}, {"subject", rt::certificate_subject(s.certificate)}};
  j["identities"] = ids;
  return j;
}

LaunchSecurity plan_security(const scenario::Scenario& sc, const std::vector<Process>& all,
                             const std::string& launcher_vendor) {
  LaunchSecurity out;
  const auto& sec = sc.security;
  if (!sec.enabled) return out;
  out.enabled = true;
  out.pki = sec.pki;
  out.governance = sec.governance;
  std::string names = kLauncherIdentity;
  for (const auto& p : all) names += ", " + p.name;
  for (const auto& [process, where] : sec.identity_where)
    if (process != kLauncherIdentity &&
        std::none_of(all.begin(), all.end(), [&](const Process& p) { return p.name == process; }))
      throw InputError(where + ": no process '" + process + "' in this scenario (processes: " + names + ")");
  std::error_code ec;
  if (!std::filesystem::is_directory(sec.pki, ec))
    throw InputError(sec.where + ".pki: " + sec.pki + ": no such folder");
  if (!sec.governance.empty() && !std::filesystem::is_regular_file(sec.governance, ec))
    throw InputError(sec.where + ".governance: " + sec.governance + ": no such file");
  auto resolve = [&](const std::string& process) {
    const auto named = sec.identities.find(process);
    const std::string id = named != sec.identities.end() ? named->second : default_identity(process);
    const std::string origin = named != sec.identities.end() ? sec.identity_where.at(process) : sec.where + ".pki";
    rt::SecurityOptions s = rt::security_from_pki(sec.pki, id, sec.governance);
    try {
      rt::check_security_files(s, origin);
    } catch (const InputError& e) {
      if (named == sec.identities.end() &&
          !std::filesystem::is_directory(std::filesystem::path(sec.pki) / "identities" / id, ec))
        throw InputError(std::string(e.what()) + " (process '" + process + "' uses identity '" + id +
                         "' unless security.identities names another; tools/security/make_test_pki.sh PKI " + id +
                         " creates it)");
      throw;
    }
    out.identity_of[process] = id;
    return s;
  };
  out.launcher = resolve(kLauncherIdentity);
  for (const auto& p : all) out.processes[p.name] = resolve(p.name);

  std::vector<Participant> fast, cyclone;
  auto add = [&](const std::string& process, const std::string& vendor, const rt::SecurityOptions& s) {
    (vendor == "cyclone" ? cyclone : fast).push_back({process, vendor, &s, rt::handshake_rank(s.certificate)});
  };
  add(kLauncherIdentity, launcher_vendor, out.launcher);
  for (const auto& p : all) add(p.name, p.vendor, out.processes.at(p.name));
  for (const auto& f : fast)
    for (const auto& c : cyclone)
      if (f.rank <= c.rank)
        throw InputError(
            sec.where + ": " + describe(f) + " and " + describe(c) + " cannot authenticate: " +
            (f.rank < c.rank ? "the Fast DDS side's certificate subject ranks first (DDS Security 1.1, 9.3.3), "
                               "so it starts the handshake"
                             : "their certificate subjects rank equal, so the Fast DDS side may start the handshake") +
            ", and Fast DDS 2.9 sends a DH+MODP-2048-256 public key that Cyclone DDS 0.10 cannot decode (it "
            "expects ASN.1; cyclonedds#1547, Fast-DDS#3802); give every Cyclone DDS participant an identity "
            "that ranks first (make_test_pki.sh PKI NAME:cyclone, docs/security.md) or run both on one vendor");
  return out;
}

}  // namespace plexus::cli
