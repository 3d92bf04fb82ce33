// Bad input: a config, message, file or argument that plexus refuses.
#pragma once

#include <cstdio>
#include <stdexcept>
#include <string>

namespace plexus {

/// Exit code of a command that refuses its input (config, file, argument).
inline constexpr int kExitBadInput = 2;

/// `text` on one line: control characters (a newline in a quoted YAML key, the offending
/// byte a parser quotes) written as \n, \r or \xNN. Tabs and other bytes are kept.
inline std::string one_line(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x20 && u != 0x7f) {
      out += c;
    } else if (c == '\t') {
      out += c;
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\r') {
      out += "\\r";
    } else {
      char hex[5];
      std::snprintf(hex, sizeof hex, "\\x%02x", u);
      out += hex;
    }
  }
  return out;
}

/// Thrown for input plexus refuses. `what()` is one line that names where the
/// input came from (file:line: key, or the option) and what is wrong with it; the
/// constructor keeps it on one line whatever the input quoted in it holds (one_line).
/// Commands catch it at the top, print it and exit with kExitBadInput.
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(one_line(message)) {}
};

}  // namespace plexus
