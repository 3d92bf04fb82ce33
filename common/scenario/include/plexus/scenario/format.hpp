// Numbers in messages and files: the shortest text that reads back as the same double.
#pragma once

#include <string>

namespace plexus::scenario {

/// Shortest text that reads back as the same double ("nan" for NaN).
std::string format_number(double value);

}  // namespace plexus::scenario
