// Benchmarks of the unicycle family's hot paths (papers 000 and 003), one controller
// period each, on the paper's settings (docs/algorithms/unicycle.md):
//   BM_HeadingObserverStep   heading observer update (000 Thm 1, exact-arc discretisation)
//   BM_OutputFeedbackStep    RFID measurement + heading observer + output-feedback law
//                            (000 eqs. (27)-(28)) + figure-eight sample: one 6.3.2 period
//   BM_PathFollowingStep     velocity observer (003 Thm 1) + path evaluation + observer-based
//                            law (003 eqs. (15)-(16)) on the unit circle
// Each closes the loop through the exact plant so the inputs stay realistic; the plant step
// (a few ns, BM_UnicyclePlantStep) is part of the figure.
#include <benchmark/benchmark.h>

#include "plexus/algorithms/unicycle/figure_eight_reference.hpp"
#include "plexus/algorithms/unicycle/geometric_path.hpp"
#include "plexus/algorithms/unicycle/heading_observer.hpp"
#include "plexus/algorithms/unicycle/path_following_controller.hpp"
#include "plexus/algorithms/unicycle/position_sensor.hpp"
#include "plexus/algorithms/unicycle/tracking_controller.hpp"
#include "plexus/algorithms/unicycle/unicycle_plant.hpp"
#include "plexus/algorithms/unicycle/velocity_heading_observer.hpp"

namespace {

using namespace plexus::algorithms;
constexpr double kStep = 0.01;  // s, 100 Hz as in the papers' simulations

void BM_HeadingObserverStep(benchmark::State& state) {
  HeadingObserver obs({1.0});
  UnicycleState s{0.0, -6.0, 0.0};
  const UnicycleInput u{0.2, 0.1};
  obs.reset({0.0, 0.0}, {s.x, s.y});
  for (auto _ : state) {
    s = unicycle_step(s, u, kStep);
    obs.update(kStep, {s.x, s.y}, u);
    benchmark::DoNotOptimize(obs.state());
  }
}
BENCHMARK(BM_HeadingObserverStep);

void BM_OutputFeedbackStep(benchmark::State& state) {
  const FigureEightReference ref({});
  const TrajectoryTrackingController ctl({0.11, 0.11, 0.1});
  HeadingObserver obs({0.6});
  PositionSensorParams sp;
  sp.kind = PositionSensorKind::kRfidGrid;
  const PositionSensor sensor(sp);
  Rng rng = sensor.make_rng();
  UnicycleState s{0.0, -6.0, 0.0};
  obs.reset({0.0, 0.0}, sensor.measure({s.x, s.y}, rng));
  double t = 0.0;
  for (auto _ : state) {
    const Eigen::Vector2d p = sensor.measure({s.x, s.y}, rng);
    const TrackingOutput out = ctl.output_feedback(ref.sample(t), p, obs.state().z_hat);
    s = unicycle_step(s, out.input, kStep);
    obs.update(kStep, sensor.measure({s.x, s.y}, rng), out.input);
    t += kStep;
    benchmark::DoNotOptimize(out);
  }
}
BENCHMARK(BM_OutputFeedbackStep);

void BM_PathFollowingStep(benchmark::State& state) {
  const GeometricPath path(CirclePath{});
  const PathFollowingController ctl({1.0, 2.0});
  VelocityHeadingObserver obs({2.0, 2.0});
  UnicycleState s{1.2, 0.0, 1.8707963267948966};
  obs.reset({0.3, 0.6}, {s.x, s.y});
  for (auto _ : state) {
    const PathFollowingOutput out = ctl.observer_based(path, {s.x, s.y}, obs.state().z_hat);
    s = unicycle_step(s, {1.0, out.u2}, kStep);
    obs.update(kStep, {s.x, s.y}, out.u2);
    benchmark::DoNotOptimize(out);
  }
}
BENCHMARK(BM_PathFollowingStep);

}  // namespace
