// The one line a CLI piece refuses bad input with, for the plexus_cli_tests.
#pragma once

#include <string>

#include "plexus/base/input_error.hpp"

namespace plexus::cli::test_support {

/// fn()'s InputError message, or "no error".
std::string error_of(auto&& fn) {
  try {
    fn();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace plexus::cli::test_support
