// The security material of a participant, read and checked with OpenSSL before a vendor sees
// it, so that a wrong file is one line naming it instead of a participant that cannot be
// created (or worse, one that runs and discovers nobody).
#include <openssl/bio.h>
#include <openssl/evp.h>
#include <openssl/pem.h>
#include <openssl/pkcs7.h>
#include <openssl/x509.h>

#include <filesystem>
#include <memory>

#include "plexus/base/input_error.hpp"
#include "plexus/runtime/security.hpp"

namespace plexus::rt {
namespace {

namespace fs = std::filesystem;

struct Free {
  void operator()(BIO* p) const { BIO_free(p); }
  void operator()(X509* p) const { X509_free(p); }
  void operator()(EVP_PKEY* p) const { EVP_PKEY_free(p); }
  void operator()(PKCS7* p) const { PKCS7_free(p); }
  void operator()(X509_STORE* p) const { X509_STORE_free(p); }
};
template <class T>
using Owned = std::unique_ptr<T, Free>;

std::string absolute_path(const fs::path& p) { return fs::absolute(p).lexically_normal().string(); }

Owned<BIO> open_file(const std::string& file, const std::string& where) {
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) throw InputError(where + file + ": no such file");
  Owned<BIO> bio(BIO_new_file(file.c_str(), "r"));
  if (!bio) throw InputError(where + file + ": cannot read the file");
  return bio;
}

Owned<X509> read_certificate(const std::string& file, const std::string& where) {
  auto bio = open_file(file, where);
  Owned<X509> cert(PEM_read_bio_X509(bio.get(), nullptr, nullptr, nullptr));
  if (!cert) throw InputError(where + file + ": not a PEM certificate");
  return cert;
}

// The signed document's content, checked against the CA as both vendors check it
// (PKCS7_verify with the CA as the only trusted certificate, S/MIME text).
void check_signed(const std::string& file, X509* ca, const std::string& ca_file, const std::string& where) {
  auto bio = open_file(file, where);
  BIO* content = nullptr;
  Owned<PKCS7> p7(SMIME_read_PKCS7(bio.get(), &content));
  Owned<BIO> content_owner(content);
  if (!p7) throw InputError(where + file + ": not an S/MIME signed document");
  Owned<X509_STORE> store(X509_STORE_new());
  X509_STORE_add_cert(store.get(), ca);
  Owned<BIO> out(BIO_new(BIO_s_mem()));
  if (PKCS7_verify(p7.get(), nullptr, store.get(), content, out.get(), PKCS7_TEXT) != 1)
    throw InputError(where + file + ": not signed by the permissions CA " + ca_file);
}

}  // namespace

SecurityOptions security_from_pki(const std::string& pki_dir, const std::string& name, const std::string& governance) {
  SecurityOptions s;
  s.enabled = true;
  const fs::path pki(pki_dir);
  const bool folder = name.find('/') != std::string::npos;
  const fs::path id = folder ? fs::path(name) : pki / "identities" / name;
  s.identity = folder ? id.filename().string() : name;
  s.identity_ca = absolute_path(pki / "identity_ca.pem");
  s.permissions_ca = absolute_path(pki / "permissions_ca.pem");
  s.governance =
      absolute_path(governance.empty() ? pki / "governance.p7s" : pki / governance);  // an absolute one stays
  s.certificate = absolute_path(id / "cert.pem");
  s.private_key = absolute_path(id / "key.pem");
  s.permissions = absolute_path(id / "permissions.p7s");
  return s;
}

void check_security_files(const SecurityOptions& s, const std::string& origin) {
  const std::string where = origin + ": identity '" + s.identity + "': ";
  auto ca = read_certificate(s.identity_ca, where);
  auto cert = read_certificate(s.certificate, where);
  if (X509_verify(cert.get(), X509_get0_pubkey(ca.get())) != 1)
    throw InputError(where + s.certificate + ": not signed by the identity CA " + s.identity_ca);
  if (X509_cmp_current_time(X509_get0_notBefore(cert.get())) > 0)
    throw InputError(where + s.certificate + ": not valid yet");
  if (X509_cmp_current_time(X509_get0_notAfter(cert.get())) < 0) throw InputError(where + s.certificate + ": expired");
  {
    auto bio = open_file(s.private_key, where);
    Owned<EVP_PKEY> key(PEM_read_bio_PrivateKey(bio.get(), nullptr, nullptr, nullptr));
    if (!key) throw InputError(where + s.private_key + ": not a PEM private key (an encrypted key is not supported)");
    if (X509_check_private_key(cert.get(), key.get()) != 1)
      throw InputError(where + s.private_key + ": not the key of " + s.certificate);
  }
  auto pca = read_certificate(s.permissions_ca, where);
  check_signed(s.governance, pca.get(), s.permissions_ca, where);
  check_signed(s.permissions, pca.get(), s.permissions_ca, where);
}

uint64_t handshake_rank(const std::string& certificate_file) {
  auto cert = read_certificate(certificate_file, "");
  unsigned char md[EVP_MAX_MD_SIZE];
  unsigned int n = 0;
  if (X509_NAME_digest(X509_get_subject_name(cert.get()), EVP_sha256(), md, &n) != 1 || n < 6)
    throw InputError(certificate_file + ": cannot hash the subject name");
  uint64_t bits = 0;
  for (int i = 0; i < 6; ++i) bits = (bits << 8) | md[i];
  return bits >> 1;  // the first 47 bits, as they follow the leading 1 of the adjusted GUID prefix
}

std::string certificate_subject(const std::string& certificate_file) {
  auto cert = read_certificate(certificate_file, "");
  Owned<BIO> out(BIO_new(BIO_s_mem()));
  X509_NAME_print_ex(out.get(), X509_get_subject_name(cert.get()), 0, XN_FLAG_RFC2253);
  char* data = nullptr;
  const long len = BIO_get_mem_data(out.get(), &data);
  return std::string(data, static_cast<std::size_t>(len));
}

}  // namespace plexus::rt
