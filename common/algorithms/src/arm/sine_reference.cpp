#include "plexus/algorithms/arm/sine_reference.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "plexus/algorithms/core/validation.hpp"

namespace plexus::algorithms {
namespace {
constexpr const char* kWhereArmSineReference = "arm_sine_reference";
}

ArmSineReferenceParams ArmSineReferenceParams::paper(int n) {
  const double a = 1.0 / (2.0 * std::numbers::pi);
  return {Eigen::VectorXd::Constant(n, a), Eigen::VectorXd::Constant(n, 1.0), Eigen::VectorXd::Constant(n, 0.088 * a),
          Eigen::VectorXd::Zero(n)};
}

ArmSineReference::ArmSineReference(const ArmSineReferenceParams& p) : params_(p) {
  const auto n = p.amplitude.size();
  if (n == 0) validation::fail(kWhereArmSineReference, "amplitude", "a non-empty list", 0.0);
  const std::pair<const char*, const Eigen::VectorXd*> all[] = {
      {"amplitude", &p.amplitude}, {"frequency_hz", &p.frequency_hz}, {"offset", &p.offset}, {"phase", &p.phase}};
  for (const auto& [name, v] : all) {
    if (v->size() != n) {
      validation::fail(kWhereArmSineReference, std::string(name) + " size", "the joint count " + std::to_string(n),
                       static_cast<double>(v->size()));
    }
    for (Eigen::Index i = 0; i < n; ++i) {
      validation::require_finite(kWhereArmSineReference, std::string(name) + "[" + std::to_string(i) + "]", (*v)(i));
    }
  }
  for (Eigen::Index i = 0; i < n; ++i) {
    validation::require_non_negative(kWhereArmSineReference, "frequency_hz[" + std::to_string(i) + "]",
                                     p.frequency_hz(i));
  }
}

void ArmSineReference::sample(double t, ArmReferenceSample& out) const {
  const int n = dof();
  if (out.q.size() != n || out.qddd.size() != n) {
    const Eigen::VectorXd z = Eigen::VectorXd::Zero(n);
    out = {z, z, z, z};
  }
  for (int i = 0; i < n; ++i) {
    const double w = 2.0 * std::numbers::pi * params_.frequency_hz(i);
    const double a = w * t + params_.phase(i);
    const double s = std::sin(a), c = std::cos(a);
    out.q(i) = params_.offset(i) + params_.amplitude(i) * s;  // eq. (59)
    out.qd(i) = params_.amplitude(i) * w * c;
    out.qdd(i) = -params_.amplitude(i) * w * w * s;
    out.qddd(i) = -params_.amplitude(i) * w * w * w * c;
  }
}

}  // namespace plexus::algorithms
