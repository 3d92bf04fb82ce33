// Bad input: a config, message, file or argument that plexus refuses.
#pragma once

#include <stdexcept>
#include <string>

namespace plexus {

/// Exit code of a command that refuses its input (config, file, argument).
inline constexpr int kExitBadInput = 2;

/// Thrown for input plexus refuses. `what()` is one line that names where the
/// input came from (file:line: key, or the option) and what is wrong with it.
/// Commands catch it at the top, print it and exit with kExitBadInput.
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace plexus
