// The observer's rigid-body model (chain_dynamics.hpp) against KDL and against finite
// differences of itself.
#include <gtest/gtest.h>

#include "arm_test_helpers.hpp"
#include "plexus/algorithms/arm/chain_dynamics.hpp"
#include "plexus/algorithms/arm/rigid_body_dynamics.hpp"

namespace plexus::algorithms {
namespace {

using testing::random_vector;

ArmModel chain(int n) {
  ArmModel m = n == 2 ? ArmModel::paper_2dof() : testing::twisted_chain(n);
  m.payload_mass = 0.7;  // the payload is part of the rigid-body model
  return m;
}

class ChainDynamicsTest : public ::testing::TestWithParam<int> {};

TEST_P(ChainDynamicsTest, AgreesWithKdl) {
  const int n = GetParam();
  const ArmModel model = chain(n);
  ArmChainDynamics fast(model);
  ArmRigidBodyDynamics kdl(model);
  Rng rng(70 + n);
  for (int trial = 0; trial < 10; ++trial) {
    const Eigen::VectorXd q = random_vector(rng, n, 3), qd = random_vector(rng, n, 4), qdd = random_vector(rng, n, 20),
                          tau = random_vector(rng, n, 50);
    Eigen::MatrixXd m1(n, n), m2(n, n);
    fast.mass_matrix(q, m1);
    kdl.mass_matrix(q, m2);
    EXPECT_LT((m1 - m2).norm(), 1e-12 * (1.0 + m2.norm()));
    Eigen::VectorXd t1(n), t2(n);
    fast.inverse_dynamics(q, qd, qdd, t1);
    kdl.inverse_dynamics(q, qd, qdd, t2);
    EXPECT_LT((t1 - t2).norm(), 1e-11 * (1.0 + t2.norm()));
    fast.forward_dynamics(q, qd, tau, t1);
    kdl.forward_dynamics(q, qd, tau, t2);
    EXPECT_LT((t1 - t2).norm(), 1e-10 * (1.0 + t2.norm()));
  }
}

TEST_P(ChainDynamicsTest, TangentIsTheDerivativeOfTheInverseDynamics) {
  const int n = GetParam();
  ArmChainDynamics d(chain(n));
  Rng rng(80 + n);
  for (int trial = 0; trial < 10; ++trial) {
    const Eigen::VectorXd q = random_vector(rng, n, 3), qd = random_vector(rng, n, 4), tau = random_vector(rng, n, 50),
                          dq = random_vector(rng, n, 1), dqd = random_vector(rng, n, 1);
    Eigen::VectorXd qdd(n), dtau(n), plus(n), minus(n);
    d.forward_dynamics(q, qd, tau, qdd);
    d.tangent(dq, dqd, dtau);
    const double h = 1e-6;
    d.inverse_dynamics(q + h * dq, qd + h * dqd, qdd, plus);
    d.inverse_dynamics(q - h * dq, qd - h * dqd, qdd, minus);
    const Eigen::VectorXd fd = (plus - minus) / (2 * h);
    EXPECT_LT((dtau - fd).norm(), 1e-6 * (1.0 + fd.norm())) << "trial " << trial;
    // derivatives() is the same tangent along each unit direction.
    Eigen::MatrixXd a(n, n), b(n, n);
    d.forward_dynamics(q, qd, tau, qdd);
    d.derivatives(a, b);
    EXPECT_LT((a * dq + b * dqd - dtau).norm(), 1e-9 * (1.0 + dtau.norm()));
  }
}

INSTANTIATE_TEST_SUITE_P(Chains, ChainDynamicsTest, ::testing::Values(1, 2, 3, 7));

}  // namespace
}  // namespace plexus::algorithms
