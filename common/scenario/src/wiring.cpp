#include "wiring.hpp"

#include <algorithm>
#include <map>

#include "plexus/base/input_error.hpp"
#include "plexus/msg/registry.hpp"
#include "plexus/scenario/member_of.hpp"

namespace plexus::scenario::detail {
namespace {

std::string join(const std::vector<std::string>& v) {
  std::string out;
  for (const auto& s : v) out += (out.empty() ? "" : ", ") + s;
  return out;
}

void check_width(const ScenarioComponent& c, const Port& p) {
  if (p.fields().empty() || p.fields().size() > kMaxSignalFields)
    throw InputError(c.where + ": port '" + p.port() + "' has " + std::to_string(p.fields().size()) +
                     " fields; a signal has 1 to " + std::to_string(kMaxSignalFields));
}

// The remap entry of a component's port, if the scenario remapped it (else empty).
std::string remap_of(const ScenarioComponent& c, const std::string& port) {
  const auto it = c.remap_where.find(port);
  return it == c.remap_where.end() ? std::string() : it->second;
}

// An input nobody produces: when a remap moved its producer away or pointed the reader
// elsewhere, the error names that remap entry, not the reader.
[[noreturn]] void no_producer(const std::vector<ScenarioComponent>& components, const ScenarioComponent& reader,
                              const Port& in) {
  for (const auto& c : components)
    for (const auto& out : c.component->outputs())
      if (const auto where = remap_of(c, out->port());
          !where.empty() && c.component->default_signal(out->port()) == in.signal())
        throw InputError(where + ": sends " + c.component->name() + "'s output '" + out->port() + "' to '" +
                         out->signal() + "', so nothing produces '" + in.signal() + "', read by " + reader.where +
                         " (port '" + in.port() + "')");
  if (const auto where = remap_of(reader, in.port()); !where.empty())
    throw InputError(where + ": reads port '" + in.port() + "' from '" + in.signal() +
                     "', which no component produces");
  throw InputError(reader.where + ": input '" + in.signal() + "' (port '" + in.port() +
                   "') is produced by no component; remap the port or add its producer");
}

// Two names of one message type: equal, or one the short form of the other ("Pose2D" and
// "plexus::msg::Pose2D").
bool same_message(const std::string& a, const std::string& b) {
  if (a == b) return true;
  auto short_of = [](const std::string& s) {
    const auto p = s.rfind("::");
    return p == std::string::npos ? s : s.substr(p + 2);
  };
  return (a.find("::") == std::string::npos || b.find("::") == std::string::npos) && short_of(a) == short_of(b) &&
         msg::find_wire_type(a) == msg::find_wire_type(b);
}

}  // namespace

Wiring wire(const Scenario& scenario) {
  const auto& components = scenario.components;
  Wiring w;
  std::map<std::string, std::size_t> by_name;
  std::vector<std::pair<std::size_t, std::string>> produced_by;  // per signal: component and port
  w.outputs.resize(components.size());
  w.inputs.resize(components.size());
  for (std::size_t ci = 0; ci < components.size(); ++ci) {
    const auto& c = components[ci];
    for (const auto& out : c.component->outputs()) {
      check_width(c, *out);
      if (auto it = by_name.find(out->signal()); it != by_name.end()) {
        // Two producers of one signal: a remap that made it so is the culprit, not the other one.
        const auto& [first_ci, first_port] = produced_by[it->second];
        if (const auto where = remap_of(c, out->port()); !where.empty())
          throw InputError(where + ": sends " + c.component->name() + "'s output '" + out->port() + "' to '" +
                           out->signal() + "', which " + w.signals[it->second].producer + " already produces");
        if (const auto where = remap_of(components[first_ci], first_port); !where.empty())
          throw InputError(where + ": sends " + w.signals[it->second].producer + "'s output '" + first_port + "' to '" +
                           out->signal() + "', which " + c.component->name() + " produces");
        throw InputError(c.where + ": output '" + out->signal() + "' is already produced by " +
                         w.signals[it->second].producer);
      }
      by_name[out->signal()] = w.signals.size();
      produced_by.emplace_back(ci, out->port());
      w.outputs[ci].push_back({out.get(), w.signals.size()});
      w.signals.push_back({out->signal(), out->fields(), c.period_steps, c.component->name(),
                           c.kind == ComponentKind::plant, out->message()});
      w.producer_kind.push_back(c.kind);
    }
  }
  for (std::size_t ci = 0; ci < components.size(); ++ci) {
    const auto& c = components[ci];
    for (const auto& in : c.component->inputs()) {
      check_width(c, *in);
      auto it = by_name.find(in->signal());
      if (it == by_name.end() && scenario.partial) {
        // Produced in another process: its spec is what this document knows of it.
        if (in->message().empty())
          throw InputError(c.where + ": input '" + in->signal() + "' (port '" + in->port() +
                           "') must be produced in the same process (it has no IDL message type)");
        const auto ext = scenario.inputs.find(in->signal());
        SignalSpec spec;
        spec.name = in->signal();
        spec.period_steps =
            ext != scenario.inputs.end() && ext->second.period_steps > 0 ? ext->second.period_steps : c.period_steps;
        spec.producer =
            ext != scenario.inputs.end() && !ext->second.producer.empty() ? ext->second.producer : "(another process)";
        spec.message = in->message();
        it = by_name.emplace(spec.name, w.signals.size()).first;
        w.signals.push_back(std::move(spec));
        produced_by.emplace_back(ci, in->port());
        // Without a stage the reader reads it as from an earlier stage (no delay).
        const bool staged = ext != scenario.inputs.end() && ext->second.staged;
        w.producer_kind.push_back(staged ? ext->second.stage : ComponentKind::plant);
        w.external.push_back(w.signals.size() - 1);
      }
      if (it == by_name.end()) no_producer(components, c, *in);
      InputBinding b;
      b.port = in.get();
      b.signal = it->second;
      const bool external = std::find(w.external.begin(), w.external.end(), b.signal) != w.external.end();
      b.delayed = external && scenario.inputs.count(in->signal()) == 0
                      ? false
                      : static_cast<int>(w.producer_kind[b.signal]) >= static_cast<int>(c.kind);
      b.width = in->fields().size();
      SignalSpec& spec = w.signals[b.signal];
      if (external) {  // the fields of an external signal are those its readers here name
        if (!same_message(spec.message, in->message()))
          throw InputError(c.where + ": input '" + in->signal() + "' is read as " + in->message() + " here and as " +
                           spec.message + " by another component of this process");
        for (const auto& f : in->fields())
          if (std::find(spec.fields.begin(), spec.fields.end(), f) == spec.fields.end()) spec.fields.push_back(f);
        if (spec.fields.size() > kMaxSignalFields)
          throw InputError(c.where + ": input '" + in->signal() + "' is read with more than " +
                           std::to_string(kMaxSignalFields) + " fields");
      } else if (!in->message().empty() && !spec.message.empty() && !same_message(in->message(), spec.message)) {
        throw InputError(c.where + ": input '" + in->signal() + "' (port '" + in->port() + "') expects " +
                         in->message() + ", but '" + spec.producer + "' publishes it as " + spec.message);
      }
      for (std::size_t f = 0; f < b.width; ++f) {
        std::size_t found = spec.fields.size();
        for (std::size_t g = 0; g < spec.fields.size(); ++g)
          if (spec.fields[g] == in->fields()[f]) found = g;
        // Another name of the same member of the message type (Imu's gyro is wy).
        if (found == spec.fields.size() && !spec.message.empty())
          if (const std::string member = member_of(spec.message, in->fields()[f]); !member.empty())
            for (std::size_t g = 0; g < spec.fields.size(); ++g)
              if (member_of(spec.message, spec.fields[g]) == member) found = g;
        if (found == spec.fields.size() && in->whole_message()) {
          b.absent[f] = true;  // a member its producer does not use: 0, as on the wire
          continue;
        }
        if (found == spec.fields.size())
          throw InputError(c.where + ": input '" + in->signal() + "' has no field '" + in->fields()[f] +
                           "' (it has: " + join(spec.fields) + ")");
        b.field_of[f] = found;
      }
      w.inputs[ci].push_back(b);
    }
  }
  return w;
}

}  // namespace plexus::scenario::detail

namespace plexus::scenario {

std::string member_of(const std::string& message, const std::string& field) {
  if (const msg::WireType* t = msg::find_wire_type(message))
    for (const auto& s : t->slots)
      if (s.field == field) return s.path;
  return "";
}

}  // namespace plexus::scenario
