// Every registered component type of the built-in services has its data-path test: the test
// files of services/<executable>/tests/ each name the types they cover (service_harness.hpp,
// Covers), and this checks the registry against those names, both ways.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "plexus/scenario/registry.hpp"
#include "service_harness.hpp"

namespace plexus::services_test {
namespace {

TEST(ServicesTests, CoverEveryRegisteredComponentType) {
  const auto& covered = covered_types();
  std::set<std::string> registered;
  for (const auto* t : scenario::component_types()) {
    registered.insert(t->name);
    EXPECT_TRUE(covered.count(t->name)) << t->name << " has no data-path test (no Covers names it)";
  }
  for (const auto& [type, file] : covered)
    EXPECT_TRUE(registered.count(type)) << type << " (named in " << file << ") is not registered";
}

}  // namespace
}  // namespace plexus::services_test
