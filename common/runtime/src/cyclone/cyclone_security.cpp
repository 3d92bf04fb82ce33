#include "cyclone_security.hpp"

#include <string>

namespace plexus::rt::detail {

void apply_cyclone_security(dds_qos_t* qos, const SecurityOptions& s) {
  if (!s.enabled) return;
  const auto set = [qos](const char* name, const std::string& value) { dds_qset_prop(qos, name, value.c_str()); };
  // The plugin libraries are not on the default library path on Debian (libddsc0debian/):
  // CMake passes their full paths (common/runtime/CMakeLists.txt).
  set("dds.sec.auth.library.path", PLEXUS_CYCLONE_SECURITY_AUTH);
  set("dds.sec.auth.library.init", "init_authentication");
  set("dds.sec.auth.library.finalize", "finalize_authentication");
  set("dds.sec.auth.identity_ca", "file:" + s.identity_ca);
  set("dds.sec.auth.identity_certificate", "file:" + s.certificate);
  set("dds.sec.auth.private_key", "file:" + s.private_key);
  set("dds.sec.access.library.path", PLEXUS_CYCLONE_SECURITY_AC);
  set("dds.sec.access.library.init", "init_access_control");
  set("dds.sec.access.library.finalize", "finalize_access_control");
  set("dds.sec.access.permissions_ca", "file:" + s.permissions_ca);
  set("dds.sec.access.governance", "file:" + s.governance);
  set("dds.sec.access.permissions", "file:" + s.permissions);
  set("dds.sec.crypto.library.path", PLEXUS_CYCLONE_SECURITY_CRYPTO);
  set("dds.sec.crypto.library.init", "init_crypto");
  set("dds.sec.crypto.library.finalize", "finalize_crypto");
}

}  // namespace plexus::rt::detail
