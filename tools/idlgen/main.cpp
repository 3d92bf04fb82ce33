// plexus_idlgen: what plexus generates from a message package's IDL files, beside fastddsgen
// and idlc (cmake/PlexusMessages.cmake runs all three; docs/sdk.md, "Messages"):
//   --header FILE  type supports, signal layouts, to_json declarations
//   --source FILE  type supports, signal fields (the edge check), schemas, registration
//   --docs FILE    the Markdown reference of the messages
//   --ros2 DIR     the ROS 2 interface package of the messages (docs/ros2.md)
// after checking the interop rules (idl_checks.hpp). A broken rule or a parse error is one
// line "file:line: what" and exit code 2.
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "emit.hpp"
#include "idl_checks.hpp"
#include "idl_parser.hpp"

namespace {

int usage() {
  std::fprintf(stderr,
               "usage: plexus_idlgen --package NAME --header-name INCLUDE [--dependency-header INCLUDE]...\n"
               "                     [--header FILE] [--source FILE] [--docs FILE] [--ros2 DIR] [--check] -I DIR... "
               "FILE.idl...\n"
               "       plexus_idlgen --version\n");
  return 2;
}

// Writes `text` to `path` unless it already holds exactly that (so that builds depending on it
// do not rerun).
void write_if_changed(const std::string& path, const std::string& text) {
  {
    std::ifstream in(path, std::ios::binary);
    if (in) {
      std::string old((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      if (old == text) return;
    }
  }
  if (const auto dir = std::filesystem::path(path).parent_path(); !dir.empty())
    std::filesystem::create_directories(dir);
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error(path + ": cannot be written");
}

}  // namespace

int main(int argc, char** argv) {
  using namespace plexus::idlgen;
  Package pkg;
  std::string header, source, docs, ros2;
  std::vector<std::string> dirs, files;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::runtime_error(a + " needs a value");
      return argv[++i];
    };
    try {
      if (a == "--package")
        pkg.name = value();
      else if (a == "--header-name")
        pkg.header = value();
      else if (a == "--dependency-header")
        pkg.dependency_headers.push_back(value());
      else if (a == "--header")
        header = value();
      else if (a == "--source")
        source = value();
      else if (a == "--docs")
        docs = value();
      else if (a == "--ros2")
        ros2 = value();
      else if (a == "-I")
        dirs.push_back(value());
      else if (a.rfind("-I", 0) == 0)
        dirs.push_back(a.substr(2));
      else if (a == "--help" || a == "-h")
        return usage() - 2;
      else if (a == "--version") {
        std::printf("plexus_idlgen %s\n", PLEXUS_VERSION);
        return 0;
      } else if (a.rfind("-", 0) == 0) {
        std::fprintf(stderr, "plexus_idlgen: error: unknown option %s\n", a.c_str());
        return usage();
      } else
        files.push_back(a);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "plexus_idlgen: error: %s\n", e.what());
      return 2;
    }
  }
  if (pkg.name.empty() || pkg.header.empty() || files.empty() || dirs.empty()) return usage();
  try {
    const Model model = parse_files(files, dirs);
    check_model(model);
    if (!header.empty()) write_if_changed(header, emit_header(model, pkg));
    if (!source.empty()) write_if_changed(source, emit_source(model, pkg));
    if (!docs.empty()) write_if_changed(docs, emit_docs(model, pkg));
    if (!ros2.empty())
      for (const auto& f : emit_ros2(model, pkg)) {
        std::filesystem::create_directories(std::filesystem::path(ros2 + "/" + f.path).parent_path());
        write_if_changed(ros2 + "/" + f.path, f.text);
      }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "plexus_idlgen: error: %s\n", e.what());
    return 2;
  }
  return 0;
}
