// localisation_observer: heading_observer (paper 000) and velocity_heading_observer (paper
// 003). PositionMeasurement + UnicycleCommand in -> edge check -> observer update ->
// HeadingEstimate out.
#include <gtest/gtest.h>

#include <functional>

#include <cmath>
#include <numbers>

#include "plexus/algorithms/unicycle/heading_observer.hpp"
#include "plexus/algorithms/unicycle/velocity_heading_observer.hpp"
#include "plexus/scenario/parameter_change.hpp"
#include "service_harness.hpp"

namespace plexus::services_test {
namespace {

// The component types of services/localisation_observer/ whose data path this file tests.
const Covers kCovers{"heading_observer", "velocity_heading_observer"};

namespace alg = plexus::algorithms;

const std::string kHeading = R"(name: obs_part
step: 0.01
services:
  obs: {type: heading_observer, robot: r1, L: 4.0}
)";

const std::string kVelocity = R"(name: obs_part
step: 0.01
services:
  obs: {type: velocity_heading_observer, robot: r1, L2: 2.0, L4: 3.0}
)";

msg::PositionMeasurement position(const ServiceUnderTest& s, int64_t k, double x, double y) {
  auto m = s.stamped<msg::PositionMeasurement>(k);
  m.x(x);
  m.y(y);
  return m;
}

msg::UnicycleCommand command(const ServiceUnderTest& s, int64_t k, double v, double omega) {
  auto m = s.stamped<msg::UnicycleCommand>(k);
  m.v(v);
  m.omega(omega);
  return m;
}

// The robot's positions along an arc (v = 1 m/s, omega = 0.5 rad/s from theta = 0.3).
Eigen::Vector2d track(int64_t k) {
  alg::UnicycleState s{1.0, 2.0, 0.3};
  for (int64_t i = 0; i < k; ++i) s = alg::unicycle_step(s, {1.0, 0.5}, 0.01);
  return {s.x, s.y};
}

void feed_track(ServiceUnderTest& s, int64_t k) {
  const Eigen::Vector2d p = track(k);
  ASSERT_EQ(s.deliver("r1/position", position(s, k, p.x(), p.y())), Rejection::none);
  ASSERT_EQ(s.deliver("r1/cmd", command(s, k, 1.0, 0.5)), Rejection::none);
}

TEST(HeadingObserver, ReadsItsInputsAsTheirIdlTypes) {
  ServiceUnderTest s(kHeading);
  EXPECT_EQ(s.message_type("r1/position"), "PositionMeasurement");
  EXPECT_EQ(s.message_type("r1/cmd"), "plexus::msg::UnicycleCommand");  // a typed port: the scoped name
  EXPECT_EQ(s.message_type("r1/heading"), "HeadingEstimate");
}

TEST(HeadingObserver, OneUpdateByHandHeldPosition) {
  // held_position: z_hat+ = e^{M h} z_hat + L dp. From z_hat(0) = 0: z_hat = L dp.
  ServiceUnderTest s(kHeading, {}, {"services.obs.discretisation=held_position"});
  s.deliver("r1/position", position(s, 0, 1.0, 2.0));
  s.deliver("r1/cmd", command(s, 0, 1.0, 0.0));
  s.step(0);  // first sample: reset, the initial estimate (0, 0)
  auto m = s.published<msg::HeadingEstimate>("r1/heading");
  EXPECT_EQ(m.direction()[0], 0.0);
  EXPECT_EQ(m.direction()[1], 0.0);
  EXPECT_EQ(m.gain(), 4.0);
  s.deliver("r1/position", position(s, 1, 1.01, 2.01));
  s.step(1);
  m = s.published<msg::HeadingEstimate>("r1/heading");
  EXPECT_NEAR(m.direction()[0], 0.04, 1e-12);  // z3 = L dx
  EXPECT_NEAR(m.direction()[1], 0.04, 1e-12);  // z4 = L dy
  EXPECT_NEAR(m.heading(), std::numbers::pi / 4, 1e-12);
  EXPECT_EQ(m.header().data_time_ns(), 1 * s.step_ns());
  EXPECT_EQ(s.check_output("r1/heading"), Rejection::none);
}

// Step k along the arc, in the service and in `ref` (the algorithm): the estimates agree.
// Returns the service's estimate.
msg::HeadingEstimate step_along_arc(ServiceUnderTest& s, alg::HeadingObserver& ref, int64_t k) {
  feed_track(s, k);
  s.step(k);
  if (k == 0)
    ref.reset({0.0, 0.0}, track(0));
  else
    ref.update(0.01, track(k), {1.0, 0.5});
  const auto m = s.published<msg::HeadingEstimate>("r1/heading");
  EXPECT_NEAR(m.direction()[0], ref.state().z_hat.x(), 1e-12) << k;
  EXPECT_NEAR(m.direction()[1], ref.state().z_hat.y(), 1e-12) << k;
  return m;
}

TEST(HeadingObserver, MatchesTheAlgorithmAlongAnArc) {
  ServiceUnderTest s(kHeading);
  alg::HeadingObserver ref({4.0, alg::ObserverDiscretisation::kExactArc});
  for (int64_t k = 0; k < 20; ++k) {
    step_along_arc(s, ref, k);
    ASSERT_FALSE(::testing::Test::HasFailure()) << k;
  }
  // The estimate converges towards the true heading 0.3 + 0.5 t (eq. (10)): it has moved.
  EXPECT_GT(s.out("r1/heading", "z3"), 0.1);
  EXPECT_GT(s.out("r1/heading", "theta"), 0.2);
}

// plexus param (docs/parameters.md): L changes between two steps, through the component's
// tunable parameter (as the param server does) or the scenario's parameter_changes; the
// estimate follows the algorithm with the new gain from that step on, and its gain field says it.
void expect_gain_change_at_step_10(ServiceUnderTest& s, const std::function<void(int64_t)>& before_step) {
  alg::HeadingObserver ref({4.0, alg::ObserverDiscretisation::kExactArc});
  for (int64_t k = 0; k < 20; ++k) {
    before_step(k);
    if (k == 10) ref.set_params({1.5, alg::ObserverDiscretisation::kExactArc});
    ASSERT_EQ(step_along_arc(s, ref, k).gain(), k < 10 ? 4.0 : 1.5) << k;
    ASSERT_FALSE(::testing::Test::HasFailure()) << k;
  }
}

TEST(HeadingObserver, ItsGainChangesWhileItRunsFromTheNextStep) {
  ServiceUnderTest s(kHeading);
  const scenario::TunableParameter* L = s.scenario().components[0].component->tunable("L");
  ASSERT_NE(L, nullptr);
  EXPECT_EQ(L->get(), 4.0);
  expect_gain_change_at_step_10(s, [L](int64_t k) {
    if (k == 10) L->set(1.5);
  });
  // A bad value is refused by the constructor's own check, and changes nothing.
  EXPECT_THROW(L->set(-1.0), std::invalid_argument);
  EXPECT_EQ(L->get(), 1.5);
  EXPECT_EQ(scenario::try_set(*L, 0.0), "heading_observer: L must be finite and > 0 (got 0)");
  EXPECT_EQ(scenario::try_set(*L, kNaN), "L: must be a finite number");
  feed_track(s, 20);
  s.step(20);
  EXPECT_EQ(s.published<msg::HeadingEstimate>("r1/heading").gain(), 1.5);
}

TEST(HeadingObserver, TheScenarioScheduleChangesItsGainAtItsStep) {
  ServiceUnderTest s(kHeading + "parameter_changes: [{step: 10, key: obs.L, value: 1.5}]\n");
  expect_gain_change_at_step_10(s, [](int64_t) {});
}

// `reads_v`: the heading observer reads the command's v; the velocity observer reads only
// omega, so a bad v is not a member it reads and passes (its own edge check is per field).
std::vector<BadSample> bad_inputs(bool reads_v) {
  std::vector<BadSample> t{
      {"position x NaN",
       [](ServiceUnderTest& s, int64_t k) { return s.deliver("r1/position", position(s, k, kNaN, 0.0)); },
       Rejection::non_finite},
      {"position y 2000 km",
       [](ServiceUnderTest& s, int64_t k) { return s.deliver("r1/position", position(s, k, 0.0, 2e6)); },
       Rejection::out_of_range},
      {"position from before the epoch",
       [](ServiceUnderTest& s, int64_t) { return s.deliver("r1/position", position(s, -5, 0.5, 0.5)); },
       Rejection::negative_time},
      {"command omega inf",
       [](ServiceUnderTest& s, int64_t k) { return s.deliver("r1/cmd", command(s, k, 1.0, kInf)); },
       Rejection::non_finite},
  };
  if (reads_v)
    t.push_back({"command v 1e5 m/s",
                 [](ServiceUnderTest& s, int64_t k) { return s.deliver("r1/cmd", command(s, k, 1e5, 0.0)); },
                 Rejection::out_of_range});
  return t;
}

TEST(HeadingObserver, BadSamplesAreRefusedAndLeaveTheEstimateAlone) {
  expect_refused_without_effect(kHeading, {}, {"r1/heading"}, 12, 5, feed_track, bad_inputs(true));
}

TEST(HeadingObserver, BadParametersAreConfigurationErrors) {
  expect_config_errors(kHeading, {
                                     {"services.obs.L=-1", {"services.obs", "L"}},
                                     {"services.obs.L=fast", {"services.obs.L"}},
                                     {"services.obs.discretisation=euler", {"services.obs.discretisation"}},
                                     {"services.obs.z3_0=[1]", {"services.obs.z3_0"}},
                                     {"services.obs.gain=1", {"services.obs.gain", "unknown key"}},
                                 });
  EXPECT_NE(config_error(R"(name: p
step: 0.01
services:
  obs: {type: heading_observer, robot: r1}
)",
                         {})
                .find("services.obs.L: required key is missing"),
            std::string::npos);
}

TEST(VelocityHeadingObserver, OneUpdateByHandHeldPosition) {
  // held_position: z_hat+ = E z_hat + diag(L2, L4) dp; from 0: (L2 dx, L4 dy).
  ServiceUnderTest s(kVelocity, {}, {"services.obs.discretisation=held_position"});
  s.deliver("r1/position", position(s, 0, 1.0, 2.0));
  s.deliver("r1/cmd", command(s, 0, 0.0, 0.3));
  s.step(0);
  s.deliver("r1/position", position(s, 1, 1.01, 2.02));
  s.step(1);
  const auto m = s.published<msg::HeadingEstimate>("r1/heading");
  EXPECT_NEAR(m.direction()[0], 0.02, 1e-12);  // z2 = L2 dx
  EXPECT_NEAR(m.direction()[1], 0.06, 1e-12);  // z4 = L4 dy
  EXPECT_NEAR(m.speed(), std::hypot(0.02, 0.06), 1e-12);
  EXPECT_NEAR(m.heading(), std::atan2(0.06, 0.02), 1e-12);
  EXPECT_EQ(m.gain(), 0.0);  // not in this signal: zero
}

TEST(VelocityHeadingObserver, MatchesTheAlgorithmAlongAnArc) {
  ServiceUnderTest s(kVelocity);
  alg::VelocityHeadingObserver ref({2.0, 3.0, alg::ObserverDiscretisation::kExactArc});
  for (int64_t k = 0; k < 20; ++k) {
    feed_track(s, k);
    s.step(k);
    if (k == 0)
      ref.reset({0.0, 0.0}, track(0));
    else
      ref.update(0.01, track(k), 0.5);
    ASSERT_NEAR(s.out("r1/heading", "z2"), ref.state().z_hat.x(), 1e-12) << k;
    ASSERT_NEAR(s.out("r1/heading", "z4"), ref.state().z_hat.y(), 1e-12) << k;
    ASSERT_NEAR(s.out("r1/heading", "speed"), ref.speed(), 1e-12) << k;
  }
  EXPECT_GT(s.out("r1/heading", "speed"), 0.1);  // on its way to the true 1 m/s
}

TEST(VelocityHeadingObserver, BadSamplesAreRefusedAndLeaveTheEstimateAlone) {
  expect_refused_without_effect(kVelocity, {}, {"r1/heading"}, 12, 5, feed_track, bad_inputs(false));
}

TEST(VelocityHeadingObserver, ReadsOnlyTheTurnRateOfTheCommand) {
  ServiceUnderTest s(kVelocity);
  EXPECT_EQ(s.fields("r1/cmd"), std::vector<std::string>{"omega"});
  EXPECT_EQ(s.deliver("r1/cmd", command(s, 0, kNaN, 0.5)), Rejection::none);  // v is not read
}

TEST(VelocityHeadingObserver, BadParametersAreConfigurationErrors) {
  expect_config_errors(kVelocity, {
                                      {"services.obs.L2=0", {"services.obs", "L2"}},
                                      {"services.obs.L4=-3", {"services.obs", "L4"}},
                                      {"services.obs.discretisation=rk4", {"services.obs.discretisation"}},
                                      {"services.obs.L=1", {"services.obs.L", "unknown key"}},
                                  });
}

}  // namespace
}  // namespace plexus::services_test
