// What plexus_idlgen reads from IDL files: the subset of OMG IDL 4 that plexus messages use
// (docs/sdk.md, "Messages"): modules, constants, enums and @final structs whose members are
// primitive numbers, bounded strings and sequences, fixed arrays, enums and other structs.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace plexus::idlgen {

/// Where something was written, for errors ("idl/plexus/msg/pose.idl:12").
struct Location {
  std::string file;  ///< as given on the command line (or found through an include)
  int line = 0;
  std::string str() const { return file + ":" + std::to_string(line); }
};

/// A primitive IDL type; `none` for constructed ones.
enum class Primitive { none, boolean, octet, char_, i8, u8, i16, u16, i32, u32, i64, u64, f32, f64 };

/// The type of a member (before its array dimensions).
struct TypeRef {
  enum class Kind { primitive, string, sequence, named };
  Kind kind = Kind::primitive;
  Primitive primitive = Primitive::none;
  std::string name;              ///< named: the scoped name it resolves to ("plexus::msg::StampHeader")
  uint64_t bound = 0;            ///< string / sequence bound (0: unbounded)
  std::vector<TypeRef> element;  ///< sequence: its element type (one)
};

/// One `[fields: ...]` element: the signal field names of one array element (or of the scalar).
using FieldNames = std::vector<std::string>;

struct Member {
  std::string name;
  TypeRef type;
  std::vector<uint64_t> dims;                  ///< fixed array dimensions (one at most for signal fields)
  std::optional<std::string> unit;             ///< @unit("m")
  std::optional<double> range_min, range_max;  ///< @range(min=..., max=...)
  bool range_integral = true;                  ///< both @range limits written as whole numbers
  bool key = false, optional = false;          ///< @key, @optional (both refused by the checks)
  std::vector<FieldNames> fields;              ///< the comment's [fields: ...]; '#' in a name: the 1-based index
  bool count = false;                          ///< the comment's [count]: the number of valid array entries
  std::string doc;                             ///< the comment without its tags
  Location where;
};

struct Struct {
  std::vector<std::string> scope;  ///< enclosing modules ({"plexus", "msg"})
  std::string name;
  std::vector<Member> members;
  std::string extensibility;  ///< "final", "appendable", "mutable" or "" (not given)
  bool nested = false;        ///< @nested: not a topic type
  std::string doc;            ///< the comment block above it
  Location where;
  std::string scoped() const;  ///< "plexus::msg::Pose2D"
};

struct Enum {
  std::vector<std::string> scope;
  std::string name;
  std::vector<std::string> enumerators;
  Location where;
  std::string scoped() const;
};

struct Constant {
  std::vector<std::string> scope;
  std::string name;
  TypeRef type;
  std::string value;  ///< the literal as written
  Location where;
};

/// One parsed IDL file.
struct File {
  std::string path;                   ///< as found on disk
  std::string include_name;           ///< the name others include it by ("plexus/msg/pose.idl")
  std::string base;                   ///< file name without extension ("pose"): fastddsgen's header name
  std::vector<std::string> includes;  ///< include names, in order
  std::vector<Struct> structs;
  std::vector<Enum> enums;
  std::vector<Constant> constants;
  std::string text;  ///< the file's text
  bool own = false;  ///< given on the command line (not only included)
};

/// Every file read: those given and those they include, each once, includes first.
struct Model {
  std::vector<File> files;
  const Struct* find_struct(const std::string& scoped) const;
  const Enum* find_enum(const std::string& scoped) const;
  const Constant* find_constant(const std::string& scoped) const;
};

}  // namespace plexus::idlgen
