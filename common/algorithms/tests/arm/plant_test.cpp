// The flexible-joint plant and its KDL rigid-body dynamics (paper 004, eqs. (16)-(17), (24)).
#include <gtest/gtest.h>

#include <cmath>

#include "arm_test_helpers.hpp"
#include "plexus/algorithms/arm/flexible_joint_plant.hpp"
#include "plexus/algorithms/arm/rigid_body_dynamics.hpp"

namespace plexus::algorithms {
namespace {

using testing::random_vector;

TEST(RigidBodyDynamics, KdlMatchesTheClosedFormTwoLinkPlanarArm) {
  ArmRigidBodyDynamics dyn(ArmModel::paper_2dof());
  Rng rng(4);
  const double m2 = 4.0, l1 = 0.5, d2 = 0.25, i1 = 1.0, i2 = 0.4, g = 9.81, m1 = 10.0, d1 = 0.25;
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::VectorXd q = random_vector(rng, 2, 3.0), qd = random_vector(rng, 2, 2.0);
    Eigen::MatrixXd m(2, 2);
    dyn.mass_matrix(q, m);
    const double c2 = std::cos(q(1)), s2 = std::sin(q(1));
    EXPECT_NEAR(m(0, 0), i1 + i2 + m2 * l1 * l1 + 2 * m2 * l1 * d2 * c2, 1e-12);
    EXPECT_NEAR(m(0, 1), i2 + m2 * l1 * d2 * c2, 1e-12);
    EXPECT_NEAR(m(1, 1), i2, 1e-12);
    // h = C q' + G; gravity along +x of the base (q = 0 hangs down).
    Eigen::VectorXd h(2);
    dyn.bias(q, qd, h);
    const double hc = m2 * l1 * d2 * s2;
    const double g1 = (m1 * d1 + m2 * l1) * g * std::sin(q(0)) + m2 * d2 * g * std::sin(q(0) + q(1));
    const double g2 = m2 * d2 * g * std::sin(q(0) + q(1));
    EXPECT_NEAR(h(0), -hc * (2 * qd(0) * qd(1) + qd(1) * qd(1)) + g1, 1e-10);
    EXPECT_NEAR(h(1), hc * qd(0) * qd(0) + g2, 1e-10);
  }
}

TEST(RigidBodyDynamics, ForwardDynamicsInvertsInverseDynamics) {
  for (const ArmModel& model : {ArmModel::paper_2dof(), testing::twisted_chain(5)}) {
    ArmRigidBodyDynamics dyn(model);
    const int n = dyn.dof();
    Rng rng(5);
    const Eigen::VectorXd q = random_vector(rng, n, 3), qd = random_vector(rng, n, 2), qdd = random_vector(rng, n, 5);
    Eigen::VectorXd tau(n), back(n);
    dyn.inverse_dynamics(q, qd, qdd, tau);
    dyn.forward_dynamics(q, qd, tau, back);
    EXPECT_TRUE(back.isApprox(qdd, 1e-10));
  }
}

TEST(FlexibleJointPlant, ConservesEnergyWithoutFrictionOrInput) {
  ArmModel model = ArmModel::paper_2dof();
  for (ArmJoint& j : model.joints) j.friction = 0.0;
  FlexibleJointArmPlant plant({model, 1e-4});
  Eigen::VectorXd q(2), zero = Eigen::VectorXd::Zero(2);
  q << 0.4, -0.3;
  plant.reset({q, zero, q + Eigen::VectorXd::Constant(2, 0.002), zero});  // springs loaded
  const double e0 = plant.energy();
  for (int k = 0; k < 2000; ++k) plant.step(zero, 1e-3);
  EXPECT_NEAR(plant.energy(), e0, 1e-6 * std::abs(e0) + 1e-6);
}

TEST(FlexibleJointPlant, FrictionDissipatesEnergy) {
  FlexibleJointArmPlant plant({});
  Eigen::VectorXd q(2), zero = Eigen::VectorXd::Zero(2);
  q << 0.4, -0.3;
  plant.reset({q, zero, q, zero});
  double previous = plant.energy();
  for (int k = 0; k < 50; ++k) {
    plant.step(zero, 1e-2);
    const double e = plant.energy();
    EXPECT_LE(e, previous + 1e-9);
    previous = e;
  }
}

TEST(FlexibleJointPlant, Rk4SubstepConvergesAtFourthOrder) {
  // Compare max_substep h and h/2 against h/8 under a sinusoidal torque; the error ratio
  // of a 4th-order method is ~16 per halving.
  auto run = [](double h) {
    FlexibleJointArmPlant plant({ArmModel::paper_2dof(), h});
    Eigen::VectorXd u(2);
    for (int k = 0; k < 200; ++k) {
      u << 30 * std::sin(6.0 * k * 1e-3), 8 * std::cos(5.0 * k * 1e-3);
      plant.step(u, 1e-3);
    }
    return plant.state().q;
  };
  const Eigen::VectorXd ref = run(1e-3 / 16), a = run(1e-3 / 2), b = run(1e-3 / 4);
  const double ea = (a - ref).norm(), eb = (b - ref).norm();
  EXPECT_GT(ea / eb, 10.0);
  // At the default 1e-4 s the error is far below the 1.15e-3 rad settling band.
  EXPECT_LT((run(1e-4) - ref).norm(), 1e-8);
}

TEST(FlexibleJointPlant, RestingStateIsAnEquilibriumUnderGravityTorque) {
  FlexibleJointArmPlant plant({});
  Eigen::VectorXd q(2), g(2), zero = Eigen::VectorXd::Zero(2);
  q << 0.3, 0.5;
  plant.reset_at_rest(q);
  plant.dynamics().bias(q, zero, g);
  for (int k = 0; k < 100; ++k) plant.step(g, 1e-3);  // motor torque = gravity torque
  EXPECT_LT((plant.state().q - q).norm(), 1e-9);
}

TEST(FlexibleJointPlant, InMotionStartHasNoLinkAccelerationAndNoSpringRate) {
  // reset_in_motion: the springs hold C(q, q') q' + G(q), so q'' = 0 and tau' = 0 at t = 0;
  // over a short step the link keeps its velocity (to second order in dt).
  FlexibleJointArmPlant plant({});
  Eigen::VectorXd q(2), qd(2), tau(2), qdd(2);
  q << 0.3, -0.5;
  qd << 1.0, -0.7;
  plant.reset_in_motion(q, qd);
  EXPECT_TRUE(plant.state().phid.isApprox(qd));
  plant.spring_torque(tau);
  plant.dynamics().forward_dynamics(q, qd, tau, qdd);
  EXPECT_LT(qdd.norm(), 1e-9);
  Eigen::VectorXd u(2);  // motor torque that keeps phi'' = 0: tau + F phi'
  for (int i = 0; i < 2; ++i)
    u(i) = tau(i) + plant.dynamics().model().joints[static_cast<std::size_t>(i)].friction * qd(i);
  const double dt = 1e-4;
  plant.step(u, dt);
  EXPECT_LT((plant.state().qd - qd).norm(), 1e-2 * dt);
  // Without velocity it is reset_at_rest.
  plant.reset_in_motion(q, Eigen::VectorXd::Zero(2));
  const FlexibleJointArmState moving = plant.state();
  plant.reset_at_rest(q);
  EXPECT_TRUE(plant.state().phi.isApprox(moving.phi));
}

}  // namespace
}  // namespace plexus::algorithms
