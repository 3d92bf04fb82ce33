#include "plexus/msg/registry.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>

namespace plexus::msg {
namespace {

struct Entry {
  const WireType* wire;
  const char* package;
};

// Function-local statics: registrations run during static initialisation of other libraries.
std::vector<Entry>& entries() {
  static std::vector<Entry> e;
  return e;
}
std::vector<const TypeSupport*>& supports() {
  static std::vector<const TypeSupport*> s;
  return s;
}
std::vector<const WireType*>& wires() {
  static std::vector<const WireType*> w;
  return w;
}
std::mutex& registry_mutex() {
  static std::mutex m;
  return m;
}

std::string_view short_name(std::string_view scoped) {
  const auto p = scoped.rfind("::");
  return p == std::string_view::npos ? scoped : scoped.substr(p + 2);
}

template <class T>
T* at(void* message, const WireSlot& s) {
  return static_cast<T*>(s.member(message)) + s.index;
}

}  // namespace

double read_slot(const WireSlot& s, void* m) {
  using K = WireSlot::Kind;
  switch (s.kind) {
    case K::f64: return *at<double>(m, s);
    case K::f32: return static_cast<double>(*at<float>(m, s));
    case K::i8: return static_cast<double>(*at<int8_t>(m, s));
    case K::u8: return static_cast<double>(*at<uint8_t>(m, s));
    case K::i16: return static_cast<double>(*at<int16_t>(m, s));
    case K::u16: return static_cast<double>(*at<uint16_t>(m, s));
    case K::i32: return static_cast<double>(*at<int32_t>(m, s));
    case K::u32: return static_cast<double>(*at<uint32_t>(m, s));
    case K::i64: return static_cast<double>(*at<int64_t>(m, s));
    case K::u64: return static_cast<double>(*at<uint64_t>(m, s));
    case K::boolean: return *at<bool>(m, s) ? 1.0 : 0.0;
  }
  return 0.0;
}

void write_slot(const WireSlot& s, void* m, double v) {
  using K = WireSlot::Kind;
  switch (s.kind) {
    case K::f64: *at<double>(m, s) = v; break;
    case K::f32: *at<float>(m, s) = static_cast<float>(v); break;
    case K::i8: *at<int8_t>(m, s) = static_cast<int8_t>(v); break;
    case K::u8: *at<uint8_t>(m, s) = static_cast<uint8_t>(v); break;
    case K::i16: *at<int16_t>(m, s) = static_cast<int16_t>(v); break;
    case K::u16: *at<uint16_t>(m, s) = static_cast<uint16_t>(v); break;
    case K::i32: *at<int32_t>(m, s) = static_cast<int32_t>(v); break;
    case K::u32: *at<uint32_t>(m, s) = static_cast<uint32_t>(v); break;
    case K::i64: *at<int64_t>(m, s) = static_cast<int64_t>(v); break;
    case K::u64: *at<uint64_t>(m, s) = static_cast<uint64_t>(v); break;
    case K::boolean: *at<bool>(m, s) = v != 0.0; break;
  }
}

PackageRegistration::PackageRegistration(const char* package, std::initializer_list<const WireType*> types) {
  std::lock_guard<std::mutex> lock(registry_mutex());
  for (const WireType* t : types) {
    bool known = false;
    for (const auto& e : entries())
      if (std::strcmp(e.wire->support->type_name, t->support->type_name) == 0) {
        if (e.wire == t) {
          known = true;  // the same library seen twice
          break;
        }
        std::fprintf(stderr, "plexus: message type %s is defined by both %s and %s; a process may load only one\n",
                     t->support->type_name, e.package, package);
        std::abort();
      }
    if (known) continue;
    entries().push_back({t, package});
    supports().push_back(t->support);
    wires().push_back(t);
  }
}

const TypeSupport* find_type_support(std::string_view type_name) {
  for (const TypeSupport* ts : supports())
    if (type_name == ts->type_name) return ts;
  return nullptr;
}

const std::vector<const TypeSupport*>& all_type_supports() { return supports(); }

const WireType* find_wire_type(std::string_view name) {
  for (const WireType* t : wires())
    if (name == t->support->type_name) return t;
  if (name.find("::") != std::string_view::npos) return nullptr;
  const WireType* found = nullptr;
  for (const WireType* t : wires())
    if (short_name(t->support->type_name) == name) {
      if (found) return nullptr;  // two packages share the short name: only the scoped one is unambiguous
      found = t;
    }
  return found;
}

const std::vector<const WireType*>& all_wire_types() { return wires(); }

std::string package_of(std::string_view type_name) {
  for (const auto& e : entries())
    if (type_name == e.wire->support->type_name) return e.package;
  return "";
}

}  // namespace plexus::msg
