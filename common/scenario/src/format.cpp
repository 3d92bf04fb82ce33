#include "plexus/scenario/format.hpp"

#include <charconv>
#include <cmath>

namespace plexus::scenario {

std::string format_number(double value) {
  if (std::isnan(value)) return "nan";
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, value);
  return std::string(buf, r.ptr);
}

}  // namespace plexus::scenario
