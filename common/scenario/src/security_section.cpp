#include "security_section.hpp"

#include <cctype>
#include <filesystem>

namespace plexus::scenario {
namespace {

namespace fs = std::filesystem;

bool identity_name(const std::string& s) {
  if (s.empty() || s.size() > 64) return false;
  for (char c : s)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.')) return false;
  return s != "." && s != "..";
}

std::string absolute_in(const std::string& base, const std::string& path) {
  return fs::absolute(fs::path(base.empty() ? "." : base) / path).lexically_normal().string();
}

}  // namespace

ScenarioSecurity load_security_section(const YamlMap& top, const std::string& base_dir) {
  ScenarioSecurity s;
  const YamlMap sec = top.map("security");
  s.where = sec.where() + ": security";
  s.enabled = sec.required<bool>("enabled");
  if (s.enabled && !sec.has("pki"))
    sec.fail("enabled", "DDS Security needs `pki`, the PKI folder (tools/security/make_test_pki.sh writes one)");
  if (sec.has("pki")) {
    const auto pki = sec.required<std::string>("pki");
    if (pki.empty()) sec.fail("pki", "expected the PKI folder (tools/security/make_test_pki.sh writes one)");
    s.pki = absolute_in(base_dir, pki);
  }
  if (sec.has("governance")) {
    const auto g = sec.required<std::string>("governance");
    if (g.empty()) sec.fail("governance", "expected a governance document (.p7s), relative to the PKI folder");
    s.governance = fs::path(g).is_absolute() ? g : absolute_in(s.pki, g);
  }
  if (sec.has("identities")) {
    const YamlMap ids = sec.map("identities");
    for (const auto& process : ids.keys()) {
      const auto id = ids.required<std::string>(process);
      if (id.find('/') == std::string::npos && !identity_name(id))
        ids.fail(process,
                 "expected an identity name in the PKI folder's identities/ (letters, digits, '_', '-', '.') "
                 "or a folder path containing '/', got '" +
                     id + "'");
      s.identities[process] = id.find('/') == std::string::npos ? id : absolute_in(base_dir, id);
      s.identity_where[process] = ids.where(ids.node(process)) + ": " + ids.key_path(process);
    }
  }
  sec.reject_unknown();
  return s;
}

}  // namespace plexus::scenario
