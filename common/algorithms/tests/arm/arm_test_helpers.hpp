// Shared fixtures of the arm tests: models and random states (plus the family-independent
// validation-message helper of the unicycle tests).
#pragma once

#include <Eigen/Core>

#include "../support/validation_message.hpp"  // invalid_argument_message<T>(args...)
#include "plexus/algorithms/arm/arm_model.hpp"
#include "plexus/algorithms/core/random.hpp"

namespace plexus::algorithms::testing {

/// A spatial (twisted) n-link chain with gravity in an arbitrary direction.
inline ArmModel twisted_chain(int n) {
  ArmModel m = ArmModel::uniform_chain(n);
  for (int i = 0; i < n; ++i) {
    m.links[static_cast<std::size_t>(i)].twist = 0.3 * (i % 3) - 0.4;
    m.links[static_cast<std::size_t>(i)].inertia_xx = 0.05;
  }
  m.gravity = Eigen::Vector3d(1.0, -3.0, 9.0);
  return m;
}

inline Eigen::VectorXd random_vector(Rng& rng, int n, double scale) {
  Eigen::VectorXd v(n);
  for (int i = 0; i < n; ++i) v(i) = rng.uniform(-scale, scale);
  return v;
}

}  // namespace plexus::algorithms::testing
