#include "idl_parser.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace plexus::idlgen {
namespace fs = std::filesystem;

std::string Struct::scoped() const {
  std::string s;
  for (const auto& m : scope) s += m + "::";
  return s + name;
}

std::string Enum::scoped() const {
  std::string s;
  for (const auto& m : scope) s += m + "::";
  return s + name;
}

const Struct* Model::find_struct(const std::string& scoped) const {
  for (const auto& f : files)
    for (const auto& s : f.structs)
      if (s.scoped() == scoped) return &s;
  return nullptr;
}

const Enum* Model::find_enum(const std::string& scoped) const {
  for (const auto& f : files)
    for (const auto& e : f.enums)
      if (e.scoped() == scoped) return &e;
  return nullptr;
}

const Constant* Model::find_constant(const std::string& scoped) const {
  for (const auto& f : files)
    for (const auto& c : f.constants) {
      std::string s;
      for (const auto& m : c.scope) s += m + "::";
      if (s + c.name == scoped) return &c;
    }
  return nullptr;
}

namespace {

struct Token {
  enum class Kind { ident, number, string, punct, end };
  Kind kind = Kind::end;
  std::string text;
  int line = 0;
};

struct Comment {
  int line = 0;
  int column = 0;
  bool alone = false;  // the only thing on its line
  std::string text;    // without the // and surrounding blanks
};

// The tokens and comments of one file; preprocessor lines are kept aside.
struct Lexed {
  std::vector<Token> tokens;
  std::vector<Comment> comments;
  std::vector<std::pair<int, std::string>> includes;  // line, name
};

Lexed lex(const std::string& text, const std::string& file) {
  Lexed out;
  std::size_t i = 0;
  int line = 1;
  std::size_t line_start = 0;
  bool line_has_code = false;
  auto at = [&](std::size_t k) { return k < text.size() ? text[k] : '\0'; };
  while (i < text.size()) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
      ++i;
      line_start = i;
      line_has_code = false;
      continue;
    }
    if (std::isspace(static_cast<unsigned char>(c))) {
      ++i;
      continue;
    }
    if (c == '#' && !line_has_code) {  // a preprocessor line
      std::size_t e = text.find('\n', i);
      if (e == std::string::npos) e = text.size();
      const std::string directive = text.substr(i, e - i);
      std::istringstream in(directive.substr(1));
      std::string word;
      in >> word;
      if (word == "include") {
        const auto q1 = directive.find_first_of("\"<");
        const auto q2 = directive.find_first_of("\">", q1 + 1);
        if (q1 == std::string::npos || q2 == std::string::npos) throw IdlError({file, line}, "malformed #include");
        out.includes.emplace_back(line, directive.substr(q1 + 1, q2 - q1 - 1));
      } else if (word != "ifndef" && word != "define" && word != "endif" && word != "pragma") {
        throw IdlError({file, line},
                       "preprocessor directive '#" + word + "' is not supported (only #include and include guards)");
      }
      i = e;
      continue;
    }
    if (c == '/' && at(i + 1) == '/') {
      std::size_t e = text.find('\n', i);
      if (e == std::string::npos) e = text.size();
      std::string body = text.substr(i + 2, e - i - 2);
      while (!body.empty() && std::isspace(static_cast<unsigned char>(body.back()))) body.pop_back();
      std::size_t b = 0;
      while (b < body.size() && body[b] == ' ') ++b;
      out.comments.push_back({line, static_cast<int>(i - line_start), !line_has_code, body.substr(b)});
      i = e;
      continue;
    }
    if (c == '/' && at(i + 1) == '*') {
      const std::size_t e = text.find("*/", i + 2);
      if (e == std::string::npos) throw IdlError({file, line}, "unterminated comment");
      for (std::size_t k = i; k < e; ++k)
        if (text[k] == '\n') {
          ++line;
          line_start = k + 1;
        }
      i = e + 2;
      continue;
    }
    line_has_code = true;
    Token t;
    t.line = line;
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      std::size_t e = i;
      while (e < text.size() && (std::isalnum(static_cast<unsigned char>(text[e])) || text[e] == '_')) ++e;
      t.kind = Token::Kind::ident;
      t.text = text.substr(i, e - i);
      i = e;
    } else if (std::isdigit(static_cast<unsigned char>(c)) ||
               (c == '.' && std::isdigit(static_cast<unsigned char>(at(i + 1))))) {
      std::size_t e = i;
      while (e < text.size() && (std::isalnum(static_cast<unsigned char>(text[e])) || text[e] == '.' ||
                                 ((text[e] == '+' || text[e] == '-') && (text[e - 1] == 'e' || text[e - 1] == 'E'))))
        ++e;
      t.kind = Token::Kind::number;
      t.text = text.substr(i, e - i);
      i = e;
    } else if (c == '"') {
      std::size_t e = i + 1;
      std::string s;
      while (e < text.size() && text[e] != '"') {
        if (text[e] == '\\' && e + 1 < text.size()) ++e;
        if (text[e] == '\n') throw IdlError({file, line}, "unterminated string");
        s += text[e++];
      }
      if (e >= text.size()) throw IdlError({file, line}, "unterminated string");
      t.kind = Token::Kind::string;
      t.text = s;
      i = e + 1;
    } else if (c == ':' && at(i + 1) == ':') {
      t.kind = Token::Kind::punct;
      t.text = "::";
      i += 2;
    } else {
      t.kind = Token::Kind::punct;
      t.text = std::string(1, c);
      ++i;
    }
    out.tokens.push_back(std::move(t));
  }
  out.tokens.push_back({Token::Kind::end, "", line});
  return out;
}

struct Annotation {
  std::string name;
  std::map<std::string, std::string> params;  // "value" for a single unnamed parameter
  int line = 0;
};

class Parser {
 public:
  Parser(Lexed lexed, File& file, const Model& model) : lx_(std::move(lexed)), file_(file), model_(model) {}

  void parse() {
    while (peek().kind != Token::Kind::end) definition();
  }

 private:
  const Token& peek(std::size_t ahead = 0) const { return lx_.tokens[std::min(pos_ + ahead, lx_.tokens.size() - 1)]; }
  Token next() { return lx_.tokens[std::min(pos_++, lx_.tokens.size() - 1)]; }
  Location here() const { return {file_.path, peek().line}; }
  [[noreturn]] void fail(const std::string& what) const {
    const Token& t = peek();
    throw IdlError(here(),
                   what + (t.kind == Token::Kind::end ? " (at the end of the file)" : " (at '" + t.text + "')"));
  }
  bool accept(const std::string& p) {
    if (peek().kind != Token::Kind::string && peek().text == p) {
      ++pos_;
      return true;
    }
    return false;
  }
  void expect(const std::string& p) {
    if (!accept(p)) fail("expected '" + p + "'");
  }
  std::string ident() {
    if (peek().kind != Token::Kind::ident) fail("expected a name");
    return next().text;
  }

  std::vector<Annotation> annotations() {
    std::vector<Annotation> out;
    while (accept("@")) {
      Annotation a;
      a.line = peek().line;
      a.name = ident();
      while (accept("::")) a.name += "::" + ident();
      if (accept("(")) {
        while (!accept(")")) {
          std::string key = "value";
          if (peek().kind == Token::Kind::ident && peek(1).text == "=") {
            key = next().text;
            next();
          }
          std::string value;
          if (accept("-")) value = "-";
          if (peek().kind == Token::Kind::end) fail("unterminated annotation");
          value += next().text;
          a.params[key] = value;
          if (!accept(",") && peek().text != ")") fail("expected ',' or ')' in @" + a.name);
        }
      }
      out.push_back(std::move(a));
    }
    return out;
  }

  void definition() {
    const int start_line = peek().line;
    auto ann = annotations();
    if (accept(";")) return;
    if (peek().text == "module") {
      if (!ann.empty()) fail("annotations on a module are not supported");
      next();
      scope_.push_back(ident());
      expect("{");
      while (!accept("}")) {
        if (peek().kind == Token::Kind::end) fail("module '" + scope_.back() + "' is not closed");
        definition();
      }
      expect(";");
      scope_.pop_back();
    } else if (peek().text == "struct") {
      structure(std::move(ann), start_line);
    } else if (peek().text == "enum") {
      enumeration();
    } else if (peek().text == "const") {
      constant();
    } else if (peek().text == "typedef" || peek().text == "union" || peek().text == "bitmask" ||
               peek().text == "bitset" || peek().text == "interface") {
      fail("'" + peek().text + "' is not supported in plexus messages (docs/sdk.md)");
    } else {
      fail("expected module, struct, enum or const");
    }
  }

  // The scoped name `name` stands for, seen from the current scope (innermost first).
  std::string resolve(const std::string& name, bool absolute, Location where) const {
    if (absolute) {
      if (model_.find_struct(name) || model_.find_enum(name) || model_.find_constant(name) || declared(name))
        return name;
      throw IdlError(where, "unknown type '::" + name + "'");
    }
    for (std::size_t n = scope_.size() + 1; n-- > 0;) {
      std::string s;
      for (std::size_t k = 0; k < n; ++k) s += scope_[k] + "::";
      s += name;
      if (model_.find_struct(s) || model_.find_enum(s) || model_.find_constant(s) || declared(s)) return s;
    }
    throw IdlError(where, "unknown name '" + name + "' (is its file included?)");
  }
  bool declared(const std::string& scoped) const {
    for (const auto& s : file_.structs)
      if (s.scoped() == scoped) return true;
    for (const auto& e : file_.enums)
      if (e.scoped() == scoped) return true;
    for (const auto& c : file_.constants) {
      std::string s;
      for (const auto& m : c.scope) s += m + "::";
      if (s + c.name == scoped) return true;
    }
    return false;
  }

  uint64_t const_expr() {
    const Location where = here();
    if (peek().kind == Token::Kind::number) {
      const std::string t = next().text;
      char* end = nullptr;
      const unsigned long long v = std::strtoull(t.c_str(), &end, 0);
      if (*end != '\0') throw IdlError(where, "'" + t + "' is not a whole number");
      return v;
    }
    const bool absolute = accept("::");
    std::string name = ident();
    while (accept("::")) name += "::" + ident();
    const std::string scoped = resolve(name, absolute, where);
    const Constant* c = model_.find_constant(scoped);
    if (!c)
      for (const auto& k : file_.constants) {
        std::string s;
        for (const auto& m : k.scope) s += m + "::";
        if (s + k.name == scoped) c = &k;
      }
    if (!c) throw IdlError(where, "'" + name + "' is not a constant");
    return std::strtoull(c->value.c_str(), nullptr, 0);
  }

  TypeRef type_spec() {
    TypeRef t;
    const Location where = here();
    const std::string w = peek().text;
    auto prim = [&](Primitive p) {
      t.kind = TypeRef::Kind::primitive;
      t.primitive = p;
    };
    if (accept("unsigned")) {
      if (accept("short"))
        prim(Primitive::u16);
      else if (accept("long"))
        prim(accept("long") ? Primitive::u64 : Primitive::u32);
      else
        fail("expected 'short' or 'long' after 'unsigned'");
    } else if (accept("long")) {
      if (accept("double")) throw IdlError(where, "'long double' has no portable CDR form; use double");
      prim(accept("long") ? Primitive::i64 : Primitive::i32);
    } else if (accept("short"))
      prim(Primitive::i16);
    else if (accept("double"))
      prim(Primitive::f64);
    else if (accept("float"))
      prim(Primitive::f32);
    else if (accept("boolean"))
      prim(Primitive::boolean);
    else if (accept("octet") || accept("uint8"))
      prim(Primitive::u8);
    else if (accept("int8"))
      prim(Primitive::i8);
    else if (accept("char"))
      prim(Primitive::char_);
    else if (accept("int16"))
      prim(Primitive::i16);
    else if (accept("uint16"))
      prim(Primitive::u16);
    else if (accept("int32"))
      prim(Primitive::i32);
    else if (accept("uint32"))
      prim(Primitive::u32);
    else if (accept("int64"))
      prim(Primitive::i64);
    else if (accept("uint64"))
      prim(Primitive::u64);
    else if (w == "wchar" || w == "wstring" || w == "any" || w == "map" || w == "fixed")
      throw IdlError(where, "'" + w + "' is not supported in plexus messages (docs/sdk.md)");
    else if (accept("string")) {
      t.kind = TypeRef::Kind::string;
      if (accept("<")) {
        t.bound = const_expr();
        expect(">");
      }
    } else if (accept("sequence")) {
      t.kind = TypeRef::Kind::sequence;
      expect("<");
      t.element.push_back(type_spec());
      if (accept(",")) t.bound = const_expr();
      expect(">");
    } else {
      const bool absolute = accept("::");
      std::string name = ident();
      while (accept("::")) name += "::" + ident();
      t.kind = TypeRef::Kind::named;
      t.name = resolve(name, absolute, where);
      if (!model_.find_struct(t.name) && !model_.find_enum(t.name) && !declared_type(t.name))
        throw IdlError(where, "'" + name + "' is not a type");
    }
    return t;
  }
  bool declared_type(const std::string& scoped) const {
    for (const auto& s : file_.structs)
      if (s.scoped() == scoped) return true;
    for (const auto& e : file_.enums)
      if (e.scoped() == scoped) return true;
    return false;
  }

  // The comment block directly above `line` (comment-only lines, no blank line between).
  std::string doc_above(int line) const {
    std::vector<std::string> lines;
    for (auto it = lx_.comments.rbegin(); it != lx_.comments.rend(); ++it) {
      if (it->line >= line) continue;
      if (it->line != line - 1 - static_cast<int>(lines.size()) || !it->alone || continued_.count(it->line)) break;
      lines.push_back(it->text);
    }
    std::string out;
    for (auto it = lines.rbegin(); it != lines.rend(); ++it) out += (out.empty() ? "" : " ") + *it;
    return out;
  }

  // The trailing comment of the line `line` ends on, with the comment-only lines right below it
  // that start in the same column (a continued comment).
  std::string trailing(int line) {
    std::string out;
    int col = -1, expect_line = line;
    for (const auto& c : lx_.comments) {
      if (c.line < expect_line) continue;
      if (c.line == line && !c.alone) {
        out = c.text;
        col = c.column;
        expect_line = line + 1;
      } else if (col >= 0 && c.line == expect_line && c.alone && c.column == col) {
        out += " " + c.text;
        continued_.insert(c.line);
        ++expect_line;
      } else {
        break;
      }
    }
    return out;
  }

  // Takes the [fields: ...] and [count] tags out of `doc`.
  static void tags(std::string& doc, Member& m, const Location& where) {
    for (;;) {
      const auto b = doc.find('[');
      if (b == std::string::npos) break;
      const auto e = doc.find(']', b);
      if (e == std::string::npos) break;
      const std::string tag = doc.substr(b + 1, e - b - 1);
      if (tag == "count") {
        m.count = true;
      } else if (tag.rfind("fields:", 0) == 0) {
        std::string list = tag.substr(7);
        std::stringstream elems(list);
        std::string elem;
        while (std::getline(elems, elem, ',')) {
          FieldNames names;
          std::stringstream alts(elem);
          std::string name;
          while (std::getline(alts, name, '|')) {
            name.erase(0, name.find_first_not_of(' '));
            name.erase(name.find_last_not_of(' ') + 1);
            if (name.empty()) throw IdlError(where, "empty name in [fields: " + list + "]");
            names.push_back(name);
          }
          m.fields.push_back(std::move(names));
        }
      } else {
        break;  // brackets that are not a tag stay in the text
      }
      doc.erase(b, e - b + 1);
    }
    while (doc.find("  ") != std::string::npos) doc.replace(doc.find("  "), 2, " ");
    while (!doc.empty() && doc.back() == ' ') doc.pop_back();
    while (!doc.empty() && doc.front() == ' ') doc.erase(0, 1);
  }

  static double number(const Annotation& a, const std::string& key, const Location& where) {
    const auto it = a.params.find(key);
    if (it == a.params.end()) throw IdlError(where, "@" + a.name + " needs " + key + "=");
    char* end = nullptr;
    const double v = std::strtod(it->second.c_str(), &end);
    if (end == it->second.c_str() || *end != '\0')
      throw IdlError(where, "@" + a.name + "(" + key + "=" + it->second + "): not a number");
    return v;
  }

  void structure(std::vector<Annotation> ann, int start_line) {
    Struct s;
    s.where = here();
    next();  // struct
    s.scope = scope_;
    s.name = ident();
    s.doc = doc_above(start_line);
    for (const auto& a : ann) {
      if (a.name == "final" || a.name == "appendable" || a.name == "mutable")
        s.extensibility = a.name;
      else if (a.name == "extensibility")
        s.extensibility = a.params.count("value") ? a.params.at("value") : "";
      else if (a.name == "nested")
        s.nested = a.params.count("value") == 0 || a.params.at("value") != "FALSE";
      else if (a.name != "topic")
        throw IdlError({file_.path, a.line}, "@" + a.name + " is not supported on a struct");
    }
    if (accept(";")) throw IdlError(s.where, "forward declarations are not supported");
    if (accept(":")) throw IdlError(s.where, "struct inheritance is not supported in plexus messages");
    expect("{");
    file_.structs.push_back(s);  // declared from here on: a member may not name it, but lookups see it
    while (!accept("}")) {
      if (peek().kind == Token::Kind::end) fail("struct '" + s.name + "' is not closed");
      const int member_line = peek().line;
      auto mann = annotations();
      Member proto;
      const std::size_t first = s.members.size();
      proto.type = type_spec();
      for (const auto& a : mann) {
        const Location where{file_.path, a.line};
        if (a.name == "unit") {
          if (!a.params.count("value")) throw IdlError(where, "@unit needs a string: @unit(\"m\")");
          proto.unit = a.params.at("value");
        } else if (a.name == "range") {
          proto.range_min = number(a, "min", where);
          proto.range_max = number(a, "max", where);
          for (const char* k : {"min", "max"})
            if (a.params.at(k).find_first_of(".eE") != std::string::npos) proto.range_integral = false;
        } else if (a.name == "key") {
          proto.key = true;
        } else if (a.name == "optional") {
          proto.optional = true;
        } else {
          throw IdlError(where, "@" + a.name + " is not supported on a member (plexus knows @unit, @range)");
        }
      }
      do {
        Member m = proto;
        m.where = here();
        m.name = ident();
        while (accept("[")) {
          m.dims.push_back(const_expr());
          expect("]");
        }
        s.members.push_back(std::move(m));
      } while (accept(","));
      const int end_line = peek().line;
      expect(";");
      std::string doc = doc_above(member_line);
      const std::string tail = trailing(end_line);
      if (!tail.empty()) doc += (doc.empty() ? "" : " ") + tail;
      for (std::size_t k = first; k < s.members.size(); ++k) {
        s.members[k].doc = doc;
        tags(s.members[k].doc, s.members[k], s.members[k].where);
      }
    }
    expect(";");
    file_.structs.back() = std::move(s);
  }

  void enumeration() {
    Enum e;
    e.where = here();
    next();
    e.scope = scope_;
    e.name = ident();
    expect("{");
    do {
      annotations();
      e.enumerators.push_back(ident());
    } while (accept(","));
    expect("}");
    expect(";");
    file_.enums.push_back(std::move(e));
  }

  void constant() {
    Constant c;
    c.where = here();
    next();
    c.scope = scope_;
    c.type = type_spec();
    c.name = ident();
    expect("=");
    if (accept("-")) c.value = "-";
    if (peek().kind == Token::Kind::end) fail("expected a value");
    c.value += next().text;
    expect(";");
    file_.constants.push_back(std::move(c));
  }

  Lexed lx_;
  std::size_t pos_ = 0;
  File& file_;
  const Model& model_;
  std::vector<std::string> scope_;
  std::set<int> continued_;  // comment lines that continue a member's trailing comment
};

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot be read");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

struct Reader {
  const std::vector<std::string>& dirs;
  Model model;
  std::vector<std::string> in_progress;

  std::string find(const std::string& include_name, const Location& from) const {
    for (const auto& d : dirs) {
      const fs::path p = fs::path(d) / include_name;
      if (fs::exists(p)) return p.string();
    }
    throw IdlError(from, "included file '" + include_name + "' not found in the include directories");
  }

  void read(const std::string& path, const std::string& include_name, bool own) {
    for (auto& f : model.files)
      if (f.include_name == include_name) {
        f.own = f.own || own;
        return;
      }
    if (std::find(in_progress.begin(), in_progress.end(), include_name) != in_progress.end())
      throw IdlError({path, 1}, "include cycle through '" + include_name + "'");
    in_progress.push_back(include_name);
    File f;
    f.path = path;
    f.include_name = include_name;
    f.base = fs::path(path).stem().string();
    f.text = read_text(path);
    f.own = own;
    Lexed lx = lex(f.text, path);
    for (const auto& [line, name] : lx.includes) {
      f.includes.push_back(name);
      read(find(name, {path, line}), name, false);
    }
    Parser(std::move(lx), f, model).parse();
    in_progress.pop_back();
    model.files.push_back(std::move(f));
  }
};

// The name `path` is included by: relative to the include directory that holds it.
std::string include_name_of(const std::string& path, const std::vector<std::string>& dirs) {
  const fs::path abs = fs::weakly_canonical(path);
  for (const auto& d : dirs) {
    const fs::path dir = fs::weakly_canonical(d);
    const auto rel = abs.lexically_relative(dir);
    if (!rel.empty() && *rel.begin() != "..") return rel.generic_string();
  }
  throw std::runtime_error(path + ": not under any include directory (-I)");
}

}  // namespace

Model parse_files(const std::vector<std::string>& files, const std::vector<std::string>& include_dirs) {
  Reader r{include_dirs, {}, {}};
  for (const auto& f : files) r.read(f, include_name_of(f, include_dirs), true);
  return std::move(r.model);
}

}  // namespace plexus::idlgen
