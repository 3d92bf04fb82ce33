#include "plexus/algorithms/arm/arm_model.hpp"

#include <cmath>
#include <string>

#include "plexus/algorithms/core/validation.hpp"

namespace plexus::algorithms {
namespace {
constexpr const char* kWhereArmModel = "arm_model";

std::string indexed(const char* group, std::size_t i, const char* name) {
  return std::string(group) + "[" + std::to_string(i) + "]." + name;
}
}  // namespace

void ArmModel::validate() const {
  if (links.empty()) validation::fail(kWhereArmModel, "links", "a list of at least one link", 0.0);
  if (joints.size() != links.size()) {
    validation::fail(kWhereArmModel, "joints", "as many as links (" + std::to_string(links.size()) + ")",
                     static_cast<double>(joints.size()));
  }
  for (std::size_t i = 0; i < links.size(); ++i) {
    const ArmLink& l = links[i];
    validation::require_non_negative(kWhereArmModel, indexed("links", i, "length"), l.length);
    validation::require_finite(kWhereArmModel, indexed("links", i, "com"), l.com);
    validation::require_positive(kWhereArmModel, indexed("links", i, "mass"), l.mass);
    validation::require_finite(kWhereArmModel, indexed("links", i, "twist"), l.twist);
    if (!(std::isfinite(l.inertia_o) && l.inertia_zz_com() > 0.0)) {
      validation::fail(kWhereArmModel, indexed("links", i, "inertia_o"),
                       "finite and > mass * com^2 = " + validation::format_value(l.mass * l.com * l.com), l.inertia_o);
    }
    if (!std::isfinite(l.inertia_xx))
      validation::fail(kWhereArmModel, indexed("links", i, "inertia_xx"), "finite", l.inertia_xx);
    if (!std::isfinite(l.inertia_yy))
      validation::fail(kWhereArmModel, indexed("links", i, "inertia_yy"), "finite", l.inertia_yy);
    const double a = l.inertia_xx_com(), b = l.inertia_yy_com(), c = l.inertia_zz_com();
    if (a + b < c || a + c < b || b + c < a) {
      validation::fail(kWhereArmModel, indexed("links", i, "inertia_xx"),
                       "such that the central inertias satisfy the triangle inequality", a);
    }
  }
  for (std::size_t i = 0; i < joints.size(); ++i) {
    validation::require_positive(kWhereArmModel, indexed("joints", i, "motor_inertia"), joints[i].motor_inertia);
    validation::require_non_negative(kWhereArmModel, indexed("joints", i, "friction"), joints[i].friction);
    validation::require_positive(kWhereArmModel, indexed("joints", i, "stiffness"), joints[i].stiffness);
  }
  for (int k = 0; k < 3; ++k) validation::require_finite(kWhereArmModel, "gravity", gravity(k));
  validation::require_non_negative(kWhereArmModel, "payload_mass", payload_mass);
}

ArmModel ArmModel::paper_2dof() {
  ArmModel m;
  m.links = {ArmLink{0.5, 0.25, 10.0, 1.0}, ArmLink{0.5, 0.25, 4.0, 0.4}};
  m.joints = {ArmJoint{2.0, 1.0, 1e4}, ArmJoint{0.5, 0.5, 1e4}};
  return m;
}

spatial::Transform ArmModel::fixed_link_frame(int i) const {
  const ArmLink* prev = i == 0 ? nullptr : &links[static_cast<std::size_t>(i - 1)];
  const double twist = prev ? prev->twist : 0.0;
  const double ct = std::cos(twist), st = std::sin(twist);
  spatial::Transform t;
  t.rotation << 1.0, 0.0, 0.0, 0.0, ct, -st, 0.0, st, ct;
  t.origin = Eigen::Vector3d(prev ? prev->length : 0.0, 0.0, 0.0);
  return t;
}

ArmModel ArmModel::uniform_chain(int n) {
  ArmModel m;
  m.links.assign(static_cast<std::size_t>(n), ArmLink{0.5, 0.25, 4.0, 0.4});
  m.joints.assign(static_cast<std::size_t>(n), ArmJoint{0.5, 0.5, 1e4});
  return m;
}

}  // namespace plexus::algorithms
