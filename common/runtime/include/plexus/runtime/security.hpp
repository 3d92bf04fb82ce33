// DDS Security for a participant (OMG DDS Security 1.1, builtin plugins): authentication
// (PKI-DH), access control (permissions) and cryptography (AES-GCM-GMAC), on either vendor.
// The material is a set of files: two CA certificates, this participant's identity
// certificate and key, and two documents signed (S/MIME) by the permissions CA. A PKI folder
// laid out as tools/security/make_test_pki.sh writes it gives them all (docs/security.md):
//
//   PKI/identity_ca.pem  PKI/permissions_ca.pem  PKI/governance.p7s
//   PKI/identities/NAME/cert.pem  PKI/identities/NAME/key.pem  PKI/identities/NAME/permissions.p7s
#pragma once

#include <cstdint>
#include <string>

namespace plexus::rt {

struct SecurityOptions {
  bool enabled = false;
  std::string identity;        ///< name of the identity, for messages ("observer")
  std::string identity_ca;     ///< PEM certificate of the identity CA
  std::string certificate;     ///< this participant's identity certificate (PEM), signed by identity_ca
  std::string private_key;     ///< its private key (PEM, not encrypted)
  std::string permissions_ca;  ///< PEM certificate of the permissions CA
  std::string governance;      ///< governance document (domain rules, protections), signed by permissions_ca
  std::string permissions;     ///< this identity's permissions document, signed by permissions_ca
};

/// The files of identity `name` in the PKI folder `pki_dir` (layout above), as absolute paths.
/// `name` may also be a folder (it contains a '/') holding cert.pem, key.pem and permissions.p7s.
/// `governance` (optional) replaces PKI/governance.p7s; a relative path is taken in `pki_dir`.
/// Nothing is read here: check_security_files() does that.
SecurityOptions security_from_pki(const std::string& pki_dir, const std::string& name,
                                  const std::string& governance = "");

/// Reads and checks every file of `s` before a vendor sees it: each exists and parses (PEM
/// certificates and key, S/MIME documents); the identity certificate is signed by the identity
/// CA and valid now, and the key is its key; governance and permissions are signed by the
/// permissions CA. Throws InputError "<origin>: identity 'NAME': <file>: <what is wrong>".
void check_security_files(const SecurityOptions& s, const std::string& origin);

/// The order in which two participants authenticate: a participant's GUID prefix starts with 1
/// bit set and the first 47 bits of SHA-256 of its certificate's subject name (DER) (DDS
/// Security 1.1, 9.3.3), and of two participants the one with the lower GUID sends the
/// handshake request (Fast DDS 2.9 and Cyclone DDS 0.10 alike). Returns those 47 bits; equal ranks (same subject) order
/// at random. Throws InputError if the certificate cannot be read.
uint64_t handshake_rank(const std::string& certificate_file);

/// The subject name of a certificate (RFC 2253), for messages. Throws InputError.
std::string certificate_subject(const std::string& certificate_file);

}  // namespace plexus::rt
