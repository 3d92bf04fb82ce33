// DDS Security under `plexus launch` (the scenario's `security:` section, docs/security.md):
// the identity of every participant of the run, its material checked before anything starts,
// the arguments that hand it to each process, and the mixed-vendor handshake check.
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "launch_plan.hpp"
#include "plexus/runtime/security.hpp"
#include "plexus/scenario/scenario.hpp"

namespace plexus::cli {

/// The launcher's own participant (the lockstep clock, the realtime monitor).
inline constexpr const char* kLauncherIdentity = "plexus_launch";

struct LaunchSecurity {
  bool enabled = false;
  std::string pki;                                       ///< the PKI folder (absolute)
  std::string governance;                                ///< absolute; empty: <pki>/governance.p7s
  rt::SecurityOptions launcher;                          ///< the launcher's participant
  std::map<std::string, rt::SecurityOptions> processes;  ///< by process name
  std::map<std::string, std::string> identity_of;        ///< process -> identity name or folder

  /// The arguments that give a process its security: --security PKI --identity ID
  /// [--governance FILE]; none when security is off.
  std::vector<std::string> args(const std::string& process) const;
  /// launch.json's record: PKI, governance, each participant's identity and subject.
  nlohmann::ordered_json to_json() const;
};

/// A process's identity when `security.identities` does not name one: its name, with every
/// character other than letters, digits, '_', '-' and '.' replaced by '_'
/// ("plant_simulator r1,r2" -> "plant_simulator_r1_r2").
std::string default_identity(const std::string& process);

/// The security of the launcher (on `launcher_vendor`) and of every process of `all` (their
/// vendors resolved), from the scenario's `security` section: every identity's files checked;
/// a key of `security.identities` that names no process refused. Mixed vendors: DDS Security
/// 1.1 lets the participant whose certificate subject sorts first start the handshake
/// (rt::handshake_rank), and a handshake that Fast DDS 2.9 starts with Cyclone DDS 0.10 fails
/// (its DH public key is raw bytes, Cyclone expects ASN.1), so every Fast DDS participant must
/// rank after every Cyclone DDS one; otherwise the deployment is refused here, naming the pair,
/// instead of running with participants that never authenticate. Throws InputError (exit 2).
LaunchSecurity plan_security(const scenario::Scenario& sc, const std::vector<Process>& all,
                             const std::string& launcher_vendor);

}  // namespace plexus::cli
