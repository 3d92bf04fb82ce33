// What the libFuzzer targets of tests/fuzz share: a check that holds in every build, a
// scratch folder of the process for the files a target writes, quiet logging, and the
// check that an error refusing bad input is the one line plexus promises.
#pragma once

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

// Not assert(): it must hold in every build, and abort() is what libFuzzer reports.
#define CHECK(cond)                                                                 \
  do {                                                                              \
    if (!(cond)) {                                                                  \
      std::fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond); \
      std::abort();                                                                 \
    }                                                                               \
  } while (0)

namespace plexus::fuzz {

/// Reports an input that ended in something other than a clean refusal, then aborts (a
/// finding: libFuzzer saves the input).
[[noreturn]] inline void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz finding: %s\n", what.c_str());
  std::abort();
}

/// A refusal must be one non-empty line (docs/architecture.md, "Bad input").
inline void check_one_line(const std::string& message) {
  if (message.empty() || message.find('\n') != std::string::npos)
    finding("the refusal is not one non-empty line: [" + message + "]");
}

/// A folder of this process ($TMPDIR or /tmp), removed at exit. Created on first use.
inline const std::string& scratch_dir() {
  // Never destroyed: the exit handler that removes the folder runs after static destructors.
  static const std::string* dir = [] {
    const char* tmp = std::getenv("TMPDIR");
    const std::filesystem::path base = tmp && *tmp ? tmp : "/tmp";
    auto* d = new std::string((base / ("plexus_fuzz_" + std::to_string(::getpid()))).string());
    std::filesystem::create_directories(*d);
    std::atexit([] {
      std::error_code ec;
      std::filesystem::remove_all(scratch_dir(), ec);
    });
    return d;
  }();
  return *dir;
}

inline std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) finding("cannot read " + path + " (the fuzz target needs the source tree it was built from)");
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace plexus::fuzz
