// Benchmarks of the flexible-joint arm family (paper 004).
//
//   BM_VdcEkfStep   2-DoF: EKF update (full Jacobian, 1 RK4 sub-step) + VDC step, one 5 kHz period
//                   (the paper's tuning: 8 states)
//   BM_VdcEkfStepRobust  the same with the default (robust) tuning: 11 states (tip mass,
//                   disturbance torques) and the VDC's disturbance feed-forward (issue 18)
//   BM_CtPdStep     2-DoF: CT+PD (one KDL recursive Newton-Euler call)
//   BM_VdcStep/n    VDC step alone on an n-link chain: the paper's claim is O(n)
//                   (see the reported BigO fit; docs/algorithms/arm.md has the figures)
#include <benchmark/benchmark.h>

#include <cmath>

#include "plexus/algorithms/arm/ct_pd_controller.hpp"
#include "plexus/algorithms/arm/flexible_joint_ekf.hpp"
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

void vdc_ekf_step(benchmark::State& state, bool robust) {
  FlexibleJointEkfParams ep = robust ? FlexibleJointEkfParams::robust() : FlexibleJointEkfParams::paper();
  ep.step = 2e-4;
  FlexibleJointEkf ekf(ep);
  VdcParams vp = VdcParams::paper_2dof();
  vp.step = 2e-4;
  if (robust) vp.disturbance_compensation = VdcParams::kRobustDisturbanceCompensation;
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
}
void BM_VdcEkfStep(benchmark::State& state) { vdc_ekf_step(state, false); }
void BM_VdcEkfStepRobust(benchmark::State& state) { vdc_ekf_step(state, true); }
BENCHMARK(BM_VdcEkfStep);
BENCHMARK(BM_VdcEkfStepRobust);

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
