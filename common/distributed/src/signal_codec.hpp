// Internal: scenario SignalSample <-> plexus::msg::Signal.
#pragma once

#include "plexus/msg/messages.hpp"
#include "plexus/scenario/signal.hpp"

namespace plexus::distributed::detail {

void to_message(const scenario::SignalSample& s, std::size_t width, int64_t step_ns, msg::Signal& m);
/// Why a received Signal was refused.
enum class Rejection { none, wrong_width, negative_step, non_finite };

/// Decodes `m` into `s` for a signal of `width` fields, or says why it cannot (then `s` is
/// untouched); `bad_field` receives the index of the first non-finite field.
Rejection from_message(const msg::Signal& m, std::size_t width, scenario::SignalSample& s, std::size_t& bad_field);

}  // namespace plexus::distributed::detail
