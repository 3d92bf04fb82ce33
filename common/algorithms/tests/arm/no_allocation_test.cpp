// The arm's hot paths (plant step, reference sample, EKF update, VDC and CT+PD steps) must
// not allocate. This binary's global operator new counts; the count is checked around them.
#include <gtest/gtest.h>

#include "../support/count_allocations.hpp"

#include <atomic>
#include <cstdlib>
#include <new>

#include "plexus/algorithms/arm/ct_pd_controller.hpp"
#include "plexus/algorithms/arm/flexible_joint_ekf.hpp"
#include "plexus/algorithms/arm/flexible_joint_plant.hpp"
#include "plexus/algorithms/arm/vdc_controller.hpp"

namespace plexus::algorithms {
namespace {

TEST(ArmNoAllocation, HotPathsDoNotAllocate) {
  FlexibleJointArmPlant plant({});
  FlexibleJointEkfParams ep;
  ep.step = 2e-4;
  FlexibleJointEkf ekf(ep);
  VdcParams vp = VdcParams::paper_2dof();
  vp.step = 2e-4;
  VdcController vdc(vp);
  CtPdController ctpd(CtPdParams::paper_2dof());
  ArmSineReference ref(ArmSineReferenceParams::paper(2));
  ArmReferenceSample r;
  ref.sample(0.0, r);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(2), y = Eigen::VectorXd::Zero(4);
  double sink = 0.0;
  const long before = plexus::test::allocations();
  for (int k = 1; k < 200; ++k) {
    plant.step(u, 2e-4);
    const FlexibleJointArmState& s = plant.state();
    y << s.phi, s.phid;
    if (k % 5 == 0)
      ekf.predict(u, 2e-4);  // a period without a sample
    else
      ekf.update(u, y, 2e-4);
    ref.sample(k * 2e-4, r);
    u = vdc.step(r, ekf.feedback());
    sink += ctpd.step(r, ekf.feedback()).sum();
  }
  const long after = plexus::test::allocations();
  EXPECT_EQ(after - before, 0);
  EXPECT_TRUE(std::isfinite(sink + u.sum()));
}

}  // namespace
}  // namespace plexus::algorithms

namespace plexus::algorithms {
namespace {

TEST(ArmNoAllocation, RobustTuningAndTorqueLimitDoNotAllocate) {
  // Issue 18's defaults: the EKF with the tip-mass and disturbance states, the VDC with
  // disturbance compensation and a saturating torque limit (anti-windup active).
  FlexibleJointArmParams pp;
  pp.model.payload_mass = 0.8;
  pp.torque_limit = Eigen::Vector2d(50, 15);
  FlexibleJointArmPlant plant(pp);
  FlexibleJointEkfParams ep = FlexibleJointEkfParams::robust();
  ep.step = 2e-4;
  FlexibleJointEkf ekf(ep);
  VdcParams vp = VdcParams::paper_2dof();
  vp.step = 2e-4;
  vp.disturbance_compensation = VdcParams::kRobustDisturbanceCompensation;
  vp.torque_limit = Eigen::Vector2d(50, 15);
  VdcController vdc(vp);
  ArmSineReference ref(ArmSineReferenceParams::paper(2));
  ArmReferenceSample r;
  ref.sample(0.0, r);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(2), y = Eigen::VectorXd::Zero(4);
  double saturated = 0.0;
  const long before = plexus::test::allocations();
  for (int k = 1; k < 200; ++k) {
    plant.step(u, 2e-4);
    const FlexibleJointArmState& s = plant.state();
    y << s.phi, s.phid;
    ekf.update(u, y, 2e-4);
    ref.sample(k * 2e-4, r);
    u = vdc.step(r, ekf.feedback());
    saturated += vdc.saturation().cwiseAbs().sum();
  }
  const long after = plexus::test::allocations();
  EXPECT_EQ(after - before, 0);  // neither operator new nor Eigen's malloc
  EXPECT_GT(saturated, 0.0);     // the limit was reached: the anti-windup path ran
  EXPECT_TRUE(std::isfinite(u.sum() + ekf.payload()));
}

}  // namespace
}  // namespace plexus::algorithms
