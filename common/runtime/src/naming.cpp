#include "plexus/runtime/naming.hpp"

#include <string>

#include "plexus/base/input_error.hpp"
#include "plexus/msg/registry.hpp"

namespace plexus::rt {
namespace {

std::string ros2_type(const msg::TypeSupport& type) {
  const std::string_view scoped = type.type_name;
  const auto p = scoped.rfind("::");
  const std::string_view name = p == std::string_view::npos ? scoped : scoped.substr(p + 2);
  std::string package = msg::package_of(scoped);
  if (package.empty()) package = "plexus_msgs";  // a type not registered (a test's): plexus's own
  return package + "::msg::dds_::" + std::string(name) + "_";
}

}  // namespace

Naming parse_naming(std::string_view name, std::string_view origin) {
  if (name == "plexus") return Naming::plexus;
  if (name == "ros2") return Naming::ros2;
  throw InputError(std::string(origin) + ": unknown naming '" + std::string(name) + "' (expected plexus or ros2)");
}

const char* to_string(Naming n) { return n == Naming::ros2 ? "ros2" : "plexus"; }

DdsNames dds_names(Naming naming, const msg::TypeSupport& type, std::string_view topic) {
  if (naming == Naming::plexus) return {std::string(topic), type.type_name};
  return {std::string(kRos2TopicPrefix) + std::string(topic), ros2_type(type)};
}

std::string plexus_topic(Naming naming, std::string_view dds_topic) {
  if (naming == Naming::ros2 && dds_topic.substr(0, kRos2TopicPrefix.size()) == kRos2TopicPrefix)
    return std::string(dds_topic.substr(kRos2TopicPrefix.size()));
  return std::string(dds_topic);
}

std::string plexus_type(Naming naming, std::string_view dds_type) {
  if (naming == Naming::ros2)
    for (const msg::TypeSupport* ts : msg::all_type_supports())
      if (ros2_type(*ts) == dds_type) return ts->type_name;
  return std::string(dds_type);
}

}  // namespace plexus::rt
