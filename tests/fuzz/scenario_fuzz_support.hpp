// What the two scenario targets share: a scratch layout in which the scenarios' relative
// paths resolve (scenarios/ beside training/, as in deploy/), and the containment of the
// one kind of parameter that writes a file when a scenario is loaded.
#pragma once

#include <yaml-cpp/yaml.h>

#include <spdlog/spdlog.h>

#include <filesystem>
#include <string>

#include "fuzz_support.hpp"

namespace plexus::fuzz {

/// The file name every fuzzed scenario is loaded as: <scratch>/scenarios/fuzz.yaml, with a
/// copy of deploy/training in <scratch>/training, so `../training/...` parameters resolve.
inline const std::string& scenario_origin() {
  static const std::string origin = [] {
    namespace fs = std::filesystem;
    const fs::path root = scratch_dir();
    fs::create_directories(root / "scenarios");
    fs::create_directories(root / "out");
    fs::copy(fs::path(PLEXUS_SOURCE_DIR) / "deploy" / "training", root / "training",
             fs::copy_options::recursive | fs::copy_options::overwrite_existing);
    spdlog::set_level(spdlog::level::off);  // the components' warnings of valid inputs
    return (root / "scenarios" / "fuzz.yaml").string();
  }();
  return origin;
}

/// Recorders (terrain_recorder, icr_library_recorder) open their `output` file when they are
/// built, that is when the scenario is loaded. So that a fuzzed path cannot name a file of
/// this machine, every scalar `output` is pointed into the scratch folder before loading.
/// (The walk follows aliases: the loader has refused cycles before this runs.)
inline void contain_outputs(YAML::Node node, int depth = 0) {
  if (depth > 1000) finding("a YAML tree deeper than 1000 levels reached the scenario loader");
  if (node.IsMap()) {
    for (auto kv : node) {
      if (kv.first.IsScalar() && kv.first.Scalar() == "output" && kv.second.IsScalar())
        kv.second = scratch_dir() + "/out/output.txt";
      else
        contain_outputs(kv.second, depth + 1);
    }
  } else if (node.IsSequence()) {
    for (auto e : node) contain_outputs(e, depth + 1);
  }
}

}  // namespace plexus::fuzz
