// TypeSupport::schema (plexus_idlgen): every message type has a self-contained IDL text
// declaring it, the `omgidl` schema of its MCAP channels.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "plexus/msg/messages.hpp"

namespace plexus::mcap {
namespace {

TEST(OmgidlSchema, EveryTypeHasSelfContainedIdlDeclaringIt) {
  // Names a type, so that the linker keeps plexus_msgs (whose load registers every type).
  ASSERT_EQ(msg::find_type_support("plexus::msg::Pose2D"), &msg::type_support<msg::Pose2D>());
  for (const msg::TypeSupport* ts : msg::all_type_supports()) {
    ASSERT_NE(ts->schema, nullptr) << ts->type_name;
    const std::string text = ts->schema;
    const std::string name = ts->type_name;
    const std::string shortname = name.substr(name.rfind("::") + 2);
    EXPECT_NE(text.find("struct " + shortname + " {"), std::string::npos) << name;
    EXPECT_NE(text.find("struct StampHeader {"), std::string::npos) << name << ": the header it uses";
    EXPECT_EQ(text.find("#include"), std::string::npos) << name;
    EXPECT_EQ(text.find("#ifndef"), std::string::npos) << name;
    EXPECT_EQ(std::count(text.begin(), text.end(), '{'), std::count(text.begin(), text.end(), '}')) << name;
    EXPECT_EQ(text.find("struct StampHeader {"), text.rfind("struct StampHeader {")) << name << ": declared once";
  }
}

}  // namespace
}  // namespace plexus::mcap
