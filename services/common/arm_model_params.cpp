#include "services/common/arm_model_params.hpp"

#include "plexus/scenario/params.hpp"
#include "services/common/arm_fields.hpp"

namespace plexus::scenario {

Eigen::VectorXd number_list(const YamlMap& p, const std::string& key, int n, const Eigen::VectorXd& fallback) {
  if (!p.has(key)) return fallback;
  const auto items = p.sequence(key);
  if (static_cast<int>(items.size()) != n) p.fail(key, "needs " + std::to_string(n) + " numbers (one per joint)");
  Eigen::VectorXd v(n);
  for (int i = 0; i < n; ++i)
    v(i) = number(p, items[static_cast<std::size_t>(i)], key);  // finite, or an error naming it
  return v;
}

void read_into(const YamlMap& p, const std::string& key, Eigen::VectorXd& v) {
  v = number_list(p, key, static_cast<int>(v.size()), v);
}

algorithms::ArmModel read_model(const YamlMap& p) {
  namespace alg = plexus::algorithms;
  const std::string preset = p.optional<std::string>("model", "paper_2dof");
  alg::ArmModel m;
  if (preset == "paper_2dof") {
    m = alg::ArmModel::paper_2dof();
  } else if (preset == "uniform") {
    const int n = p.optional<int>("dof", 2);
    if (n < 1 || n > kMaxScenarioDof) p.fail("dof", "must be in 1.." + std::to_string(kMaxScenarioDof));
    m = alg::ArmModel::uniform_chain(n);
  } else {
    p.fail("model", "must be paper_2dof or uniform");
  }
  if (preset == "paper_2dof" && p.has("dof") && p.optional<int>("dof", 2) != 2)
    p.fail("dof", "is 2 for model paper_2dof");
  const int n = m.dof();
  auto apply = [&](const std::string& key, auto member, auto& items) {
    Eigen::VectorXd current(n);
    for (int i = 0; i < n; ++i) current(i) = items[static_cast<std::size_t>(i)].*member;
    const Eigen::VectorXd v = number_list(p, key, n, current);
    for (int i = 0; i < n; ++i) items[static_cast<std::size_t>(i)].*member = v(i);
  };
  apply("length", &alg::ArmLink::length, m.links);
  apply("com", &alg::ArmLink::com, m.links);
  apply("mass", &alg::ArmLink::mass, m.links);
  apply("inertia_o", &alg::ArmLink::inertia_o, m.links);
  apply("twist", &alg::ArmLink::twist, m.links);
  apply("motor_inertia", &alg::ArmJoint::motor_inertia, m.joints);
  apply("friction", &alg::ArmJoint::friction, m.joints);
  apply("stiffness", &alg::ArmJoint::stiffness, m.joints);
  m.gravity = number_list(p, "gravity", 3, m.gravity);
  m.payload_mass = p.optional<double>("payload_mass", 0.0);
  m.validate();
  return m;
}

}  // namespace plexus::scenario
