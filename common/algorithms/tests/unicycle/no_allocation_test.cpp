// The hot-path calls (observer update, controller evaluation, path evaluation, sensor
// measurement, reference sampling) must not allocate. This test binary replaces the global
// operator new with a counting one and checks the count around those calls only.
#include <gtest/gtest.h>

#include "../support/count_allocations.hpp"

#include <atomic>
#include <cstdlib>
#include <new>

#include "plexus/algorithms/unicycle/figure_eight_reference.hpp"
#include "plexus/algorithms/unicycle/geometric_path.hpp"
#include "plexus/algorithms/unicycle/heading_observer.hpp"
#include "plexus/algorithms/unicycle/path_following_controller.hpp"
#include "plexus/algorithms/unicycle/position_sensor.hpp"
#include "plexus/algorithms/unicycle/tracking_controller.hpp"
#include "plexus/algorithms/unicycle/velocity_heading_observer.hpp"

namespace plexus::algorithms {
namespace {

TEST(NoAllocation, HotPathsDoNotAllocate) {
  FigureEightReference ref({});
  TrajectoryTrackingController tracking({});
  HeadingObserver heading({0.6});
  VelocityHeadingObserver velocity({2.0, 3.0});
  PositionSensorParams sp;
  sp.kind = PositionSensorKind::kGaussian;
  sp.sigma = 0.01;
  PositionSensor sensor(sp);
  Rng rng = sensor.make_rng();
  PolynomialPath poly;
  poly.c(2, 0) = 1.0;
  poly.c(0, 2) = 1.0;
  poly.c(0, 0) = -1.0;
  const GeometricPath paths[] = {GeometricPath(CirclePath{}), GeometricPath(EllipsePath{}), GeometricPath(poly)};
  PathFollowingController following({});
  heading.reset({0.0, 0.0}, {0.0, -6.0});
  velocity.reset({0.0, 0.0}, {0.0, -6.0});
  UnicycleState s{0.0, -6.0, 0.0};

  const long before = plexus::test::allocations();
  double sink = 0;
  for (int k = 0; k < 100; ++k) {
    const ReferenceSample r = ref.sample(0.01 * k);
    const Eigen::Vector2d m = sensor.measure({s.x, s.y}, rng);
    const TrackingOutput a = tracking.state_feedback(r, s);
    const TrackingOutput b = tracking.output_feedback(r, m, heading.state().z_hat);
    heading.update(0.01, m, b.input);
    velocity.update(0.01, m, b.input.omega);
    for (const GeometricPath& p : paths) sink += following.observer_based(p, m, velocity.state().z_hat).u2;
    s = unicycle_step(s, a.input, 0.01);
    sink += a.input.omega + b.input.omega;
  }
  const long after = plexus::test::allocations();
  EXPECT_EQ(after - before, 0);
  EXPECT_TRUE(std::isfinite(sink));
}

}  // namespace
}  // namespace plexus::algorithms
