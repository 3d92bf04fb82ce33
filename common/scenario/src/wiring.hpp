// Binding of component ports to signals (internal to plexus_scenario).
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "plexus/scenario/scenario.hpp"

namespace plexus::scenario::detail {

struct InputBinding {
  InputPort* port = nullptr;
  std::size_t signal = 0;  ///< index into Wiring::signals
  bool delayed = false;    ///< reads the latest sample before this step (producer in same or later stage)
  std::size_t width = 0;
  std::array<std::size_t, kMaxSignalFields> field_of{};  ///< port field i = signal field field_of[i]
  std::array<bool, kMaxSignalFields> absent{};           ///< typed ports: a field the producer does not fill (reads 0)
};

struct OutputBinding {
  OutputPort* port = nullptr;
  std::size_t signal = 0;
};

struct Wiring {
  std::vector<SignalSpec> signals;
  std::vector<ComponentKind> producer_kind;         ///< per signal
  std::vector<std::vector<InputBinding>> inputs;    ///< per component
  std::vector<std::vector<OutputBinding>> outputs;  ///< per component
  std::vector<std::size_t> external;                ///< signals produced in another process (partial scenarios)
};

/// Binds every port; throws InputError naming the component for an output signal produced
/// twice, an input with no producer (in a partial scenario: an external input, see
/// Scenario::inputs), a missing field, a bad field count or a message type the producer
/// does not publish.
Wiring wire(const Scenario& scenario);

}  // namespace plexus::scenario::detail
