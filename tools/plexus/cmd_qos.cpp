// plexus qos: list and check QoS profile files.
#include <cstdio>

#include "command.hpp"
#include "plexus/runtime/qos.hpp"

namespace plexus::cli {

Command add_qos_command(CLI::App& root) {
  auto file = std::make_shared<std::string>();
  auto profile = std::make_shared<std::string>();
  Command c;
  c.app = root.add_subcommand("qos", "Validate a QoS profile file and print its profiles");
  c.app->add_option("--qos-file", *file, "QoS profiles file (default: deploy/qos.yaml)");
  c.app->add_option("profile", *profile, "print only this profile");
  c.run = [file, profile] {
    const auto profiles = rt::QosProfiles::load(file->empty() ? rt::default_qos_file() : *file);
    if (!profile->empty()) {
      std::printf("%s\n", rt::describe(profiles.get(*profile)).c_str());
      return 0;
    }
    std::printf("%s: %zu profiles\n", profiles.origin().c_str(), profiles.all().size());
    for (const auto& [name, p] : profiles.all()) std::printf("  %s\n", rt::describe(p).c_str());
    return 0;
  };
  return c;
}

}  // namespace plexus::cli
