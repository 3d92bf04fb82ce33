// Test helper shared by the family test binaries: the std::invalid_argument message raised by constructing T from args,
// "" if none.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>

namespace plexus::algorithms::testing {

template <class T, class... Args>
std::string invalid_argument_message(Args&&... args) {
  try {
    T object(std::forward<Args>(args)...);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

}  // namespace plexus::algorithms::testing
