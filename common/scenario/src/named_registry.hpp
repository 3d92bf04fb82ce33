// A registry of named entries filled at static-initialisation time (internal).
#pragma once

#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

namespace plexus::scenario::detail {

/// Entries by `T::name`. Use through a function-local static so that registrations from
/// other translation units find it constructed.
template <class T>
class NamedRegistry {
 public:
  explicit NamedRegistry(const char* what) : what_(what) {}

  /// Adds an entry; a second entry with the same name aborts at start-up (a programming error).
  void add(T entry) {
    const std::string name = entry.name;
    if (!entries_.emplace(name, std::move(entry)).second) {
      std::fprintf(stderr, "plexus: %s '%s' registered twice\n", what_, name.c_str());
      std::abort();
    }
  }

  const T* find(const std::string& name) const {
    auto it = entries_.find(name);
    return it == entries_.end() ? nullptr : &it->second;
  }

  /// All entries, sorted by name.
  std::vector<const T*> all() const {
    std::vector<const T*> out;
    for (const auto& [name, entry] : entries_) out.push_back(&entry);
    return out;
  }

 private:
  const char* what_;
  std::map<std::string, T> entries_;
};

}  // namespace plexus::scenario::detail
