// `plexus report`: which fields of a signal share a plot panel. One quantity and one unit
// per panel, so that a 0.01 m standard deviation never shares an axis with a 37 m position.
//
// The grouping uses what the run folder knows: the field names and the unit of each field
// (signals.json, from the wire description of the signal's IDL message). Rules, in order:
//   - a spread (`sd_<f>`, `<f>_std`) is a "standard deviation" panel of its unit;
//   - a planar coordinate (`x`, `y`, `z`) in a length unit is a "position" panel;
//   - any other field with a unit goes to the panel of its unit's quantity ("angle [rad]",
//     "speed [m/s]", "length [m]": the skid-steer ICR coordinates y_l, y_r, x_G);
//   - a dimensionless field ("" unit: an id, a count, a direction cosine) or one whose unit
//     is not declared shares a panel only with fields of the same stem (q1, q2; z3, z4).
// docs/scenarios.md ("plexus report") states the same rules.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace plexus::scenario {

/// A field and its unit: "m", "" (dimensionless), nullopt (not declared).
struct FieldUnit {
  std::string field;
  std::optional<std::string> unit;
};

/// The fields of one panel, in signal order.
struct FieldGroup {
  std::string quantity;             ///< "position", "angle", "standard deviation", a stem
  std::optional<std::string> unit;  ///< the fields' common unit
  std::vector<std::string> fields;
};

/// The panels of one signal's fields, in the order of their first field.
std::vector<FieldGroup> group_fields(const std::vector<FieldUnit>& fields);

/// The bracketed unit of an axis label: "[m]", "[-]" (dimensionless), "[unit not declared]".
std::string unit_text(const std::optional<std::string>& unit);

/// "quantity [unit]".
std::string axis_label(const std::string& quantity, const std::optional<std::string>& unit);

/// The quantity a unit measures ("m" -> "length", "rad/s" -> "angular rate"), or "".
std::string quantity_of_unit(const std::string& unit);

/// The unit of a metric, from the suffix its name carries by convention (`_m`, `_mm`,
/// `_deg`, `_rad`, `_mrad`, `_s`, `_nm`, `_mps`, `_hz`; `_ratio`, `_accuracy`, `_count` are
/// dimensionless); nullopt for a name without one.
std::optional<std::string> metric_unit(const std::string& metric);

}  // namespace plexus::scenario
