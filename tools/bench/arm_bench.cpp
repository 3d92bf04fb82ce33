// Benchmarks of the flexible-joint arm family (paper 004).
//
//   BM_VdcEkfStep   2-DoF: EKF update (full Jacobian, 1 RK4 sub-step) + VDC step, one 5 kHz period
//                   (the paper's tuning: 8 states)
//   BM_VdcEkfStepOnArm/0, /1  the same on a recorded run of the arm, paper tuning (/0) and the
//                   default robust tuning (/1: 11 states, the VDC's disturbance feed-forward)
//   BM_CtPdStep     2-DoF: CT+PD (one KDL recursive Newton-Euler call)
//   BM_VdcStep/n    VDC step alone on an n-link chain: the paper's claim is O(n)
//                   (see the reported BigO fit; docs/algorithms/arm.md has the figures)
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "plexus/algorithms/arm/chain_dynamics.hpp"
#include "plexus/algorithms/arm/ct_pd_controller.hpp"
#include "plexus/algorithms/arm/flexible_joint_ekf.hpp"
#include "plexus/algorithms/arm/flexible_joint_plant.hpp"
#include "plexus/algorithms/arm/vdc_controller.hpp"

namespace {

using namespace plexus::algorithms;

ArmFeedback sample_feedback(int n) {
  ArmFeedback fb = ArmFeedback::zero(n);
  for (int i = 0; i < n; ++i) {
    fb.q(i) = 0.1 * std::sin(i + 1.0), fb.qd(i) = 0.3 * std::cos(i + 2.0), fb.qdd(i) = 0.5;
    fb.qddd(i) = 2.0, fb.tau(i) = 2.0, fb.taud(i) = 1.0, fb.phi(i) = fb.q(i) + 2e-4, fb.phid(i) = fb.qd(i);
  }
  return fb;
}

void BM_VdcEkfStep(benchmark::State& state) {
  FlexibleJointEkfParams ep;
  ep.step = 2e-4;
  FlexibleJointEkf ekf(ep);
  VdcParams vp = VdcParams::paper_2dof();
  vp.step = 2e-4;
  VdcController vdc(vp);
  ArmSineReference ref(ArmSineReferenceParams::paper(2));
  ArmReferenceSample r;
  Eigen::VectorXd u = Eigen::VectorXd::Zero(2), y = Eigen::VectorXd::Zero(4);
  double t = 0.0;
  for (auto _ : state) {
    t += 2e-4;
    y << 0.01 * std::sin(t), 0.01 * std::cos(t), 0.01 * std::cos(t), -0.01 * std::sin(t);
    ekf.update(u, y, 2e-4);
    ref.sample(t, r);
    u = vdc.step(r, ekf.feedback());
    benchmark::DoNotOptimize(u.data());
  }
  state.counters["finite"] = u.allFinite() && ekf.state().allFinite() ? 1.0 : 0.0;
}
BENCHMARK(BM_VdcEkfStep);

/// One second (t = 1..2 s, after the start transient; the reference has a 1 s period) of the
/// paper's arm under VDC+EKF at 5 kHz: the encoder samples y and the applied torques u.
struct ArmRecord {
  std::vector<Eigen::VectorXd> y, u;
  std::vector<double> t;
};

// The paper's or the default (robust) tuning of the EKF and the VDC controller at 5 kHz,
// as BM_VdcEkfStepOnArm records and replays them.
FlexibleJointEkfParams arm_ekf_params(bool robust) {
  FlexibleJointEkfParams ep = robust ? FlexibleJointEkfParams::robust() : FlexibleJointEkfParams::paper();
  ep.step = 2e-4;
  return ep;
}

VdcParams arm_vdc_params(bool robust) {
  VdcParams vp = VdcParams::paper_2dof();
  vp.step = 2e-4;
  if (robust) vp.disturbance_compensation = VdcParams::kRobustDisturbanceCompensation;
  return vp;
}

ArmRecord record_arm(bool robust) {
  FlexibleJointArmPlant plant({});
  plant.reset_in_motion(Eigen::Vector2d::Zero(), Eigen::Vector2d::Ones());
  const FlexibleJointEkfParams ep = arm_ekf_params(robust);
  FlexibleJointEkf ekf(ep);
  VdcController vdc(arm_vdc_params(robust));
  ArmSineReference ref(ArmSineReferenceParams::paper(2));
  ArmReferenceSample r;
  Eigen::VectorXd u = Eigen::VectorXd::Zero(2), y(4), x0(8);
  ArmChainDynamics dyn(ep.model);
  Eigen::VectorXd bias(2);
  dyn.inverse_dynamics(plant.state().phi, plant.state().phid, Eigen::Vector2d::Zero(), bias);
  x0 << bias, Eigen::Vector2d::Zero(), plant.state().phi, plant.state().phid;
  ekf.reset(x0);
  ArmRecord rec;
  for (int k = 1; k <= 10000; ++k) {
    plant.step(u, 2e-4);
    y << plant.state().phi, plant.state().phid;
    ekf.update(u, y, 2e-4);
    ref.sample(k * 2e-4, r);
    u = vdc.step(r, ekf.feedback());
    if (k > 5000) rec.y.push_back(y), rec.u.push_back(u), rec.t.push_back(k * 2e-4);
  }
  return rec;
}

// BM_VdcEkfStepOnArm/0 (paper tuning), /1 (default, robust tuning): EKF update + VDC step on
// a recorded run of the arm (the inputs a real step sees; the fake signal of BM_VdcEkfStep
// drives the robust filter's extra states away), replayed cyclically.
void BM_VdcEkfStepOnArm(benchmark::State& state) {
  const bool robust = state.range(0) == 1;
  const ArmRecord rec = record_arm(robust);
  const FlexibleJointEkfParams ep = arm_ekf_params(robust);
  FlexibleJointEkf ekf(ep);
  VdcController vdc(arm_vdc_params(robust));
  ArmSineReference ref(ArmSineReferenceParams::paper(2));
  ArmReferenceSample r;
  ArmChainDynamics dyn(ep.model);
  Eigen::VectorXd x0(8), bias(2);
  dyn.inverse_dynamics(rec.y[0].head(2), rec.y[0].tail(2), Eigen::Vector2d::Zero(), bias);
  x0 << bias, Eigen::Vector2d::Zero(), rec.y[0];
  ekf.reset(x0);
  std::size_t k = 0;
  for (auto _ : state) {
    ekf.update(rec.u[k], rec.y[k], 2e-4);
    ref.sample(rec.t[k], r);
    const Eigen::VectorXd& u = vdc.step(r, ekf.feedback());
    benchmark::DoNotOptimize(u.data());
    k = (k + 1) % rec.y.size();
  }
  state.counters["finite"] = ekf.state().allFinite() ? 1.0 : 0.0;
}
BENCHMARK(BM_VdcEkfStepOnArm)->Arg(0)->Arg(1);

void BM_CtPdStep(benchmark::State& state) {
  CtPdController c(CtPdParams::paper_2dof());
  ArmSineReference ref(ArmSineReferenceParams::paper(2));
  ArmReferenceSample r;
  ref.sample(0.3, r);
  const ArmFeedback fb = sample_feedback(2);
  for (auto _ : state) {
    const Eigen::VectorXd& u = c.step(r, fb);
    benchmark::DoNotOptimize(u.data());
  }
}
BENCHMARK(BM_CtPdStep);

void BM_VdcStep(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  VdcController vdc(VdcParams::uniform(ArmModel::uniform_chain(n)));
  ArmSineReference ref(ArmSineReferenceParams::paper(n));
  ArmReferenceSample r;
  ref.sample(0.3, r);
  const ArmFeedback fb = sample_feedback(n);
  for (auto _ : state) {
    const Eigen::VectorXd& u = vdc.step(r, fb);
    benchmark::DoNotOptimize(u.data());
  }
  state.SetComplexityN(n);
}
BENCHMARK(BM_VdcStep)->Arg(2)->Arg(4)->Arg(8)->Arg(16)->Arg(32)->Complexity();

}  // namespace
