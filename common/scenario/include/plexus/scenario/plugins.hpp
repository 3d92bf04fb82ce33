// Plugins: shared libraries of component types, services and message types that a program
// loads at run time (docs/sdk.md, "Plugins"). A scenario names them (`plugins: [lib/libmylab_components.so]`,
// relative to the scenario's folder); `plexus launch` passes them on to every process it starts,
// and every plexus command takes `--plugin LIB`. Loading a library runs its registrations
// (ComponentRegistration, ServiceRegistration, a message package's types), so its types are
// then known as if they were built in.
#pragma once

#include <string>
#include <vector>

namespace plexus::scenario {

/// Loads the library at `path` (once per file); throws InputError "<where>: cannot load plugin
/// '<path>': <reason>" when it cannot be opened or a symbol it needs is missing.
void load_plugin(const std::string& path, const std::string& where);

/// The plugins loaded so far, as absolute paths, in load order.
const std::vector<std::string>& loaded_plugins();

}  // namespace plexus::scenario
