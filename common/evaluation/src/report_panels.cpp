#include "plexus/evaluation/report_panels.hpp"

#include <array>
#include <utility>

namespace plexus::scenario {
namespace {

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() > suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

bool is_spread(const std::string& field) { return field.rfind("sd_", 0) == 0 || ends_with(field, "_std"); }

bool is_coordinate(const std::string& field) { return field == "x" || field == "y" || field == "z"; }

bool is_length(const std::string& unit) { return unit == "m" || unit == "mm" || unit == "km"; }

/// The name without its trailing digits: q1 -> q, z3 -> z, class -> class.
std::string stem(const std::string& field) {
  std::size_t end = field.size();
  while (end > 1 && field[end - 1] >= '0' && field[end - 1] <= '9') --end;
  return field.substr(0, end);
}

}  // namespace

std::string quantity_of_unit(const std::string& unit) {
  static const std::array<std::pair<const char*, const char*>, 16> kQuantities{{
      {"m", "length"},
      {"mm", "length"},
      {"km", "length"},
      {"rad", "angle"},
      {"mrad", "angle"},
      {"deg", "angle"},
      {"m/s", "speed"},
      {"rad/s", "angular rate"},
      {"deg/s", "angular rate"},
      {"m/s^2", "acceleration"},
      {"rad/s^2", "angular acceleration"},
      {"rad/s^3", "angular jerk"},
      {"N m", "torque"},
      {"N m/s", "torque rate"},
      {"1/s", "rate"},
      {"s", "time"},
  }};
  for (const auto& [u, q] : kQuantities)
    if (unit == u) return q;
  return "";
}

std::vector<FieldGroup> group_fields(const std::vector<FieldUnit>& fields) {
  std::vector<FieldGroup> groups;
  for (const auto& f : fields) {
    std::string quantity;
    if (f.unit && !f.unit->empty()) {
      if (is_spread(f.field))
        quantity = "standard deviation";
      else if (is_coordinate(f.field) && is_length(*f.unit))
        quantity = "position";
      else
        quantity = quantity_of_unit(*f.unit);
      if (quantity.empty()) quantity = *f.unit;  // a unit without a known quantity is its own
    } else {
      quantity = stem(f.field);  // dimensionless or undeclared: same stem only
    }
    auto it = groups.begin();
    for (; it != groups.end(); ++it)
      if (it->quantity == quantity && it->unit == f.unit) break;
    if (it == groups.end()) {
      groups.push_back({quantity, f.unit, {}});
      it = groups.end() - 1;
    }
    it->fields.push_back(f.field);
  }
  return groups;
}

std::string unit_text(const std::optional<std::string>& unit) {
  if (!unit) return "[unit not declared]";
  return unit->empty() ? "[-]" : "[" + *unit + "]";
}

std::string axis_label(const std::string& quantity, const std::optional<std::string>& unit) {
  return quantity + " " + unit_text(unit);
}

std::optional<std::string> metric_unit(const std::string& metric) {
  static const std::array<std::pair<const char*, const char*>, 12> kSuffixes{{
      {"_mrad", "mrad"},
      {"_mm", "mm"},
      {"_m", "m"},
      {"_deg", "deg"},
      {"_rad", "rad"},
      {"_s", "s"},
      {"_nm", "N m"},
      {"_mps", "m/s"},
      {"_hz", "Hz"},
      {"_ratio", ""},
      {"_accuracy", ""},
      {"_count", ""},
  }};
  for (const auto& [suffix, unit] : kSuffixes)
    if (ends_with(metric, suffix)) return std::string(unit);
  return std::nullopt;
}

}  // namespace plexus::scenario
