// What plexus_idlgen writes from a checked Model. Each emitter returns the file's text.
#pragma once

#include <string>
#include <vector>

#include "idl_model.hpp"

namespace plexus::idlgen {

/// What the generated code of one message package is called and where it is included from.
struct Package {
  std::string name;    ///< "plexus_msgs", "mylab_msgs"
  std::string header;  ///< include name of the generated header ("plexus/msg/messages.hpp")
  /// Headers of the packages this one's files include (for their to_json and type supports).
  std::vector<std::string> dependency_headers;
};

/// The structs of the files given on the command line that are topic types (not @nested and
/// not the StampHeader), in file order.
std::vector<const Struct*> topic_structs(const Model& model);
/// The file a struct is in.
const File& file_of(const Model& model, const Struct& s);

/// The generated header: type supports, signal layouts, to_json declarations, the type tuples.
std::string emit_header(const Model& model, const Package& pkg);
/// The generated source: type supports, field descriptions, schemas, JSON, registration.
std::string emit_source(const Model& model, const Package& pkg);
/// The self-contained IDL text of a file: its includes' texts first, preprocessor lines removed
/// (the `omgidl` schema of its types in MCAP files and on the Foxglove WebSocket).
std::string schema_text(const Model& model, const File& file);
/// One file of a generated folder, its path relative to the folder.
struct GeneratedFile {
  std::string path;
  std::string text;
};
/// The ROS 2 interface package of the package's types (docs/ros2.md): package.xml,
/// CMakeLists.txt, msg/<Type>.msg. Throws std::runtime_error, naming the IDL line, for what
/// a .msg cannot say (a name ROS 2 refuses, a multi-dimensional array).
std::vector<GeneratedFile> emit_ros2(const Model& model, const Package& pkg);
/// The Markdown reference of the package's message types (docs/messages.md for plexus).
std::string emit_docs(const Model& model, const Package& pkg);

}  // namespace plexus::idlgen
