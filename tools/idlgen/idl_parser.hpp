// Reads IDL files into the Model (idl_model.hpp). Errors are thrown as IdlError with the file
// and line.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "idl_model.hpp"

namespace plexus::idlgen {

/// One line: "file:line: what".
class IdlError : public std::runtime_error {
 public:
  IdlError(const Location& where, const std::string& what) : std::runtime_error(where.str() + ": " + what) {}
};

/// Parses `files` (paths on disk) and, once each, every file they include, found through
/// `include_dirs` (the first that holds it). `files` must be named relative to one of the
/// include directories, so that each has an include name.
Model parse_files(const std::vector<std::string>& files, const std::vector<std::string>& include_dirs);

}  // namespace plexus::idlgen
