// Parameter validation helpers shared by every algorithm's Params check.
//
// Each throws ParameterError (a std::invalid_argument) with a message that names the algorithm, the
// parameter, the requirement and the offending value, e.g.
//   "heading_observer: L must be finite and > 0 (got -1)"
// The scenario layer catches it and names the file:line of the parameter's key.
#pragma once

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>

namespace plexus::algorithms::validation {

inline std::string format_value(double value) {
  std::ostringstream os;
  os.precision(12);
  os << value;
  return os.str();
}

/// The error of one parameter: the message above, and the parameter's name, so that the
/// scenario layer can name the line of that key.
class ParameterError : public std::invalid_argument {
 public:
  ParameterError(const std::string& message, std::string_view parameter)
      : std::invalid_argument(message), parameter_(parameter) {}
  /// As the algorithm names it: a key of the component's section, or an element ("k_tau[1]").
  const std::string& parameter() const { return parameter_; }

 private:
  std::string parameter_;
};

[[noreturn]] inline void fail(std::string_view where, std::string_view name, std::string_view requirement,
                              double value) {
  std::string msg;
  msg.append(where).append(": ").append(name).append(" must be ").append(requirement);
  msg.append(" (got ").append(format_value(value)).append(")");
  throw ParameterError(msg, name);
}

/// value is finite and > 0.
inline void require_positive(std::string_view where, std::string_view name, double value) {
  if (!(std::isfinite(value) && value > 0.0)) fail(where, name, "finite and > 0", value);
}

/// value is finite and >= 0.
inline void require_non_negative(std::string_view where, std::string_view name, double value) {
  if (!(std::isfinite(value) && value >= 0.0)) fail(where, name, "finite and >= 0", value);
}

/// value is finite.
inline void require_finite(std::string_view where, std::string_view name, double value) {
  if (!std::isfinite(value)) fail(where, name, "finite", value);
}

/// lo < value < hi (open interval).
inline void require_open_interval(std::string_view where, std::string_view name, double value, double lo, double hi) {
  if (!(value > lo && value < hi)) {
    fail(where, name, "in (" + format_value(lo) + ", " + format_value(hi) + ")", value);
  }
}

/// value > 0, +infinity allowed (e.g. "no saturation").
inline void require_positive_or_inf(std::string_view where, std::string_view name, double value) {
  if (!(value > 0.0)) fail(where, name, "> 0 (infinity allowed)", value);
}

}  // namespace plexus::algorithms::validation
