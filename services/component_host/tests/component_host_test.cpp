// component_host: figure_eight_reference, circle_reference, geometric_path,
// arm_sine_reference, constant_command. Only geometric_path reads a message
// (PositionMeasurement); the others are clocks -> PlanarReference / JointReference /
// UnicycleCommand, whose output must pass the consumer's edge check.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "plexus/algorithms/unicycle/figure_eight_reference.hpp"
#include "service_harness.hpp"

namespace plexus::services_test {
namespace {

// The component types of services/component_host/ whose data path this file tests.
const Covers kCovers{"figure_eight_reference", "circle_reference", "geometric_path", "arm_sine_reference",
                     "constant_command"};

namespace alg = plexus::algorithms;
constexpr double kPi = std::numbers::pi;

// --- figure_eight_reference ---------------------------------------------------------------

const std::string kFigureEight = R"(name: ref_part
step: 0.01
services:
  ref: {type: figure_eight_reference, robot: r1}
)";

TEST(FigureEightReference, StartsAtTheBottomPointByHand) {
  // Paper 000 eq. (51)-(52), h1 = 5, h2 = 0.02, t0 = 3 pi / (2 h2): at t = 0, a = 3 pi / 2:
  // p = (h1 sin 3pi, h1 sin(3pi/2)) = (0, -5), p' = (2 h1 h2 cos 3pi, 0) = (-0.2, 0),
  // p'' = (0, h1 h2^2) = (0, 0.002).
  ServiceUnderTest s(kFigureEight);
  s.step(0);
  const auto m = s.published<msg::PlanarReference>("r1/reference");
  EXPECT_NEAR(m.position()[0], 0.0, 1e-12);
  EXPECT_NEAR(m.position()[1], -5.0, 1e-12);
  EXPECT_NEAR(m.velocity()[0], -0.2, 1e-12);
  EXPECT_NEAR(m.velocity()[1], 0.0, 1e-12);
  EXPECT_NEAR(m.acceleration()[0], 0.0, 1e-12);
  EXPECT_NEAR(m.acceleration()[1], 0.002, 1e-12);
  EXPECT_EQ(s.check_output("r1/reference"), Rejection::none);
}

TEST(FigureEightReference, FollowsTheCurveInTime) {
  ServiceUnderTest s(kFigureEight, {}, {"services.ref.h1=3", "services.ref.h2=0.1"});
  const alg::FigureEightReference ref({3.0, 0.1, alg::FigureEightParams::paper_t0(0.1)});
  for (int64_t k : {1, 777, 12345}) {
    s.step(k);
    const auto r = ref.sample(0.01 * static_cast<double>(k));
    EXPECT_DOUBLE_EQ(s.out("r1/reference", "x"), r.p.x()) << k;
    EXPECT_DOUBLE_EQ(s.out("r1/reference", "dy"), r.dp.y()) << k;
    EXPECT_DOUBLE_EQ(s.out("r1/reference", "ddx"), r.ddp.x()) << k;
  }
}

TEST(FigureEightReference, BadParametersAreConfigurationErrors) {
  expect_config_errors(kFigureEight, {
                                         {"services.ref.h2=0", {"services.ref.h2"}},
                                         {"services.ref.h1=-5", {"services.ref", "h1"}},
                                         {"services.ref.t0=soon", {"services.ref.t0"}},
                                     });
}

// --- circle_reference ---------------------------------------------------------------------

const std::string kCircle = R"(name: ref_part
step: 0.01
services:
  ref: {type: circle_reference, robot: r1, radius: 2.0, speed: 1.0, center_x: 1.0, center_y: -1.0}
)";

TEST(CircleReference, PointOfTheCircleByHand) {
  // w = speed / radius = 0.5 rad/s; at t = 1 s the angle is 0.5 rad.
  ServiceUnderTest s(kCircle);
  s.step(100);
  const auto m = s.published<msg::PlanarReference>("r1/reference");
  EXPECT_DOUBLE_EQ(m.position()[0], 1.0 + 2.0 * std::cos(0.5));
  EXPECT_DOUBLE_EQ(m.position()[1], -1.0 + 2.0 * std::sin(0.5));
  EXPECT_DOUBLE_EQ(m.velocity()[0], -std::sin(0.5));
  EXPECT_DOUBLE_EQ(m.velocity()[1], std::cos(0.5));
  EXPECT_DOUBLE_EQ(m.acceleration()[0], -0.5 * std::cos(0.5));
  EXPECT_DOUBLE_EQ(m.acceleration()[1], -0.5 * std::sin(0.5));
  ServiceUnderTest cw(kCircle, {}, {"services.ref.speed=-1", "services.ref.phase0=1.5707963267948966"});
  cw.step(0);  // at the top, going clockwise: velocity (+1, 0)
  EXPECT_NEAR(cw.out("r1/reference", "dx"), 1.0, 1e-12);
  EXPECT_NEAR(cw.out("r1/reference", "y"), 1.0, 1e-12);
}

TEST(CircleReference, BadParametersAreConfigurationErrors) {
  expect_config_errors(kCircle, {
                                    {"services.ref.radius=0", {"services.ref.radius", "> 0"}},
                                    {"services.ref.speed=0", {"services.ref.speed"}},
                                    {"services.ref.centre_x=1", {"services.ref.centre_x", "unknown key"}},
                                });
}

// --- geometric_path -----------------------------------------------------------------------

const std::string kPath = R"(name: path_part
step: 0.01
services:
  path: {type: geometric_path, robot: r1, shape: circle, radius: 1.0}
)";

msg::PositionMeasurement position(const ServiceUnderTest& s, int64_t k, double x, double y) {
  auto m = s.stamped<msg::PositionMeasurement>(k);
  m.x(x), m.y(y);
  return m;
}

TEST(GeometricPath, CircleAtAPositionByHand) {
  // h = x^2 + y^2 - 1 at (2, 0): h = 3, grad = (4, 0), Hess = 2 I. The point on the path:
  // three Gauss-Newton steps q <- q - h grad / |grad|^2 from 2: 1.25, 1.025, then
  // 1.025 - 0.050625 * 2.05 / 4.2025.
  ServiceUnderTest s(kPath);
  EXPECT_EQ(s.message_type("r1/position"), "PositionMeasurement");
  ASSERT_EQ(s.deliver("r1/position", position(s, 0, 2.0, 0.0)), Rejection::none);
  s.step(0);
  const auto m = s.published<msg::PathSample>("r1/path");
  EXPECT_DOUBLE_EQ(m.h(), 3.0);
  EXPECT_DOUBLE_EQ(m.gradient()[0], 4.0);
  EXPECT_DOUBLE_EQ(m.gradient()[1], 0.0);
  EXPECT_DOUBLE_EQ(m.hessian()[0], 2.0);
  EXPECT_DOUBLE_EQ(m.hessian()[1], 0.0);
  EXPECT_DOUBLE_EQ(m.hessian()[2], 2.0);
  EXPECT_NEAR(m.position()[0], 1.025 - 0.050625 * 2.05 / 4.2025, 1e-12);
  EXPECT_DOUBLE_EQ(m.position()[1], 0.0);
}

TEST(GeometricPath, LineByHand) {
  // h = n . (p - point) with point (0, 1), n = (0, 1): at (3, 4) h = 3, on the path (3, 1).
  ServiceUnderTest s(R"(name: path_part
step: 0.01
services:
  path: {type: geometric_path, robot: r1, shape: line, point_y: 1.0}
)");
  s.deliver("r1/position", position(s, 0, 3.0, 4.0));
  s.step(0);
  EXPECT_DOUBLE_EQ(s.out("r1/path", "h"), 3.0);
  EXPECT_DOUBLE_EQ(s.out("r1/path", "hy"), 1.0);
  EXPECT_DOUBLE_EQ(s.out("r1/path", "x"), 3.0);
  EXPECT_DOUBLE_EQ(s.out("r1/path", "y"), 1.0);
}

TEST(GeometricPath, BadSamplesAreRefusedAndLeaveThePathAlone) {
  const Feed feed = [](ServiceUnderTest& s, int64_t k) {
    ASSERT_EQ(s.deliver("r1/position", position(s, k, 1.5 - 0.1 * static_cast<double>(k), 0.2)), Rejection::none);
  };
  expect_refused_without_effect(
      kPath, {}, {"r1/path"}, 6, 3, feed,
      {
          {"x NaN", [](ServiceUnderTest& s, int64_t k) { return s.deliver("r1/position", position(s, k, kNaN, 0)); },
           Rejection::non_finite},
          {"y 1e7 m", [](ServiceUnderTest& s, int64_t k) { return s.deliver("r1/position", position(s, k, 0, 1e7)); },
           Rejection::out_of_range},
          {"before the epoch",
           [](ServiceUnderTest& s, int64_t) { return s.deliver("r1/position", position(s, -3, 0, 0)); },
           Rejection::negative_time},
      });
}

TEST(GeometricPath, BadParametersAreConfigurationErrors) {
  expect_config_errors(kPath, {
                                  {"services.path.shape=square", {"services.path.shape"}},
                                  {"services.path.radius=-1", {"services.path", "radius"}},
                                  {"services.path.radius=[1, 2]", {"services.path.radius"}},
                              });
  EXPECT_NE(config_error(kPath, {"services.path.shape=polynomial", "services.path.terms=[[1, 2]]"})
                .find("services.path.terms"),
            std::string::npos);
  // Read through number(): a word as a power threw yaml-cpp's own exception; 1e10 was taken.
  for (const char* terms : {"services.path.terms=[[x, 0, 1]]", "services.path.terms=[[0.5, 0, 1]]",
                            "services.path.terms=[[1e10, 0, 1]]", "services.path.terms=[[1, 0, .inf]]"})
    EXPECT_NE(config_error(kPath, {"services.path.shape=polynomial", terms}).find("services.path.terms"),
              std::string::npos)
        << terms;
  EXPECT_NE(config_error(kPath, {"services.path.shape=ellipse", "services.path.a=2"}).find("services.path.b"),
            std::string::npos);
}

// --- arm_sine_reference -------------------------------------------------------------------

const std::string kArmReference = R"(name: ref_part
step: 0.01
services:
  ref: {type: arm_sine_reference, robot: r4}
)";

TEST(ArmSineReference, PaperReferenceByHand) {
  // Eq. (59): q_d = (sin(2 pi t) + 0.088) / (2 pi); at t = 0.25 s: q_d = 1.088 / (2 pi),
  // q_d' = cos(pi / 2) = 0, q_d'' = -2 pi, q_d''' = 0, for both joints.
  ServiceUnderTest s(kArmReference);
  s.step(25);
  const auto m = s.published<msg::JointReference>("r4/reference");
  EXPECT_EQ(m.count(), 2);
  for (int j = 0; j < 2; ++j) {
    EXPECT_NEAR(m.position()[j], 1.088 / (2 * kPi), 1e-12) << j;
    EXPECT_NEAR(m.velocity()[j], 0.0, 1e-12) << j;
    EXPECT_NEAR(m.acceleration()[j], -2 * kPi, 1e-12) << j;
    EXPECT_NEAR(m.jerk()[j], 0.0, 1e-9) << j;
  }
  EXPECT_EQ(m.position()[2], 0.0);  // joints beyond count are zero
  EXPECT_EQ(s.check_output("r4/reference"), Rejection::none);
}

TEST(ArmSineReference, OwnSinusoidByHand) {
  ServiceUnderTest s(kArmReference, {},
                     {"services.ref.dof=1", "services.ref.amplitude=[0.5]", "services.ref.frequency_hz=[2]",
                      "services.ref.offset=[0.1]", "services.ref.phase=[0.3]"});
  s.step(10);  // t = 0.1 s: a = 2 pi 2 0.1 + 0.3
  const double a = 0.4 * kPi + 0.3, w = 4 * kPi;
  EXPECT_EQ(s.fields("r4/reference"), (std::vector<std::string>{"q1", "dq1", "ddq1", "dddq1"}));
  EXPECT_NEAR(s.out("r4/reference", "q1"), 0.1 + 0.5 * std::sin(a), 1e-12);
  EXPECT_NEAR(s.out("r4/reference", "dq1"), 0.5 * w * std::cos(a), 1e-12);
  EXPECT_NEAR(s.out("r4/reference", "ddq1"), -0.5 * w * w * std::sin(a), 1e-9);
  EXPECT_NEAR(s.out("r4/reference", "dddq1"), -0.5 * w * w * w * std::cos(a), 1e-9);
}

TEST(ArmSineReference, BadParametersAreConfigurationErrors) {
  expect_config_errors(kArmReference, {
                                          {"services.ref.dof=0", {"services.ref.dof"}},
                                          {"services.ref.dof=17", {"services.ref.dof"}},
                                          {"services.ref.amplitude=[1]", {"services.ref.amplitude", "2 numbers"}},
                                          {"services.ref.frequency_hz=[-1, 1]", {"services.ref", "frequency"}},
                                      });
}

// --- constant_command ---------------------------------------------------------------------

const std::string kConstant = R"(name: driver_part
step: 0.01
services:
  driver: {type: constant_command, robot: r1, v: 0.5, omega: -0.2}
)";

TEST(ConstantCommand, PublishesItsParameters) {
  ServiceUnderTest s(kConstant);
  for (int64_t k : {0, 1, 99}) {
    s.step(k);
    const auto m = s.published<msg::UnicycleCommand>("r1/cmd");
    EXPECT_EQ(m.v(), 0.5);
    EXPECT_EQ(m.omega(), -0.2);
    EXPECT_EQ(m.header().data_time_ns(), k * s.step_ns());
  }
}

TEST(ConstantCommand, ItsCommandChangesAtTheScheduledStep) {  // parameter_changes (docs/parameters.md)
  ServiceUnderTest s(kConstant +
                     "parameter_changes: [{step: 5, key: v, value: 0.8}, {step: 7, key: driver.omega, value: 0.1}]\n");
  for (int64_t k = 0; k < 10; ++k) {
    s.step(k);
    const auto m = s.published<msg::UnicycleCommand>("r1/cmd");
    EXPECT_EQ(m.v(), k < 5 ? 0.5 : 0.8) << k;
    EXPECT_EQ(m.omega(), k < 7 ? -0.2 : 0.1) << k;
  }
  EXPECT_NE(config_error(kConstant + "parameter_changes: [{step: 5, key: v, value: .nan}]\n", {})
                .find("parameter_changes.0.value: expected a finite number, got '.nan'"),
            std::string::npos);
}

TEST(ConstantCommand, BadParametersAreConfigurationErrors) {
  expect_config_errors(kConstant, {
                                      {"services.driver.v=fast", {"services.driver.v"}},
                                      {"services.driver.omega=[1]", {"services.driver.omega"}},
                                  });
  EXPECT_NE(config_error(R"(name: p
step: 0.01
services:
  driver: {type: constant_command, robot: r1, v: 1}
)",
                         {})
                .find("services.driver.omega: required key is missing"),
            std::string::npos);
}

// --- what the clocks publish, at a consumer's edge ----------------------------------------

TEST(ComponentHostOutputs, PassTheConsumersEdgeCheckAndATamperedOneDoesNot) {
  struct Row {
    std::string doc, signal;
  };
  for (const Row& r : {Row{kFigureEight, "r1/reference"}, Row{kCircle, "r1/reference"},
                       Row{kArmReference, "r4/reference"}, Row{kConstant, "r1/cmd"}}) {
    ServiceUnderTest s(r.doc);
    s.step(3);
    EXPECT_EQ(s.check_output(r.signal), Rejection::none) << r.signal;
    // The same sample with a non-finite or huge first field, as a consumer receives it.
    const auto& spec = *std::find_if(s.scenario().signals.begin(), s.scenario().signals.end(),
                                     [&](const scenario::SignalSpec& x) { return x.name == r.signal; });
    const distributed::WireSignal wire(spec, s.step_ns());
    SignalSample bad = s.sample(r.signal);
    bad.values[0] = kNaN;
    const auto m = wire.make_message();
    wire.encode(bad, m.get());
    SignalSample got;
    std::size_t field = 99;
    EXPECT_EQ(wire.decode(m.get(), got, field), Rejection::non_finite) << r.signal;
    EXPECT_EQ(field, 0u);
    bad.values[0] = 1e13;
    wire.encode(bad, m.get());
    EXPECT_EQ(wire.decode(m.get(), got, field), Rejection::out_of_range) << r.signal;
  }
}

}  // namespace
}  // namespace plexus::services_test
