#include "input_guard.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>

#include "plexus/base/clock.hpp"

namespace plexus::distributed::detail {

bool InputGuard::accept(const WireSignal& wire, const void* message, scenario::SignalSample& s) {
  std::size_t bad = 0;
  const Rejection r = wire.decode(message, s, bad);
  if (r == Rejection::none) return true;
  ++rejected_;
  uint64_t held = 0;
  if (limiter_.allow(monotonic_ns(), held)) {
    const auto& spec = wire.spec();
    std::string why = to_string(r);
    if (r == Rejection::non_finite || r == Rejection::out_of_range) {
      const WireSlot& slot = *std::find_if(wire.type().slots.begin(), wire.type().slots.end(),
                                           [&](const WireSlot& x) { return x.field == spec.fields[bad]; });
      why += ": '" + spec.fields[bad] + "' is " + std::to_string(wire.value(message, bad)) + " (range " +
             std::to_string(slot.min) + " .. " + std::to_string(slot.max) +
             (*slot.unit ? std::string(" ") + slot.unit : "") + ")";
    }
    spdlog::warn("{}: refused a {} sample on '{}' from '{}': {}; {} refused so far{}", host_, wire.type().name,
                 spec.name, spec.producer, why, rejected_,
                 held ? " (" + std::to_string(held) + " not logged)" : std::string());
  }
  return false;
}

}  // namespace plexus::distributed::detail
