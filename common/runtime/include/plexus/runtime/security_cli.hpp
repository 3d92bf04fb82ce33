// The DDS Security options every plexus program takes (services, bridges, `plexus topic`,
// `record`, `replay`), so that a user learns them once (docs/security.md):
//   --security PKI_FOLDER   DDS Security on, with the material of this folder
//   --identity NAME|DIR     identity in PKI_FOLDER/identities (default: the program's own name)
//   --governance FILE       governance document (default PKI_FOLDER/governance.p7s)
// Header-only over CLI11 (link CLI11::CLI11).
#pragma once

#include <CLI/CLI.hpp>

#include <filesystem>
#include <string>

#include "plexus/base/input_error.hpp"
#include "plexus/runtime/security.hpp"

namespace plexus::rt {

inline void add_security_options(CLI::App& app, std::string& pki, std::string& identity, std::string& governance) {
  app.add_option("--security", pki,
                 "PKI folder: DDS Security on (authentication, access control, encryption; docs/security.md)");
  app.add_option("--identity", identity,
                 "With --security: identity NAME in PKI/identities, or its folder (default: this program's name)");
  app.add_option("--governance", governance, "With --security: governance document (default PKI/governance.p7s)");
}

/// The security of a participant from those options: off without --security (and then
/// --identity or --governance is an error), else the identity's files, checked
/// (check_security_files). Throws InputError naming the option and the file.
inline SecurityOptions security_from_options(const std::string& pki, const std::string& identity,
                                             const std::string& governance, const std::string& default_identity) {
  if (pki.empty()) {
    if (!identity.empty()) throw InputError("--identity " + identity + ": needs --security PKI_FOLDER");
    if (!governance.empty()) throw InputError("--governance " + governance + ": needs --security PKI_FOLDER");
    return {};
  }
  std::error_code ec;
  if (!std::filesystem::is_directory(pki, ec)) throw InputError("--security " + pki + ": no such folder");
  SecurityOptions s = security_from_pki(pki, identity.empty() ? default_identity : identity, governance);
  check_security_files(s, "--security " + pki);
  return s;
}

}  // namespace plexus::rt
