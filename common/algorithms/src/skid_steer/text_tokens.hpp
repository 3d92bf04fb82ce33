// The whitespace-separated tokens of one line of a plexus text file (the terrain training
// set, the terrain ICR library).
#pragma once

#include <sstream>
#include <string>
#include <vector>

namespace plexus::algorithms::detail {

inline std::vector<std::string> tokens(const std::string& line) {
  std::istringstream is(line);
  std::vector<std::string> out;
  for (std::string t; is >> t;) out.push_back(t);
  return out;
}

}  // namespace plexus::algorithms::detail
