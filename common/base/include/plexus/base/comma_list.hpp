#pragma once
// A comma-separated list from the command line or a parameter ("a,b,,c"): its items in order,
// empty ones dropped ("a", "b", "c"). No trimming: a space is part of an item.
#include <string>
#include <string_view>
#include <vector>

namespace plexus {

inline std::vector<std::string> split_comma_list(std::string_view s) {
  std::vector<std::string> out;
  std::size_t begin = 0;
  while (begin <= s.size()) {
    const std::size_t end = std::min(s.find(',', begin), s.size());
    if (end > begin) out.emplace_back(s.substr(begin, end - begin));
    begin = end + 1;
  }
  return out;
}

}  // namespace plexus
