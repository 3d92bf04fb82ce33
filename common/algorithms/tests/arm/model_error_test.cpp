// Issue 18: the observer's model-error states (disturbance torque, tip mass), the plant's
// torque limit and the VDC's anti-windup (docs/algorithms/arm.md "Model error", "Torque limit").
#include <gtest/gtest.h>

#include "arm_test_helpers.hpp"
#include "plexus/algorithms/arm/flexible_joint_ekf.hpp"
#include "plexus/algorithms/arm/flexible_joint_plant.hpp"
#include "plexus/algorithms/arm/vdc_controller.hpp"

namespace plexus::algorithms {
namespace {

using testing::random_vector;

class AugmentedJacobianTest : public ::testing::TestWithParam<int> {};

TEST_P(AugmentedJacobianTest, JacobianWithModelErrorStatesAgreesWithFiniteDifferences) {
  const int n = GetParam();
  FlexibleJointEkfParams p = FlexibleJointEkfParams::robust();
  p.model = n == 2 ? ArmModel::paper_2dof() : testing::twisted_chain(n);
  FlexibleJointEkf ekf(p);
  const int m = ekf.state_size();
  ASSERT_EQ(m, 5 * n + 1);
  Rng rng(90 + n);
  for (int trial = 0; trial < 10; ++trial) {
    // [tau, tau', d, m_p, phi, phi']
    Eigen::VectorXd x(m);
    x << random_vector(rng, n, 30), random_vector(rng, n, 300), random_vector(rng, n, 10), rng.uniform(-1.0, 1.0),
        random_vector(rng, n, 2), random_vector(rng, n, 2);
    const Eigen::VectorXd u = random_vector(rng, n, 50);
    Eigen::MatrixXd f(m, m), fd(m, m);
    ekf.jacobian(x, u, f);
    Eigen::VectorXd fp(m), fm(m);
    for (int j = 0; j < m; ++j) {
      const bool angle = j >= 3 * n + 1;  // phi, phi' (and m_p, kg) take small steps
      const double h = angle || j == 3 * n ? 1e-6 : 1e-2;
      Eigen::VectorXd xp = x, xm = x;
      xp(j) += h, xm(j) -= h;
      ekf.dynamics(xp, u, fp);
      ekf.dynamics(xm, u, fm);
      fd.col(j) = (fp - fm) / (2 * h);
    }
    for (int j = 0; j < m; ++j) {
      EXPECT_LT((f.col(j) - fd.col(j)).norm(), 1e-5 * (1.0 + fd.col(j).norm())) << "column " << j;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Chains, AugmentedJacobianTest, ::testing::Values(2, 3));

/// Drives an arm carrying `payload` open loop (smooth motor torques) and observes it with an
/// EKF on the nominal model; returns the largest link-angle error over the last second.
double drive_with_unknown_payload(const FlexibleJointEkfParams& ep, double payload, double* estimated_payload) {
  FlexibleJointArmParams pp;
  pp.model.payload_mass = payload;
  FlexibleJointArmPlant plant(pp);
  FlexibleJointEkf ekf(ep);
  const double step = 2e-4;
  Eigen::VectorXd u(2), y(4);
  double worst = 0.0;
  for (int k = 1; k <= 20000; ++k) {
    const double t = k * step;
    u << 20 * std::sin(3 * t), 5 * std::cos(2 * t);
    plant.step(u, step);
    y << plant.state().phi, plant.state().phid;
    ekf.update(u, y, step);
    if (t > 3.0) worst = std::max(worst, (ekf.feedback().q - plant.state().q).cwiseAbs().maxCoeff());
  }
  if (estimated_payload) *estimated_payload = ekf.payload();
  return worst;
}

TEST(FlexibleJointEkf, TipMassStateLearnsAnUnknownPayload) {
  // 1.2 kg (30 % of link 2) that the observer's model lacks: the robust tuning learns it and
  // keeps the link angle; the paper's filter (Q = 4 I) is biased by it.
  FlexibleJointEkfParams robust = FlexibleJointEkfParams::robust(), paper = FlexibleJointEkfParams::paper();
  robust.step = paper.step = 2e-4;
  double learned = 0.0;
  const double robust_error = drive_with_unknown_payload(robust, 1.2, &learned);
  const double paper_error = drive_with_unknown_payload(paper, 1.2, nullptr);
  EXPECT_NEAR(learned, 1.2, 0.12);
  EXPECT_LT(robust_error, 1e-4);  // 0.1 mrad
  EXPECT_GT(paper_error, 10 * robust_error);
}

TEST(FlexibleJointPlant, TorqueLimitClampsTheAppliedTorque) {
  FlexibleJointArmParams limited;
  limited.torque_limit = Eigen::Vector2d(50, 15);
  FlexibleJointArmPlant a(limited), b({});
  const Eigen::Vector2d asked(400, -100), clamped(50, -15);
  for (int k = 0; k < 100; ++k) {
    a.step(asked, 1e-3);
    b.step(clamped, 1e-3);
  }
  EXPECT_TRUE(a.applied_torque().isApprox(clamped));
  EXPECT_LT((a.state().phi - b.state().phi).norm(), 1e-15);
  FlexibleJointArmPlant c({});
  c.step(asked, 1e-3);
  EXPECT_TRUE(c.applied_torque().isApprox(asked));  // no limit by default
}

TEST(VdcController, AntiWindupHoldsTheIntegralWhileTheOutputIsClamped) {
  // A constant tracking error that the clamped output cannot remove: without a limit the
  // integral t_s (21) winds up to its bound; with one, it stays where it was at saturation.
  VdcParams p = VdcParams::paper_2dof();
  p.step = 1e-3;
  VdcParams limited = p;
  limited.torque_limit = Eigen::Vector2d(50, 15);
  VdcController free_run(p), clamped(limited);
  ArmReferenceSample r{Eigen::Vector2d(0.05, 0.05), Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero(),
                       Eigen::Vector2d::Zero()};
  ArmFeedback fb = ArmFeedback::zero(2);
  for (int k = 0; k < 500; ++k) {
    free_run.step(r, fb);
    const Eigen::VectorXd& u = clamped.step(r, fb);
    EXPECT_LE(u.cwiseAbs().maxCoeff(), 50.0);
  }
  EXPECT_EQ(clamped.saturation(), Eigen::Vector2d(1, 1));
  EXPECT_GT(free_run.ts().minCoeff(), 400.0);  // wound up towards ts_max = 500
  EXPECT_LT(clamped.ts().maxCoeff(), 5.0);     // held (one step's integration at most)
}

}  // namespace
}  // namespace plexus::algorithms
