// Text put into an HTML page (the reports: `plexus report`, `plexus bench`): the five
// characters that could end an element or an attribute, escaped.
#pragma once

#include <string>

namespace plexus {

inline std::string html_escape(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (char c : s) switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  return out;
}

}  // namespace plexus
