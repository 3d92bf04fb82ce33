// Internal: scenario SignalSample <-> plexus::msg::Signal.
#pragma once

#include "plexus/msg/messages.hpp"
#include "plexus/scenario/signal.hpp"

namespace plexus::distributed::detail {

void to_message(const scenario::SignalSample& s, std::size_t width, int64_t step_ns, msg::Signal& m);
/// False if the message does not carry `width` fields (malformed for this signal).
bool from_message(const msg::Signal& m, std::size_t width, scenario::SignalSample& s);

}  // namespace plexus::distributed::detail
