// libFuzzer target: `--set key=value` overrides (common/scenario/src/overrides.cpp) applied
// to a valid scenario, then validated, as `plexus sim SCENARIO --set ...` does.
//
// Input layout (the seeds in tests/fuzz/corpus/scenario_overrides/ follow it):
//   byte 0      the scenario: index (modulo their number) into deploy/scenarios/*.yaml, sorted
//   the rest    one `--set` argument per line (path=value, as typed after --set)
//
// Checked: parse_override and the loader accept the arguments or refuse them with one
// InputError line that names the file or the --set argument; no other exception, crash,
// leak, hang or undefined behaviour.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <string>
#include <typeinfo>
#include <vector>

#include "plexus/base/input_error.hpp"
#include "plexus/base/yaml_reader.hpp"
#include "plexus/scenario/overrides.hpp"
#include "plexus/scenario/scenario.hpp"
#include "scenario_fuzz_support.hpp"

namespace {

using plexus::fuzz::finding;

/// The scenarios of deploy/scenarios, parsed once, with their recorders' outputs contained.
const std::vector<YAML::Node>& bases() {
  static const std::vector<YAML::Node> all = [] {
    std::vector<std::string> files;
    for (const auto& e : std::filesystem::directory_iterator(std::string(PLEXUS_SOURCE_DIR) + "/deploy/scenarios"))
      if (e.path().extension() == ".yaml") files.push_back(e.path().string());
    std::sort(files.begin(), files.end());
    std::vector<YAML::Node> out;
    for (const auto& f : files) {
      YAML::Node n = plexus::load_yaml_file(f);
      plexus::fuzz::contain_outputs(n);
      out.push_back(n);
    }
    if (out.empty()) finding("no scenario in deploy/scenarios");
    return out;
  }();
  return all;
}

/// True if the override could point a recorder's `output` outside the scratch folder: its
/// path ends in `output`, or its value is a mapping or list with an `output` key in it.
bool may_write_a_file(const plexus::scenario::Override& o) {
  const std::size_t dot = o.path.rfind('.');
  if (o.path.substr(dot == std::string::npos ? 0 : dot + 1) == "output") return true;
  try {
    const YAML::Node v = plexus::load_yaml_string(o.value, "value");
    bool found = false;
    const auto walk = [&](const auto& self, const YAML::Node& n, int depth) -> void {
      if (found || depth > 1000) {
        found = true;
        return;
      }
      if (n.IsMap()) {
        for (const auto& kv : n) {
          found = found || (kv.first.IsScalar() && kv.first.Scalar() == "output");
          self(self, kv.second, depth + 1);
        }
      } else if (n.IsSequence()) {
        for (const auto& e : n) self(self, e, depth + 1);
      }
    };
    walk(walk, v, 0);
    return found;
  } catch (const plexus::InputError&) {
    return false;  // the loader refuses it before any component is built
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string& origin = plexus::fuzz::scenario_origin();
  const YAML::Node& base = bases()[data[0] % bases().size()];
  const std::string text(reinterpret_cast<const char*>(data + 1), size - 1);

  std::vector<plexus::scenario::Override> overrides;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::string argument = text.substr(start, end - start);
    start = end + 1;
    if (argument.empty()) continue;
    try {
      overrides.push_back(plexus::scenario::parse_override(argument));
    } catch (const plexus::InputError& e) {
      plexus::fuzz::check_one_line(e.what());
      return 0;
    } catch (const std::exception& e) {
      finding(std::string("an exception other than InputError escaped parse_override: ") + typeid(e).name() + ": " +
              e.what());
    }
    if (may_write_a_file(overrides.back())) return 0;
  }

  try {
    const auto sc = plexus::scenario::load_scenario_tree(YAML::Clone(base), origin, overrides);
    CHECK(sc.step >= 1e-6 && sc.steps >= 1);
  } catch (const plexus::InputError& e) {
    plexus::fuzz::check_one_line(e.what());
    const std::string what = e.what();
    if (what.find(origin) == std::string::npos && what.find("--set ") == std::string::npos)
      finding("the refusal names neither the file nor the --set argument: " + what);
  } catch (const std::exception& e) {
    finding(std::string("an exception other than InputError escaped the loader: ") + typeid(e).name() + ": " +
            e.what());
  }
  return 0;
}
