#include "cdr_sertype.hpp"

#include <dds/ddsi/ddsi_serdata.h>
#include <dds/ddsi/ddsi_sertype.h>
#include <dds/ddsi/q_radmin.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <vector>

namespace plexus::rt::detail {
namespace {

struct CdrSertype {
  struct ddsi_sertype c;  // first member: Cyclone casts between the two
  const msg::TypeSupport* type;
};

struct CdrSerdata {
  struct ddsi_serdata c;  // first member
  uint32_t size;          // bytes in data, including the 4-byte encapsulation header
  unsigned char data[];   // flexible array (GNU extension in C++, fine with g++/clang)
};

const CdrSertype* sertype_of(const struct ddsi_sertype* t) { return reinterpret_cast<const CdrSertype*>(t); }

CdrSerdata* alloc_serdata(const struct ddsi_sertype* type, enum ddsi_serdata_kind kind, std::size_t capacity) {
  void* mem = std::malloc(sizeof(CdrSerdata) + capacity);
  if (!mem) return nullptr;
  auto* d = static_cast<CdrSerdata*>(mem);
  ddsi_serdata_init(&d->c, type, kind);
  d->c.hash = type->serdata_basehash;  // keyless: every sample is the one instance
  d->size = 0;
  return d;
}

// --- serdata ops -----------------------------------------------------------

bool sd_eqkey(const struct ddsi_serdata*, const struct ddsi_serdata*) { return true; }  // keyless

uint32_t sd_get_size(const struct ddsi_serdata* d) { return reinterpret_cast<const CdrSerdata*>(d)->size; }

struct ddsi_serdata* sd_from_ser(const struct ddsi_sertype* type, enum ddsi_serdata_kind kind,
                                 const struct nn_rdata* fragchain, size_t size) {
  CdrSerdata* d = alloc_serdata(type, kind, size);
  if (!d) return nullptr;
  uint32_t off = 0;
  while (fragchain) {
    if (fragchain->maxp1 > off) {
      const unsigned char* payload =
          NN_RMSG_PAYLOADOFF(fragchain->rmsg, NN_RDATA_PAYLOAD_OFF(fragchain)) + (off - fragchain->min);
      const uint32_t n = fragchain->maxp1 - off;
      std::memcpy(d->data + off, payload, n);
      off = fragchain->maxp1;
    }
    fragchain = fragchain->nextfrag;
  }
  d->size = static_cast<uint32_t>(size);
  return &d->c;
}

struct ddsi_serdata* sd_from_ser_iov(const struct ddsi_sertype* type, enum ddsi_serdata_kind kind,
                                     ddsrt_msg_iovlen_t niov, const ddsrt_iovec_t* iov, size_t size) {
  CdrSerdata* d = alloc_serdata(type, kind, size);
  if (!d) return nullptr;
  std::size_t off = 0;
  for (ddsrt_msg_iovlen_t i = 0; i < niov && off < size; ++i) {
    const std::size_t n = std::min<std::size_t>(iov[i].iov_len, size - off);
    std::memcpy(d->data + off, iov[i].iov_base, n);
    off += n;
  }
  d->size = static_cast<uint32_t>(off);
  return &d->c;
}

struct ddsi_serdata* sd_from_keyhash(const struct ddsi_sertype* type, const struct ddsi_keyhash*) {
  return &alloc_serdata(type, SDK_KEY, 0)->c;  // keyless: the key is empty
}

struct ddsi_serdata* sd_from_sample(const struct ddsi_sertype* type, enum ddsi_serdata_kind kind, const void* sample) {
  const msg::TypeSupport& ts = *sertype_of(type)->type;
  if (kind != SDK_DATA) {
    CdrSerdata* d = alloc_serdata(type, kind, 0);
    return d ? &d->c : nullptr;
  }
  if (!ts.variable_size) {  // fixed size: the maximum is the size
    CdrSerdata* d = alloc_serdata(type, kind, ts.max_cdr_size);
    if (!d) return nullptr;
    const std::size_t n = ts.serialize(sample, d->data, ts.max_cdr_size);
    if (n == 0) {
      std::free(d);
      return nullptr;
    }
    d->size = static_cast<uint32_t>(n);
    return &d->c;
  }
  // Variable size (a sequence): a serdata of the type's maximum took a 64 KiB allocation per
  // LatencyProbe write, however small, held in the writer history until acknowledged. The
  // CDR goes first into this thread's scratch buffer of the maximum size (allocated on the
  // thread's first write), then into a serdata of exactly its size.
  thread_local std::vector<unsigned char> scratch;
  if (scratch.size() < ts.max_cdr_size) scratch.resize(ts.max_cdr_size);
  const std::size_t n = ts.serialize(sample, scratch.data(), ts.max_cdr_size);
  if (n == 0) return nullptr;
  CdrSerdata* d = alloc_serdata(type, kind, n);
  if (!d) return nullptr;
  std::memcpy(d->data, scratch.data(), n);
  d->size = static_cast<uint32_t>(n);
  return &d->c;
}

void sd_to_ser(const struct ddsi_serdata* d, size_t off, size_t sz, void* buf) {
  std::memcpy(buf, reinterpret_cast<const CdrSerdata*>(d)->data + off, sz);
}

struct ddsi_serdata* sd_to_ser_ref(const struct ddsi_serdata* d, size_t off, size_t sz, ddsrt_iovec_t* ref) {
  ref->iov_base = const_cast<unsigned char*>(reinterpret_cast<const CdrSerdata*>(d)->data) + off;
  ref->iov_len = static_cast<ddsrt_iov_len_t>(sz);
  return ddsi_serdata_ref(d);
}

void sd_to_ser_unref(struct ddsi_serdata* d, const ddsrt_iovec_t*) { ddsi_serdata_unref(d); }

bool sd_to_sample(const struct ddsi_serdata* d, void* sample, void**, void*) {
  const auto* sd = reinterpret_cast<const CdrSerdata*>(d);
  if (d->kind != SDK_DATA) return true;  // keyless: nothing to fill for a key
  return sertype_of(d->type)->type->deserialize(sd->data, sd->size, sample);
}

struct ddsi_serdata* sd_to_untyped(const struct ddsi_serdata* d) {
  CdrSerdata* u = alloc_serdata(d->type, SDK_KEY, 0);
  if (!u) return nullptr;
  u->c.type = nullptr;
  return &u->c;
}

bool sd_untyped_to_sample(const struct ddsi_sertype*, const struct ddsi_serdata*, void*, void**, void*) {
  return true;  // keyless
}

void sd_free(struct ddsi_serdata* d) { std::free(d); }

size_t sd_print(const struct ddsi_sertype* type, const struct ddsi_serdata* d, char* buf, size_t size) {
  return static_cast<size_t>(
      std::snprintf(buf, size, "%s (%u bytes CDR)", type->type_name, reinterpret_cast<const CdrSerdata*>(d)->size));
}

void sd_get_keyhash(const struct ddsi_serdata*, struct ddsi_keyhash* buf, bool) {
  std::memset(buf->value, 0, sizeof(buf->value));
}

const struct ddsi_serdata_ops kSerdataOps = {
    .eqkey = sd_eqkey,
    .get_size = sd_get_size,
    .from_ser = sd_from_ser,
    .from_ser_iov = sd_from_ser_iov,
    .from_keyhash = sd_from_keyhash,
    .from_sample = sd_from_sample,
    .to_ser = sd_to_ser,
    .to_ser_ref = sd_to_ser_ref,
    .to_ser_unref = sd_to_ser_unref,
    .to_sample = sd_to_sample,
    .to_untyped = sd_to_untyped,
    .untyped_to_sample = sd_untyped_to_sample,
    .free = sd_free,
    .print = sd_print,
    .get_keyhash = sd_get_keyhash,
#ifdef DDS_HAS_SHM
    .get_sample_size = nullptr,  // no iceoryx shared memory
    .from_iox_buffer = nullptr,
#endif
};

// --- sertype ops -----------------------------------------------------------
// Samples are never loaned out by Cyclone (plexus uses writecdr/takecdr only), so the
// sample-memory ops only need to be safe, not useful.

void st_free(struct ddsi_sertype* t) {
  ddsi_sertype_fini(t);
  delete reinterpret_cast<CdrSertype*>(t);
}
void st_zero_samples(const struct ddsi_sertype*, void*, size_t) {}
void st_realloc_samples(void** ptrs, const struct ddsi_sertype*, void*, size_t, size_t count) {
  for (size_t i = 0; i < count; ++i) ptrs[i] = nullptr;
}
void st_free_samples(const struct ddsi_sertype*, void**, size_t, dds_free_op_t) {}
bool st_equal(const struct ddsi_sertype* a, const struct ddsi_sertype* b) {
  return sertype_of(a)->type == sertype_of(b)->type;
}
uint32_t st_hash(const struct ddsi_sertype* t) {
  uint32_t h = 2166136261u;  // FNV-1a of the type name
  for (const char* p = t->type_name; *p; ++p) h = (h ^ static_cast<unsigned char>(*p)) * 16777619u;
  return h;
}
size_t st_get_serialized_size(const struct ddsi_sertype* t, const void*) { return sertype_of(t)->type->max_cdr_size; }
bool st_serialize_into(const struct ddsi_sertype* t, const void* sample, void* dst, size_t sz) {
  return sertype_of(t)->type->serialize(sample, static_cast<unsigned char*>(dst), sz) != 0;
}

const struct ddsi_sertype_ops kSertypeOps = {
    .version = ddsi_sertype_v0,
    .arg = nullptr,
    .free = st_free,
    .zero_samples = st_zero_samples,
    .realloc_samples = st_realloc_samples,
    .free_samples = st_free_samples,
    .equal = st_equal,
    .hash = st_hash,
    .type_id = nullptr,  // no type information: interop rule (docs/architecture.md)
    .type_map = nullptr,
    .type_info = nullptr,
    .derive_sertype = nullptr,  // XCDR1 only
    .get_serialized_size = st_get_serialized_size,
    .serialize_into = st_serialize_into,
};

}  // namespace

struct ddsi_sertype* make_cdr_sertype(const msg::TypeSupport& type, const std::string& wire_name) {
  auto* st = new CdrSertype{};
  st->type = &type;
  ddsi_sertype_init(&st->c, wire_name.c_str(), &kSertypeOps, &kSerdataOps, /*topickind_no_key=*/true);
  st->c.allowed_data_representation = DDS_DATA_REPRESENTATION_FLAG_XCDR1;
  return &st->c;
}

struct ddsi_serdata* serdata_from_sample(const struct ddsi_sertype* type, const void* sample) {
  return sd_from_sample(type, SDK_DATA, sample);
}

bool serdata_to_sample(const struct ddsi_serdata* d, void* sample) { return sd_to_sample(d, sample, nullptr, nullptr); }

}  // namespace plexus::rt::detail
