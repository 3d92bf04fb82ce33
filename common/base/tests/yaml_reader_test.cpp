#include "plexus/base/yaml_reader.hpp"

#include <gtest/gtest.h>

#include <string>

namespace plexus {
namespace {

std::string error_of(auto&& fn) {
  try {
    fn();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(YamlReader, ReadsTypedValues) {
  YamlMap m(load_yaml_string("a: 3\nb: 2.5\nc: hello\nd: true\n", "t.yaml"), "t.yaml");
  EXPECT_EQ(m.required<int>("a"), 3);
  EXPECT_DOUBLE_EQ(m.required<double>("b"), 2.5);
  EXPECT_EQ(m.required<std::string>("c"), "hello");
  EXPECT_TRUE(m.required<bool>("d"));
  EXPECT_EQ(m.optional<int>("e", 7), 7);
  EXPECT_NO_THROW(m.reject_unknown());
}

TEST(YamlReader, UnknownKeyNamesFileLineAndKey) {
  YamlMap m(load_yaml_string("a: 1\nsub:\n  x: 1\n  typo: 2\n", "t.yaml"), "t.yaml");
  m.required<int>("a");
  YamlMap sub = m.map("sub");
  sub.required<int>("x");
  EXPECT_EQ(error_of([&] { sub.reject_unknown(); }), "t.yaml:4: sub.typo: unknown key");
}

TEST(YamlReader, WrongTypeNamesValue) {
  YamlMap m(load_yaml_string("a: abc\nb: 1.5\nc: [1]\n", "t.yaml"), "t.yaml");
  EXPECT_EQ(error_of([&] { m.required<double>("a"); }), "t.yaml:1: a: expected a finite number, got 'abc'");
  EXPECT_EQ(error_of([&] { m.required<int>("b"); }), "t.yaml:2: b: expected an integer, got '1.5'");
  EXPECT_EQ(error_of([&] { m.required<std::string>("c"); }), "t.yaml:3: c: expected a string, got a list");
  EXPECT_EQ(error_of([&] { m.required<unsigned>("zz"); }), "t.yaml:1: zz: required key is missing");
}

TEST(YamlReader, RejectsNonFiniteAndOutOfRange) {
  YamlMap m(load_yaml_string("a: .nan\nb: -1\nc: 99999999999\n", "t.yaml"), "t.yaml");
  EXPECT_NE(error_of([&] { m.required<double>("a"); }).find("finite"), std::string::npos);
  EXPECT_NE(error_of([&] { m.required<unsigned>("b"); }).find("out of range"), std::string::npos);
  EXPECT_NE(error_of([&] { m.required<int>("c"); }).find("out of range"), std::string::npos);
}

TEST(YamlReader, SyntaxErrorAndMissingFile) {
  EXPECT_EQ(error_of([] { load_yaml_file("/nonexistent/q.yaml"); }), "/nonexistent/q.yaml: cannot open file");
  EXPECT_NE(error_of([] { load_yaml_string("a: [1, 2\n", "bad.yaml"); }).find("bad.yaml:"), std::string::npos);
  EXPECT_NE(error_of([] { YamlMap(load_yaml_string("- 1\n- 2", "l.yaml"), "l.yaml"); }).find("expected a mapping"),
            std::string::npos);
}

// Found by fuzzing (tests/fuzz, qos_file): yaml-cpp quotes the character a syntax error is
// about, a newline or a NUL included, and a quoted key may hold a newline; the refusal must
// still be one line.
TEST(YamlReader, ErrorsStayOnOneLine) {
  const std::string syntax = error_of([] { load_yaml_string(std::string("profiles: {\x01\0\n  \n", 17), "q.yaml"); });
  EXPECT_EQ(syntax.rfind("q.yaml:2: YAML syntax error: ", 0), 0u) << syntax;
  EXPECT_EQ(syntax.find('\n'), std::string::npos) << syntax;
  EXPECT_EQ(syntax.find('\0'), std::string::npos) << syntax;
  YamlMap m(load_yaml_string("\"a\\nb\": 1\n", "t.yaml"), "t.yaml");
  EXPECT_EQ(error_of([&] { m.reject_unknown(); }), "t.yaml:1: a\\nb: unknown key");
}

// Found by fuzzing (qos_file): a key that is a mapping or a list made yaml-cpp throw its own
// exception out of keys() and reject_unknown().
TEST(YamlReader, KeyThatIsNotANameIsRefused) {
  YamlMap m(load_yaml_string("a: 1\n? [x, y]\n: 2\n", "t.yaml"), "t.yaml");
  EXPECT_EQ(error_of([&] { m.keys(); }), "t.yaml:2: document: a key must be a name, got a list");
  YamlMap sub(load_yaml_string("p:\n  ? {q: 1}\n  : 2\n", "t.yaml"), "t.yaml");
  EXPECT_EQ(error_of([&] { sub.map("p").reject_unknown(); }), "t.yaml:2: p: a key must be a name, got a mapping");
}

// yaml-cpp builds an alias as the anchored node itself: an alias inside it was a cycle that
// overflowed the stack of the duplicate-key check, and aliases of aliases an exponential walk
// (a 9-line file took minutes). Both are refused before the tree is built.
TEST(YamlReader, AliasCycleAndAliasBombAreRefused) {
  EXPECT_EQ(error_of([] { load_yaml_string("name: x\nrobots: &a [*a]\n", "c.yaml"); }),
            "c.yaml:2: an alias inside the node its anchor names (a cycle)");
  EXPECT_EQ(error_of([] { load_yaml_string("a: &a {b: {c: *a}}\n", "c.yaml"); }),
            "c.yaml:1: an alias inside the node its anchor names (a cycle)");
  std::string bomb = "a: &l0 [1, 1, 1, 1, 1, 1, 1, 1, 1, 1]\n";
  for (int i = 1; i <= 8; ++i) {
    bomb += "l" + std::to_string(i) + ": &l" + std::to_string(i) + " [";
    for (int k = 0; k < 10; ++k) bomb += std::string(k ? ", " : "") + "*l" + std::to_string(i - 1);
    bomb += "]\n";
  }
  // Repeated nodes: l1 110, l2 1110, l3 11110, l4 111110: beyond 100000 on line 5 (l4).
  EXPECT_EQ(error_of([&] { load_yaml_string(bomb, "b.yaml"); }),
            "b.yaml:5: aliases repeat more than 100000 nodes in all");
  // Anchors used as a user would: accepted, and the aliases read as the anchored values.
  const YAML::Node ok = load_yaml_string("common: &c {rate: 10, noise: 0.1}\ngps1: *c\ngps2: *c\n", "ok.yaml");
  EXPECT_EQ(ok["gps2"]["rate"].as<int>(), 10);
}

}  // namespace
}  // namespace plexus
