#include "input_guard.hpp"

#include <spdlog/spdlog.h>

#include "plexus/base/clock.hpp"

namespace plexus::distributed::detail {

bool InputGuard::accept(const msg::Signal& m, const scenario::SignalSpec& spec, scenario::SignalSample& s) {
  std::size_t bad = 0;
  const Rejection r = from_message(m, spec.fields.size(), s, bad);
  if (r == Rejection::none) return true;
  ++rejected_;
  uint64_t held = 0;
  if (limiter_.allow(monotonic_ns(), held)) {
    std::string why;
    switch (r) {
      case Rejection::wrong_width:
        why = std::to_string(m.count()) + " fields, expected " + std::to_string(spec.fields.size());
        break;
      case Rejection::negative_step:
        why = "negative step " + std::to_string(m.step_index());
        break;
      default:
        why = "field '" + spec.fields[bad] + "' is " + std::to_string(m.field_values()[bad]);
        break;
    }
    spdlog::warn("{}: rejected a sample of '{}' from '{}' (step {}): {}; {} rejected so far{}", host_, spec.name,
                 spec.producer, m.step_index(), why, rejected_,
                 held ? " (" + std::to_string(held) + " not logged)" : std::string());
  }
  return false;
}

}  // namespace plexus::distributed::detail
