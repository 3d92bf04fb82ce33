// Signals: the named, fixed-size numeric records that components exchange.
//
// A signal is named `<robot>/<topic>` (for example `r1/truth/state`), has an ordered list of
// field names (for example x, y, theta) and is produced by exactly one component at
// that component's rate. Its value at one step is a SignalSample: at most
// kMaxSignalFields doubles plus the base step at which it was produced. These are
// plain records, not DDS types: the distributed runtime maps each one onto the typed IDL
// message its producer names (SignalSpec::message, docs/topics.md).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace plexus::scenario {

/// Largest number of fields in one signal: an arm estimate of 16 joints has 8 per joint, and
/// read whole (a typed port) its joint count too (plexus::msg::LinkJointState: 129).
inline constexpr std::size_t kMaxSignalFields = 136;

/// The value of a signal at one base step.
struct SignalSample {
  int64_t step = -1;                              ///< base step it was produced at; -1: never produced
  std::array<double, kMaxSignalFields> values{};  ///< fields in declared order, the rest zero
};

/// What a signal is: its name, its fields and how often it is produced.
struct SignalSpec {
  std::string name;                 ///< `<robot>/<topic>`, or `<topic>` for robot-less services
  std::vector<std::string> fields;  ///< field names, in order
  int64_t period_steps = 1;         ///< produced every period_steps base steps
  std::string producer;             ///< name of the component that produces it
  bool plant_state = false;         ///< produced by a plant: part of the run digest
  /// The IDL message type that carries it between processes ("PositionMeasurement", see
  /// idl/plexus/msg/); empty for a signal that can only run in process (`plexus sim`).
  std::string message;
};

}  // namespace plexus::scenario
