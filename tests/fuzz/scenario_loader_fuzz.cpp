// libFuzzer target: the scenario loader (common/scenario, docs/scenarios.md). The input is
// the text of a scenario file. It goes through the loader `plexus sim` and `plexus launch`
// use (YAML parsing, duplicate keys, validation of every section, the components' own
// parameter checks), as a whole scenario and as a part of one (a service's own document).
//
// Checked: the loader returns a scenario or refuses the input with an InputError of one
// line that names the file; no other exception escapes, and no crash, leak, hang or
// undefined behaviour (ASan, UBSan). A scenario it accepts has a whole
// number of steps, a step of at least 1 us, and components in stage order.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>
#include <typeinfo>

#include "plexus/base/input_error.hpp"
#include "plexus/base/yaml_reader.hpp"
#include "plexus/scenario/scenario.hpp"
#include "scenario_fuzz_support.hpp"

namespace {

using plexus::fuzz::finding;

void check_accepted(const plexus::scenario::Scenario& sc) {
  CHECK(sc.step >= 1e-6);  // distributed runs hold it in whole nanoseconds (docs/scenarios.md)
  CHECK(sc.steps >= 1);
  for (std::size_t i = 1; i < sc.components.size(); ++i)
    CHECK(static_cast<int>(sc.components[i - 1].kind) <= static_cast<int>(sc.components[i].kind));
  for (const auto& c : sc.components) CHECK(c.component != nullptr && c.period_steps >= 1);
}

void load(const YAML::Node& root, bool partial) {
  const std::string& origin = plexus::fuzz::scenario_origin();
  try {
    check_accepted(plexus::scenario::load_scenario_tree(YAML::Clone(root), origin, {}, {.partial = partial}));
  } catch (const plexus::InputError& e) {
    plexus::fuzz::check_one_line(e.what());
    if (std::string(e.what()).find(origin) == std::string::npos)
      finding(std::string("the refusal does not name the file: ") + e.what());
  } catch (const std::exception& e) {
    finding(std::string("an exception other than InputError escaped the loader: ") + typeid(e).name() + ": " +
            e.what());
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::string& origin = plexus::fuzz::scenario_origin();
  // The loader's first step (load_scenario_text = load_yaml_string + load_scenario_tree),
  // split so that recorders' output files can be contained in between.
  YAML::Node root;
  try {
    root = plexus::load_yaml_string(text, origin);
  } catch (const plexus::InputError& e) {
    plexus::fuzz::check_one_line(e.what());
    return 0;
  } catch (const std::exception& e) {
    finding(std::string("an exception other than InputError escaped the YAML reader: ") + typeid(e).name() + ": " +
            e.what());
  }
  plexus::fuzz::contain_outputs(root);
  load(root, false);
  load(root, true);
  return 0;
}
