#include "service_help.hpp"

#include <spdlog/spdlog.h>

#include <filesystem>
#include <set>

#include "plexus/base/input_error.hpp"
#include "plexus/runtime/qos.hpp"
#include "plexus/scenario/registry.hpp"
#include "plexus/service/standalone.hpp"

namespace plexus::scenario {
namespace fs = std::filesystem;
namespace {

// deploy/params beside the QoS profiles the executable finds (build tree or install prefix).
fs::path params_dir() { return fs::path(rt::default_qos_file()).parent_path() / "params"; }

std::string summary_of(const std::string& type) {
  const ComponentType* t = find_component_type(type);
  return t ? std::string(to_string(t->kind)) + ": " + t->summary : "";
}

// "    in  r1/position  PositionMeasurement" for every port of every component built.
// Inputs produced in the same process (a sensor reading its plant) are not topics it reads.
std::string ports_of(const Scenario& sc) {
  std::set<std::string> local;
  for (const auto& c : sc.components)
    for (const auto& o : c.component->outputs()) local.insert(o->signal());
  std::string out;
  for (const auto& c : sc.components) {
    for (const auto& in : c.component->inputs())
      if (!local.count(in->signal()))
        out +=
            "      in   " + in->signal() + "  " + (in->message().empty() ? "(in process only)" : in->message()) + "\n";
    for (const auto& o : c.component->outputs())
      out += "      out  " + o->signal() + "  " + (o->message().empty() ? "(in process only)" : o->message()) + "\n";
  }
  return out;
}

std::string describe(StandaloneSpec spec, const std::string& heading) {
  std::string out = "  " + heading + "\n";
  try {
    out += ports_of(load_standalone(spec, {}, true));
  } catch (const InputError& e) {
    out += "      (its topics depend on its parameters: " + std::string(e.what()) + ")\n";
  }
  return out;
}

}  // namespace

std::string hosted_help(const ServiceDeclaration& service) {
  const std::string& program = service.name;
  const auto& types = service.component_types;
  const auto level = spdlog::default_logger()->level();
  spdlog::set_level(spdlog::level::off);  // building the examples must not print
  std::string out;
  std::error_code ec;
  if (service.role == ServiceRole::plant) {
    out += "Runs a robot's plant and sensors (--params ROBOT.yaml). Example robots (deploy/params), robot r1:\n";
    for (const auto& entry : fs::directory_iterator(params_dir(), ec)) {
      const std::string file = entry.path().filename().string();
      if (file.size() < 11 || file.compare(file.size() - 11, 11, "_robot.yaml") != 0) continue;
      StandaloneSpec spec;
      spec.program = program;
      spec.robot_section = true;
      spec.params_file = entry.path().string();
      out += describe(spec, file);
    }
  } else if (service.role == ServiceRole::host) {
    out += "Hosts any component type (plexus sim --list names them); its topics are those of the type.\n";
  } else {
    out += "Hosts (--type; default " + types.front() +
           "), with the topics of its example parameters "
           "(deploy/params/<type>.yaml) for robot r1:\n";
    for (const auto& t : types) {
      StandaloneSpec spec;
      spec.program = program;
      spec.name = t;
      spec.type = t;
      if (const fs::path p = params_dir() / (t + ".yaml"); fs::exists(p, ec)) spec.params_file = p.string();
      out += describe(spec, t + "  (" + summary_of(t) + ")");
    }
  }
  out +=
      "Topics are <robot>/<port> (--robot); types are the IDL messages of idl/; QoS, ranges and units: docs/topics.md.";
  spdlog::set_level(level);
  return out;
}

}  // namespace plexus::scenario
