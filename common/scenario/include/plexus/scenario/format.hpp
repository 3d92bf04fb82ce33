// Numbers in messages and files: the shortest text that reads back as the same double.
#pragma once

#include <string>

namespace plexus::scenario {

/// Shortest text that reads back as the same double ("nan" for NaN).
std::string format_number(double value);

/// Appends format_number(value) to `out` (no temporary: for the rows of large CSV files).
void append_number(std::string& out, double value);

}  // namespace plexus::scenario
