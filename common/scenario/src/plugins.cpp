#include "plexus/scenario/plugins.hpp"

#include <dlfcn.h>

#include <filesystem>

#include "plexus/base/input_error.hpp"

namespace plexus::scenario {
namespace {

std::vector<std::string>& loaded() {
  static std::vector<std::string> paths;
  return paths;
}

}  // namespace

void load_plugin(const std::string& path, const std::string& where) {
  std::error_code ec;
  const std::filesystem::path abs = std::filesystem::weakly_canonical(std::filesystem::absolute(path), ec);
  const std::string name = ec ? path : abs.string();
  for (const auto& p : loaded())
    if (p == name) return;
  if (!std::filesystem::exists(name, ec)) throw InputError(where + ": cannot load plugin '" + path + "': no such file");
  // RTLD_GLOBAL: a message package loaded as a plugin serves the component libraries loaded after it.
  if (!dlopen(name.c_str(), RTLD_NOW | RTLD_GLOBAL)) {
    const char* why = dlerror();
    throw InputError(where + ": cannot load plugin '" + path + "': " + (why ? why : "unknown error"));
  }
  loaded().push_back(name);
}

const std::vector<std::string>& loaded_plugins() { return loaded(); }

}  // namespace plexus::scenario
