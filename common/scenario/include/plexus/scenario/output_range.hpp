// The range an output port's fields may take: each field's @range in its IDL message, the
// edge check its readers in other processes apply (plexus/msg/registry.hpp). A component
// checks its own output against it before the output leaves the step: an estimator whose
// state diverged (non-finite, or beyond what its message can carry) restarts rather than
// publish it, so a reader in its own process never gets what one in another process would
// refuse (docs/architecture.md, "Bad input").
#pragma once

#include <vector>

#include "plexus/scenario/component.hpp"

namespace plexus::scenario {

class OutputRange {
 public:
  /// The ranges of `port`'s fields, from its message type (a field the type does not
  /// carry, or a port without a message, only has to be finite).
  explicit OutputRange(const OutputPort& port);

  /// The index of the first field of `port`'s current output that is non-finite or out of
  /// its range, or -1. No allocation.
  int first_violation(const OutputPort& port) const;

 private:
  std::vector<double> min_, max_;
};

}  // namespace plexus::scenario
