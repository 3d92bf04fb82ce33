#include "launch_plan.hpp"

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>

#include "plexus/base/input_error.hpp"
#include "plexus/scenario/registry.hpp"
#include "plexus/scenario/step_executor.hpp"

namespace plexus::cli {
namespace {

/// The robot a plant or sensor belongs to.
std::string robot_of(const scenario::ScenarioComponent& c) {
  return c.component->name().substr(0, c.component->name().find('/'));
}

/// The plant-side program of each robot: the plant service that hosts its plant and sensors.
std::map<std::string, std::string> plant_programs(const scenario::Scenario& sc) {
  std::map<std::string, std::string> plant_type;
  std::map<std::string, std::vector<std::string>> sensor_types;
  for (const auto& c : sc.components) {
    if (c.kind == scenario::ComponentKind::plant) plant_type[robot_of(c)] = c.type;
    if (c.kind == scenario::ComponentKind::sensor) sensor_types[robot_of(c)].push_back(c.type);
  }
  std::map<std::string, std::string> out;
  for (const auto& [robot, type] : plant_type) out[robot] = scenario::plant_executable_for(type, sensor_types[robot]);
  return out;
}

bool physical(const scenario::ScenarioComponent& c) {
  return c.kind == scenario::ComponentKind::plant || c.kind == scenario::ComponentKind::sensor;
}

/// Services that share a `process` key must agree on where and how that process runs, and
/// the process name must not be taken by another service or a plant-side process.
void check_process_groups(const scenario::Scenario& sc) {
  std::set<std::string> plant_side;
  for (const auto& [robot, program] : plant_programs(sc)) plant_side.insert(program);
  std::map<std::string, const scenario::ScenarioComponent*> first_of;
  for (const auto& c : sc.components) {
    if (c.process.empty() || c.kind == scenario::ComponentKind::sensor) continue;
    const std::string key = c.where + ".process";
    for (const auto& program : plant_side)
      if (c.process.rfind(program, 0) == 0)
        throw InputError(key + ": '" + c.process + "' is the name of a plant-side process (" + program + ")");
    for (const auto& other : sc.components)
      if (other.component->name() == c.process && other.process != c.process &&
          other.kind != scenario::ComponentKind::plant && other.kind != scenario::ComponentKind::sensor)
        throw InputError(key + ": '" + c.process + "' is the name of service " + other.where +
                         ", which runs in a process of its own");
    auto [it, first] = first_of.emplace(c.process, &c);
    if (first) continue;
    const auto& f = *it->second;
    auto clash = [&](const char* what, const std::string& mine, const std::string& theirs) {
      if (mine != theirs)
        throw InputError(key + ": members of process '" + c.process + "' must agree on `" + what + "` ('" + mine +
                         "' here, '" + theirs + "' at " + f.where + ")");
    };
    clash("host", c.host, f.host);
    clash("dds", c.dds, f.dds);
    // A robot in a loop group takes the restart policy and scheduling of the group's services.
    if (physical(c) || physical(f)) continue;
    clash("restart", c.restart, f.restart);
    clash("restart_delay", std::to_string(c.restart_delay), std::to_string(f.restart_delay));
    clash("priority", std::to_string(c.priority), std::to_string(f.priority));
    clash("cpu", std::to_string(c.cpu), std::to_string(f.cpu));
  }
}

/// The plants and sensors of `robots`, by index in Scenario::components.
std::vector<std::size_t> robots_components(const scenario::Scenario& sc, const std::vector<std::string>& robots) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < sc.components.size(); ++i)
    if (physical(sc.components[i]) && std::count(robots.begin(), robots.end(), robot_of(sc.components[i])))
      out.push_back(i);
  return out;
}

/// A service's process, or the `process` group it joins (services, and the robots of a loop
/// group): `member` (a service or robot name) with its components, in `program` if the group's
/// members share one, else in the host service, which runs any type.
void join_group(std::vector<Process>& procs, const scenario::ScenarioComponent& c, const std::string& member,
                const std::vector<std::size_t>& components, const std::string& program) {
  const std::string name = c.process.empty() ? c.component->name() : c.process;
  auto group = std::find_if(procs.begin(), procs.end(), [&](const Process& p) { return p.name == name; });
  if (group == procs.end()) {
    Process p;
    p.name = name;
    p.program = program;
    p.select = {"--components", member};
    p.components = components;
    p.vendor = c.dds;
    procs.push_back(p);
    group = std::prev(procs.end());
  } else {
    group->select.back() += "," + member;
    group->components.insert(group->components.end(), components.begin(), components.end());
    if (group->program != program) group->program = scenario::host_service()->name;  // any type
  }
  if (physical(c)) {
    group->has_plant = true;
    group->restart = "never";  // plants hold the physical state: never restarted
  } else {
    if (!group->has_plant) {
      group->restart = c.restart;
      group->restart_delay_ns = static_cast<int64_t>(c.restart_delay * 1e9);
    }
    group->priority = c.priority;  // the members of a group agree (check_process_groups)
    group->cpu = c.cpu;
  }
}

}  // namespace

std::vector<Process> plan(const scenario::Scenario& sc, const std::string& host) {
  check_process_groups(sc);
  const std::string first = sc.hosts.empty() ? "" : sc.hosts.front();
  auto here = [&](const std::string& h) { return host.empty() || (h.empty() ? first : h) == host; };
  std::vector<Process> procs;
  const auto plant_program = plant_programs(sc);
  using HostProgram = std::pair<std::string, std::string>;
  std::map<HostProgram, std::string> robots_by_host;                      // (host, program) -> "r1,r2"
  std::map<HostProgram, std::vector<std::string>> robot_names_by_host;    // (host, program) -> {r1, r2}
  std::map<HostProgram, const scenario::ScenarioComponent*> first_plant;  // (host, program) -> its first robot's plant
  std::vector<Process> sources;                                           // robots fed by a bridge or a replay
  for (const auto& c : sc.components) {
    if (!here(c.host)) continue;
    const std::size_t index = static_cast<std::size_t>(&c - sc.components.data());
    if (c.kind == scenario::ComponentKind::plant && !c.process.empty()) {
      // A robot in a loop group (`loops:`): its plant and sensors in the group's process.
      join_group(procs, c, robot_of(c), robots_components(sc, {robot_of(c)}), plant_program.at(robot_of(c)));
    } else if (c.kind == scenario::ComponentKind::plant) {
      const std::string robot = robot_of(c);
      if (const auto src = sc.sources.find(robot); src != sc.sources.end()) {
        // A robot fed by a bridge or a replay: that program, for that robot, in place of the
        // plant simulator (docs/bridges.md).
        Process p;
        p.program = scenario::to_string(src->second.type);
        p.select = {"--robots", robot};
        p.components = robots_components(sc, {robot});
        p.name = p.service();
        p.vendor = c.dds;
        // A bridge's threads take the robot's `priority` and `cpu` (a replay has no loop).
        if (src->second.type != scenario::RobotSource::Type::replay) {
          p.priority = c.priority;
          p.cpu = c.cpu;
        }
        sources.push_back(p);
        continue;
      }
      const HostProgram key{c.host, plant_program.at(robot)};
      auto& list = robots_by_host[key];
      list += (list.empty() ? "" : ",") + robot;
      robot_names_by_host[key].push_back(robot);
      auto [it, first_robot] = first_plant.emplace(key, &c);
      auto agree = [&](const char* what, const std::string& mine, const std::string& theirs) {
        if (mine != theirs)
          throw InputError(c.where + ": the robots on one host share one " + key.second + " process, so their `" +
                           what + "` keys must agree ('" + mine + "' for " + robot + ", '" + theirs + "' for " +
                           list.substr(0, list.rfind(',')) + ")");
      };
      const auto& f = *it->second;
      agree("dds", c.dds, f.dds);
      agree("priority", std::to_string(c.priority), std::to_string(f.priority));
      agree("cpu", std::to_string(c.cpu), std::to_string(f.cpu));
    } else if (c.kind != scenario::ComponentKind::sensor) {
      join_group(procs, c, c.component->name(), {index}, scenario::executable_for(c.type));
    }
  }
  std::set<HostProgram> robot_hosts;  // over the whole scenario, so names agree on every host
  for (const auto& c : sc.components)
    if (c.kind == scenario::ComponentKind::plant && c.process.empty() && !sc.sources.count(robot_of(c)))
      robot_hosts.insert({c.host, plant_program.at(robot_of(c))});
  std::vector<Process> sims;
  for (const auto& [key, robots] : robots_by_host) {
    const std::string& program = key.second;
    Process p;  // plants hold the physical state: never restarted
    p.name = robot_hosts.size() == 1 ? program : program + " " + robots;
    p.program = program;
    p.select = {"--robots", robots};
    p.components = robots_components(sc, robot_names_by_host[key]);
    const auto& plant = *first_plant.at(key);
    p.vendor = plant.dds;
    p.priority = plant.priority;  // realtime: the robots' `priority` and `cpu`
    p.cpu = plant.cpu;
    sims.push_back(p);
  }
  procs.insert(procs.begin(), sources.begin(), sources.end());
  procs.insert(procs.begin(), sims.begin(), sims.end());
  return procs;
}

int participants_per_host(const scenario::Scenario& sc) {
  std::size_t busiest = 0;
  if (sc.hosts.empty()) busiest = plan(sc, "").size();
  for (const auto& h : sc.hosts) busiest = std::max(busiest, plan(sc, h).size());
  const int need = static_cast<int>(busiest) + kParticipantsBesideProcesses;
  if (need > kMaxParticipantsPerHost)
    throw InputError("dds.participants_per_host: a host of this scenario runs " + std::to_string(busiest) +
                     " processes, and a DDS domain holds at most " + std::to_string(kMaxParticipantsPerHost) +
                     " participants per host (with " + std::to_string(kParticipantsBesideProcesses) +
                     " for the launcher and tools): group services into fewer processes (`process`, "
                     "docs/scenarios.md) or spread them over hosts");
  return std::max(sc.dds_participants_per_host, need);
}

YAML::Node part_document(const scenario::Scenario& sc, const Process& p) {
  const YAML::Node& r = sc.resolved;
  YAML::Node part(YAML::NodeType::Map);
  for (const char* key : {"name", "description", "duration", "step", "seed", "clock", "plugins", "parameter_changes"})
    if (r[key]) part[key] = YAML::Clone(r[key]);
  // Relative file parameters (a training file) stay relative to the original scenario.
  part["base_dir"] = std::filesystem::absolute(sc.base_dir.empty() ? "." : sc.base_dir).lexically_normal().string();
  // What the process builds (Process::components): its robots' sections, or its services'.
  std::vector<bool> hosted(sc.components.size(), false);
  std::set<std::string> robots, services;
  for (std::size_t i : p.components) {
    hosted[i] = true;
    const auto& c = sc.components[i];
    if (physical(c))
      robots.insert(robot_of(c));
    else
      services.insert(c.component->name());
  }
  auto section = [](const YAML::Node& n) {
    YAML::Node out = YAML::Clone(n);
    out.remove("host");
    return out;
  };
  for (const auto& robot : robots) part["robots"][robot] = section(r["robots"][robot]);
  for (const auto& service : services) part["services"][service] = section(r["services"][service]);
  // The inputs other processes produce: their schedule, as the whole scenario has it.
  const scenario::StepExecutor wiring(const_cast<scenario::Scenario&>(sc), hosted);
  for (std::size_t s : wiring.remote_inputs()) {
    const auto& spec = wiring.signals()[s];
    const auto producer = std::find_if(sc.components.begin(), sc.components.end(),
                                       [&](const auto& c) { return c.component->name() == spec.producer; });
    YAML::Node in(YAML::NodeType::Map);
    in["period_steps"] = spec.period_steps;
    in["stage"] = scenario::to_string(producer->kind);
    if (!producer->qos.empty()) in["qos"] = producer->qos;
    in["producer"] = spec.producer;  // named in this process's messages (a lockstep timeout)
    part["inputs"][spec.name] = in;
  }
  return part;
}

std::vector<std::string> replay_args(const scenario::Scenario& sc, const Process& p) {
  const std::string& robot = p.select.back();
  std::string topics;
  for (const auto& s : sc.signals) {
    const auto producer = std::find_if(sc.components.begin(), sc.components.end(),
                                       [&](const auto& c) { return c.component->name() == s.producer; });
    if (producer != sc.components.end() && physical(*producer) && s.name.rfind(robot + "/", 0) == 0)
      topics += (topics.empty() ? "" : ",") + s.name;
  }
  return {"replay",    sc.sources.at(robot).recording,
          "--topics",  topics,
          "--restamp", "--service",
          p.service(), "--wait",
          "10",        "--linger",
          "0"};
}

nlohmann::ordered_json process_table(const std::vector<Process>& procs) {
  nlohmann::ordered_json t = nlohmann::ordered_json::object();
  for (const auto& p : procs) t[p.name] = {{"program", p.program}, {"vendor", p.vendor}};
  return t;
}

}  // namespace plexus::cli
