#include "wiring.hpp"

#include <map>

#include "plexus/base/input_error.hpp"

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

}  // namespace

Wiring wire(const std::vector<ScenarioComponent>& components) {
  Wiring w;
  std::map<std::string, std::size_t> by_name;
  w.outputs.resize(components.size());
  w.inputs.resize(components.size());
  for (std::size_t ci = 0; ci < components.size(); ++ci) {
    const auto& c = components[ci];
    for (const auto& out : c.component->outputs()) {
      check_width(c, *out);
      if (auto it = by_name.find(out->signal()); it != by_name.end())
        throw InputError(c.where + ": output '" + out->signal() + "' is already produced by " +
                         w.signals[it->second].producer);
      by_name[out->signal()] = w.signals.size();
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
      if (it == by_name.end())
        throw InputError(c.where + ": input '" + in->signal() + "' (port '" + in->port() +
                         "') is produced by no component; remap the port or add its producer");
      InputBinding b;
      b.port = in.get();
      b.signal = it->second;
      b.delayed = static_cast<int>(w.producer_kind[b.signal]) >= static_cast<int>(c.kind);
      b.width = in->fields().size();
      const SignalSpec& spec = w.signals[b.signal];
      for (std::size_t f = 0; f < b.width; ++f) {
        std::size_t found = spec.fields.size();
        for (std::size_t g = 0; g < spec.fields.size(); ++g)
          if (spec.fields[g] == in->fields()[f]) found = g;
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
