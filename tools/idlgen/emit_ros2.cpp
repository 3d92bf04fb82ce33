// The ROS 2 interface package of a message package (docs/ros2.md): package.xml,
// CMakeLists.txt and one msg/<Type>.msg per struct, with the members in IDL order and types
// whose CDR layout is the IDL's, so that a ROS 2 node built with the package reads and writes
// plexus topics published under `naming: ros2` with no bridge.
//
// The mapping (ROS 2 design, "Interface definition" and "IDL mapping"):
//   boolean -> bool, octet/uint8 -> uint8, char -> uint8 (one byte; ROS 2's own char is an
//   alias of uint8), int8..uint64, float -> float32, double -> float64;
//   T name[N] -> T[N] name; sequence<T, N> -> T[<=N]; string<N> -> string<=N;
//   an enum -> uint32 (XCDR1 writes an enum as 4 bytes) with its enumerators as constants of
//   the message that uses it; a struct -> its message, `plexus_msgs/StampHeader` across packages.
// Module constants (MAX_JOINTS) have no place in a .msg: the array sizes are written out.
#include <cstdint>
#include <regex>
#include <set>
#include <stdexcept>
#include <string>

#include "emit.hpp"

namespace plexus::idlgen {
namespace {

/// A comment block as .msg comment lines.
std::string comment(const std::string& text) {
  std::string out = "# ";
  for (char c : text) out += c == '\n' ? std::string("\n# ") : std::string(1, c);
  return out + "\n";
}

std::string primitive_text(Primitive p) {
  switch (p) {
    case Primitive::boolean: return "bool";
    case Primitive::octet:
    case Primitive::u8:
    case Primitive::char_: return "uint8";
    case Primitive::i8: return "int8";
    case Primitive::i16: return "int16";
    case Primitive::u16: return "uint16";
    case Primitive::i32: return "int32";
    case Primitive::u32: return "uint32";
    case Primitive::i64: return "int64";
    case Primitive::u64: return "uint64";
    case Primitive::f32: return "float32";
    case Primitive::f64: return "float64";
    case Primitive::none: break;
  }
  return "?";
}

class Ros2Writer {
 public:
  Ros2Writer(const Model& model, const Package& pkg) : model_(model), pkg_(pkg) {}

  /// The ROS 2 package a struct belongs to: this package for its own files; plexus's messages
  /// are plexus_msgs. Other packages' structs are not mapped yet (docs/ros2.md).
  std::string package_of(const Struct& s) const {
    if (file_of(model_, s).own) return pkg_.name;
    if (s.scope == std::vector<std::string>{"plexus", "msg"}) return "plexus_msgs";
    throw std::runtime_error(s.where.str() + ": " + s.scoped() +
                             " comes from another message package: its ROS 2 package is not known to plexus_idlgen "
                             "(docs/ros2.md)");
  }

  std::string base_type(const TypeRef& t, const Member& m, const Struct& in, std::set<std::string>& deps,
                        std::set<const Enum*>& enums) const {
    switch (t.kind) {
      case TypeRef::Kind::string: return t.bound ? "string<=" + std::to_string(t.bound) : "string";
      case TypeRef::Kind::sequence: {
        const TypeRef& e = t.element.front();
        if (e.kind == TypeRef::Kind::sequence || e.kind == TypeRef::Kind::string)
          throw std::runtime_error(m.where.str() + ": " + m.name +
                                   ": a sequence of sequences or strings has no .msg form");
        return base_type(e, m, in, deps, enums) + (t.bound ? "[<=" + std::to_string(t.bound) + "]" : "[]");
      }
      case TypeRef::Kind::named: {
        if (const Enum* e = model_.find_enum(t.name)) {
          enums.insert(e);
          return "uint32";
        }
        const Struct* s = model_.find_struct(t.name);
        if (!s) throw std::runtime_error(m.where.str() + ": " + m.name + ": unknown type " + t.name);
        const std::string pkg = package_of(*s);
        if (pkg == package_of(in)) return s->name;
        deps.insert(pkg);
        return pkg + "/" + s->name;
      }
      case TypeRef::Kind::primitive: break;
    }
    return primitive_text(t.primitive);
  }

  std::string msg(const Struct& s, std::set<std::string>& deps) const {
    static const std::regex field_rule("[a-z][a-z0-9]*(_[a-z0-9]+)*");
    static const std::regex type_rule("[A-Z][A-Za-z0-9]*");
    if (!std::regex_match(s.name, type_rule))
      throw std::runtime_error(s.where.str() + ": " + s.name + ": not a ROS 2 message name (CamelCase)");
    std::string body;
    std::set<const Enum*> enums;
    for (const Member& m : s.members) {
      if (!std::regex_match(m.name, field_rule))
        throw std::runtime_error(m.where.str() + ": " + m.name + ": not a ROS 2 field name (lower_snake_case)");
      if (m.dims.size() > 1)
        throw std::runtime_error(m.where.str() + ": " + m.name + ": a multi-dimensional array has no .msg form");
      std::string type = base_type(m.type, m, s, deps, enums);
      if (!m.dims.empty()) {
        if (m.type.kind == TypeRef::Kind::sequence)
          throw std::runtime_error(m.where.str() + ": " + m.name + ": an array of sequences has no .msg form");
        type += "[" + std::to_string(m.dims.front()) + "]";
      }
      if (!m.doc.empty()) body += comment(m.doc);
      body += type + " " + m.name + "\n";
    }
    std::string head =
        "# " + s.scoped() + ", generated from " + file_of(model_, s).include_name + " by plexus_idlgen: do not edit.\n";
    if (!s.doc.empty()) head += comment(s.doc);
    for (const Enum* e : enums) {
      head += "\n# " + e->scoped() + " (an IDL enum: uint32 on the wire)\n";
      for (std::size_t i = 0; i < e->enumerators.size(); ++i)
        head += "uint32 " + e->enumerators[i] + "=" + std::to_string(i) + "\n";
    }
    return head + "\n" + body;
  }

  std::vector<GeneratedFile> files() const {
    std::vector<GeneratedFile> out;
    std::set<std::string> deps;
    std::string msg_list;
    for (const File& f : model_.files) {
      if (!f.own) continue;
      for (const Struct& s : f.structs) {
        out.push_back({"msg/" + s.name + ".msg", msg(s, deps)});
        msg_list += "  \"msg/" + s.name + ".msg\"\n";
      }
    }
    std::string xml_deps, cmake_find, cmake_deps;
    for (const auto& d : deps) {
      xml_deps += "  <depend>" + d + "</depend>\n";
      cmake_find += "find_package(" + d + " REQUIRED)\n";
      cmake_deps += " " + d;
    }
    out.push_back(
        {"package.xml",
         R"(<?xml version="1.0"?>
<?xml-model href="http://download.ros.org/schema/package_format3.xsd" schematypens="http://www.w3.org/2001/XMLSchema"?>
<!-- Generated from the IDL of )" +
             pkg_.name + R"( by plexus_idlgen: do not edit (docs/ros2.md). -->
<package format="3">
  <name>)" + pkg_.name +
             R"(</name>
  <version>0.1.0</version>
  <description>The messages of )" +
             pkg_.name +
             R"( as ROS 2 interfaces, with plexus's CDR layout: ROS 2 nodes read and write plexus topics published under naming ros2.</description>
  <maintainer email="plexus@localhost">plexus</maintainer>
  <license>Apache-2.0</license>
  <buildtool_depend>ament_cmake</buildtool_depend>
  <buildtool_depend>rosidl_default_generators</buildtool_depend>
)" + xml_deps +
             R"(  <exec_depend>rosidl_default_runtime</exec_depend>
  <member_of_group>rosidl_interface_packages</member_of_group>
  <export>
    <build_type>ament_cmake</build_type>
  </export>
</package>
)"});
    out.push_back({"CMakeLists.txt", "# Generated from the IDL of " + pkg_.name +
                                         " by plexus_idlgen: do not edit (docs/ros2.md).\n"
                                         "cmake_minimum_required(VERSION 3.8)\nproject(" +
                                         pkg_.name +
                                         ")\nfind_package(ament_cmake REQUIRED)\n"
                                         "find_package(rosidl_default_generators REQUIRED)\n" +
                                         cmake_find + "rosidl_generate_interfaces(${PROJECT_NAME}\n" + msg_list +
                                         (cmake_deps.empty() ? "" : "  DEPENDENCIES" + cmake_deps + "\n") +
                                         ")\nament_export_dependencies(rosidl_default_runtime)\nament_package()\n"});
    return out;
  }

 private:
  const Model& model_;
  const Package& pkg_;
};

}  // namespace

std::vector<GeneratedFile> emit_ros2(const Model& model, const Package& pkg) { return Ros2Writer(model, pkg).files(); }

}  // namespace plexus::idlgen
