// The omgidl schema of a file: the IDL text a third-party parser needs to decode its types
// with no include path, so its includes are resolved into the text (dependencies first).
#include <set>
#include <sstream>

#include "emit.hpp"

namespace plexus::idlgen {
namespace {

const File* find_file(const Model& model, const std::string& include_name) {
  for (const auto& f : model.files)
    if (f.include_name == include_name) return &f;
  return nullptr;
}

void append(const Model& model, const File& f, std::set<std::string>& done, std::string& out) {
  if (!done.insert(f.include_name).second) return;
  for (const auto& inc : f.includes)
    if (const File* dep = find_file(model, inc)) append(model, *dep, done, out);
  std::istringstream in(f.text);
  std::string line;
  while (std::getline(in, line)) {
    const auto first = line.find_first_not_of(" \t");
    if (first != std::string::npos && line[first] == '#') continue;  // #include and the include guards
    out += line + "\n";
  }
}

}  // namespace

std::string schema_text(const Model& model, const File& file) {
  std::set<std::string> done;
  std::string out;
  append(model, file, done, out);
  return out;
}

}  // namespace plexus::idlgen
