// Registry entries of the unicycle family (papers 000 and 003; docs/algorithms/unicycle.md).
// The plant is `unicycle` (unicycle_plant_component.cpp). Ports bind to `<robot>/<port>`
// unless remapped; naming the position sensor `position` makes the defaults connect. Each
// output names its IDL type (docs/topics.md).
//
//   position_sensor (sensor)      in truth/state {x, y}; out <sensor name> {x, y} (PositionMeasurement)
//     kind: exact | gaussian | rfid_grid, sigma (m), grid_spacing (m, 0.1),
//     grid_origin_x, grid_origin_y (m, 0); rate and seed are the common keys
//   figure_eight_reference        out reference {x, y, dx, dy, ddx, ddy} (PlanarReference)
//     h1 (m, 5), h2 (rad/s, 0.02), t0 (s, 3 pi / (2 h2): starts at (0, -h1))     000 eq. (51)
//   geometric_path (reference)    in position {x, y}; out path {x, y, h, hx, hy, hxx, hxy, hyy}
//     (PathSample):
//     h and its derivatives at the measured position, and (x, y) a nearby point ON the
//     path (three Gauss-Newton steps p <- p - h grad h / |grad h|^2), for plots and errors
//     shape: circle (center_x, center_y, radius) | line (point_x, point_y, normal_x,
//     normal_y) | ellipse (center_x, center_y, a, b, phi) | polynomial (terms: list of
//     [i, j, c] for c x^i y^j)                                                    003 section 2
//   heading_observer (estimator)  in position {x, y}, cmd {v, omega};
//     out heading {theta, z3, z4, L} (HeadingEstimate)                 000 Thm 1, eqs. (5)-(11)
//     (theta = atan2(z4, z3) made continuous in time, starting in (-pi, pi], so it
//     overlays the plant's continuous theta; L is the gain, for observer_rate_bound)
//     L (required), discretisation: exact_arc | held_position, z3_0, z4_0 (0)
//   velocity_heading_observer     in position {x, y}, cmd {omega};
//     out heading {theta, speed, z2, z4} (HeadingEstimate)             003 Thm 1, eqs. (11)-(14)
//     L2, L4 (required), discretisation, z2_0, z4_0 (0)
//   reference_feedforward (ctl)   in reference; out cmd {v = |p_r'|, omega = heading rate of p_r}
//   trajectory_tracking (ctl)     in reference, and truth/state {x, y, theta} (feedback: state,
//     000 eq. (14)) or position {x, y} + heading {z3, z4} (feedback: output, eqs. (27)-(28));
//     out cmd {v, omega} (UnicycleCommand). k1, k2, k3 (required), gamma (0.9), min_speed_for_turn (1e-3),
//     reference_min_speed (m/s, the reference's lowest speed v_rm: gain condition (15) is
//     checked against it at start; none: not checked)
//   path_following (ctl)          in path, and truth/state {theta} (feedback: state, 003 eq. (5))
//     or heading {z2, z4} (feedback: observer, eqs. (15)-(16)); out cmd {v = u1, omega = u2}
//     u1 (m/s, != 0), k1, k2 (required), min_abs_g (1e-3), max_turn_rate (inf)
//
// Estimators and controllers update when their position input carries a new sample (so a
// slower sensor is handled) and output zeros / their initial estimate until inputs exist.
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <string>

#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include "plexus/algorithms/core/angles.hpp"
#include "plexus/algorithms/unicycle/figure_eight_reference.hpp"
#include "plexus/algorithms/unicycle/geometric_path.hpp"
#include "plexus/algorithms/unicycle/heading_observer.hpp"
#include "plexus/algorithms/unicycle/path_following_controller.hpp"
#include "plexus/algorithms/unicycle/position_sensor.hpp"
#include "plexus/algorithms/unicycle/tracking_controller.hpp"
#include "plexus/algorithms/unicycle/velocity_heading_observer.hpp"
#include "plexus/scenario/registry.hpp"

namespace plexus::scenario {
namespace {

namespace alg = plexus::algorithms;

/// Warnings go to stderr (stdout carries `plexus sim --json`).
spdlog::logger& unicycle_log() {
  static const std::shared_ptr<spdlog::logger> logger = [] {
    auto l = spdlog::get("scenario.unicycle");
    return l ? l : spdlog::stderr_color_mt("scenario.unicycle");
  }();
  return *logger;
}

alg::ObserverDiscretisation discretisation(const YamlMap& p) {
  const auto s = p.optional<std::string>("discretisation", "exact_arc");
  if (s == "exact_arc") return alg::ObserverDiscretisation::kExactArc;
  if (s == "held_position") return alg::ObserverDiscretisation::kHeldPosition;
  p.fail("discretisation", "expected exact_arc or held_position, got '" + s + "'");
}

/// Required key with two allowed values: true for `second`.
bool is_second(const YamlMap& p, const std::string& key, const std::string& first, const std::string& second) {
  const auto s = p.required<std::string>(key);
  if (s != first && s != second) p.fail(key, "expected " + first + " or " + second + ", got '" + s + "'");
  return s == second;
}

Eigen::Vector2d vec2(const InputPort& in) { return {in[0], in[1]}; }

/// A heading estimate made continuous in time (like the plant's theta): each new value is
/// the previous one plus the wrapped change; the first is atan2's value in (-pi, pi].
struct ContinuousHeading {
  double value = 0.0;
  bool started = false;
  double operator()(double wrapped) {
    value = started ? value + alg::wrap_angle(wrapped - value) : wrapped;
    started = true;
    return value;
  }
};

/// New position sample since the last update? Tracks the producer's step.
struct SampleClock {
  int64_t last = -1;
  /// Seconds since the previous sample (0 for the first), or < 0 when nothing new.
  double advance(const InputPort& in, double base_step) {
    const int64_t s = in.sample().step;
    if (s < 0 || s == last) return -1.0;
    const double dt = last < 0 ? 0.0 : static_cast<double>(s - last) * base_step;
    last = s;
    return dt;
  }
};

// ------------------------------------------------------------------------------ sensors

class PositionSensorComponent final : public Component {
 public:
  explicit PositionSensorComponent(const ComponentConfig& c)
      : Component(c), sensor_(params(c)), rng_(sensor_.make_rng()),
        in_(add_input("truth/state", {"x", "y"}, "Pose2D")), out_(add_output(c.key, {"x", "y"}, "PositionMeasurement")) {}

  void step(int64_t /*k*/, double /*t*/) override {
    const Eigen::Vector2d m = sensor_.measure(vec2(in_), rng_);
    out_[0] = m.x();
    out_[1] = m.y();
  }

 private:
  static alg::PositionSensorParams params(const ComponentConfig& c) {
    const YamlMap& p = c.params();
    alg::PositionSensorParams s;
    const auto kind = p.required<std::string>("kind");
    try {
      s.kind = alg::position_sensor_kind_from_string(kind);
    } catch (const std::invalid_argument&) {
      p.fail("kind", "expected exact, gaussian or rfid_grid, got '" + kind + "'");
    }
    if (s.kind == alg::PositionSensorKind::kGaussian) s.sigma = p.required<double>("sigma");
    if (s.kind == alg::PositionSensorKind::kRfidGrid) {
      s.grid_spacing = p.optional<double>("grid_spacing", s.grid_spacing);
      s.grid_origin = {p.optional<double>("grid_origin_x", 0.0), p.optional<double>("grid_origin_y", 0.0)};
    }
    s.rate_hz = 1.0 / c.period();
    s.seed = c.seed;
    return s;
  }

  alg::PositionSensor sensor_;
  alg::Rng rng_;
  InputPort& in_;
  OutputPort& out_;
};

// ------------------------------------------------------------------------------ references

class FigureEightComponent final : public Component {
 public:
  explicit FigureEightComponent(const ComponentConfig& c)
      : Component(c), ref_(params(c.params())), out_(add_output("reference", {"x", "y", "dx", "dy", "ddx", "ddy"}, "PlanarReference")) {}

  void step(int64_t /*k*/, double t) override {
    const alg::ReferenceSample r = ref_.sample(t);
    out_[0] = r.p.x();
    out_[1] = r.p.y();
    out_[2] = r.dp.x();
    out_[3] = r.dp.y();
    out_[4] = r.ddp.x();
    out_[5] = r.ddp.y();
  }

 private:
  static alg::FigureEightParams params(const YamlMap& p) {
    alg::FigureEightParams f;
    f.h1 = p.optional<double>("h1", f.h1);
    f.h2 = p.optional<double>("h2", f.h2);
    if (!(f.h2 > 0.0)) p.fail("h2", "must be > 0 rad/s");
    f.t0 = p.optional<double>("t0", alg::FigureEightParams::paper_t0(f.h2));
    return f;
  }

  alg::FigureEightReference ref_;
  OutputPort& out_;
};

class GeometricPathComponent final : public Component {
 public:
  explicit GeometricPathComponent(const ComponentConfig& c)
      : Component(c), path_(shape(c.params())), in_(add_input("position", {"x", "y"}, "PositionMeasurement")),
        out_(add_output("path", {"x", "y", "h", "hx", "hy", "hxx", "hxy", "hyy"}, "PathSample")) {}

  void step(int64_t /*k*/, double /*t*/) override {
    const Eigen::Vector2d p = vec2(in_);
    const alg::PathEvaluation e = path_.evaluate(p);
    Eigen::Vector2d q = p;  // a point of the path near p: Gauss-Newton on h(q) = 0
    for (int i = 0; i < 3; ++i) {
      const alg::PathEvaluation eq = i == 0 ? e : path_.evaluate(q);
      const double g2 = eq.gradient.squaredNorm();
      if (!(g2 > 1e-12)) break;
      q -= eq.h / g2 * eq.gradient;
    }
    const double v[] = {q.x(), q.y(), e.h, e.gradient.x(), e.gradient.y(), e.hessian(0, 0), e.hessian(0, 1),
                        e.hessian(1, 1)};
    for (std::size_t i = 0; i < 8; ++i) out_[i] = v[i];
  }

 private:
  static alg::PathShape shape(const YamlMap& p) {
    const auto s = p.required<std::string>("shape");
    const auto point = [&](const char* x, const char* y, double dx = 0.0, double dy = 0.0) {
      return Eigen::Vector2d(p.optional<double>(x, dx), p.optional<double>(y, dy));
    };
    if (s == "circle") return alg::CirclePath{point("center_x", "center_y"), p.required<double>("radius")};
    if (s == "line") return alg::LinePath{point("point_x", "point_y"), point("normal_x", "normal_y", 0.0, 1.0)};
    if (s == "ellipse")
      return alg::EllipsePath{point("center_x", "center_y"), p.required<double>("a"), p.required<double>("b"),
                              p.optional<double>("phi", 0.0)};
    if (s == "polynomial") {
      alg::PolynomialPath poly;
      for (const auto& term : p.sequence("terms")) {
        if (!term.IsSequence() || term.size() != 3) p.fail("terms", "each term is [i, j, c] for c x^i y^j");
        const int i = term[0].as<int>(), j = term[1].as<int>();
        if (i < 0 || j < 0 || i + j > alg::PolynomialPath::kMaxDegree)
          p.fail("terms", "powers must be >= 0 with i + j <= " + std::to_string(alg::PolynomialPath::kMaxDegree));
        poly.c(i, j) += term[2].as<double>();
      }
      return poly;
    }
    p.fail("shape", "expected circle, line, ellipse or polynomial, got '" + s + "'");
  }

  alg::GeometricPath path_;
  InputPort& in_;
  OutputPort& out_;
};

// ------------------------------------------------------------------------------ estimators

class HeadingObserverComponent final : public Component {
 public:
  explicit HeadingObserverComponent(const ComponentConfig& c)
      : Component(c),
        obs_({c.params().required<double>("L"), discretisation(c.params())}),
        z0_(c.params().optional<double>("z3_0", 0.0), c.params().optional<double>("z4_0", 0.0)),
        base_step_(c.base_step),
        pos_(add_input("position", {"x", "y"}, "PositionMeasurement")),
        cmd_(add_input("cmd", {"v", "omega"}, "UnicycleCommand")),
        out_(add_output("heading", {"theta", "z3", "z4", "L"}, "HeadingEstimate")) {}

  void step(int64_t /*k*/, double /*t*/) override {
    const double dt = clock_.advance(pos_, base_step_);
    if (dt == 0.0) obs_.reset(z0_, vec2(pos_));  // paper 000: z_hat(0) = (0, 0)
    if (dt > 0.0) obs_.update(dt, vec2(pos_), {cmd_.valid() ? cmd_[0] : 0.0, cmd_.valid() ? cmd_[1] : 0.0});
    const Eigen::Vector2d z = obs_.state().has_position ? obs_.state().z_hat : z0_;
    out_[0] = heading_(std::atan2(z.y(), z.x()));  // eq. (11), made continuous
    out_[1] = z.x();
    out_[2] = z.y();
    out_[3] = obs_.params().L;
  }

 private:
  alg::HeadingObserver obs_;
  Eigen::Vector2d z0_;
  double base_step_;
  SampleClock clock_;
  ContinuousHeading heading_;
  InputPort& pos_;
  InputPort& cmd_;
  OutputPort& out_;
};

class VelocityHeadingObserverComponent final : public Component {
 public:
  explicit VelocityHeadingObserverComponent(const ComponentConfig& c)
      : Component(c),
        obs_({c.params().required<double>("L2"), c.params().required<double>("L4"), discretisation(c.params())}),
        z0_(c.params().optional<double>("z2_0", 0.0), c.params().optional<double>("z4_0", 0.0)),
        base_step_(c.base_step),
        pos_(add_input("position", {"x", "y"}, "PositionMeasurement")),
        cmd_(add_input("cmd", {"omega"}, "UnicycleCommand")),
        out_(add_output("heading", {"theta", "speed", "z2", "z4"}, "HeadingEstimate")) {}

  void step(int64_t /*k*/, double /*t*/) override {
    const double dt = clock_.advance(pos_, base_step_);
    if (dt == 0.0) obs_.reset(z0_, vec2(pos_));
    if (dt > 0.0) obs_.update(dt, vec2(pos_), cmd_.valid() ? cmd_[0] : 0.0);
    const Eigen::Vector2d z = obs_.state().has_position ? obs_.state().z_hat : z0_;
    out_[0] = heading_(std::atan2(z.y(), z.x()));  // eq. (14), made continuous
    out_[1] = z.norm();
    out_[2] = z.x();
    out_[3] = z.y();
  }

 private:
  alg::VelocityHeadingObserver obs_;
  Eigen::Vector2d z0_;
  double base_step_;
  SampleClock clock_;
  ContinuousHeading heading_;
  InputPort& pos_;
  InputPort& cmd_;
  OutputPort& out_;
};

// ------------------------------------------------------------------------------ controllers

alg::ReferenceSample reference_sample(const InputPort& in) {
  alg::ReferenceSample r;
  r.p = {in[0], in[1]};
  r.dp = {in[2], in[3]};
  r.ddp = {in[4], in[5]};
  return r;
}

const std::vector<std::string> kReferenceFields{"x", "y", "dx", "dy", "ddx", "ddy"};

/// Open loop along the reference: v = |p_r'|, omega = (x_r' y_r'' - y_r' x_r'') / v^2
/// (paper 000 section 6.1 drives the observer-only run with v = v_r, omega = theta_r').
class ReferenceFeedforward final : public Component {
 public:
  explicit ReferenceFeedforward(const ComponentConfig& c)
      : Component(c), ref_(add_input("reference", kReferenceFields, "PlanarReference")), out_(add_output("cmd", {"v", "omega"}, "UnicycleCommand")) {}

  void step(int64_t /*k*/, double /*t*/) override {
    const alg::ReferenceSample r = reference_sample(ref_);
    const double v2 = r.dp.squaredNorm();
    out_[0] = std::sqrt(v2);
    out_[1] = v2 > 0.0 ? (r.dp.x() * r.ddp.y() - r.dp.y() * r.ddp.x()) / v2 : 0.0;
  }

 private:
  InputPort& ref_;
  OutputPort& out_;
};

class TrajectoryTrackingComponent final : public Component {
 public:
  explicit TrajectoryTrackingComponent(const ComponentConfig& c)
      : Component(c),
        output_feedback_(is_second(c.params(), "feedback", "state", "output")),
        ctl_(params(c.params())),
        ref_(add_input("reference", kReferenceFields, "PlanarReference")),
        pos_(add_input(output_feedback_ ? "position" : "truth/state",
                       output_feedback_ ? std::vector<std::string>{"x", "y"}
                                        : std::vector<std::string>{"x", "y", "theta"},
                       output_feedback_ ? "PositionMeasurement" : "Pose2D")),
        est_(output_feedback_ ? &add_input("heading", {"z3", "z4"}, "HeadingEstimate") : nullptr),
        out_(add_output("cmd", {"v", "omega"}, "UnicycleCommand")) {
    check_gain_condition(c);
  }

  void step(int64_t /*k*/, double /*t*/) override {
    alg::UnicycleInput u;
    if (ref_.valid() && pos_.valid() && (!est_ || est_->valid())) {
      const alg::ReferenceSample r = reference_sample(ref_);
      u = output_feedback_ ? ctl_.output_feedback(r, vec2(pos_), vec2(*est_)).input  // 000 eqs. (27)-(28)
                           : ctl_.state_feedback(r, {pos_[0], pos_[1], pos_[2]}).input;  // 000 eq. (14)
    }
    out_[0] = u.v;
    out_[1] = u.omega;
  }

 private:
  static alg::TrackingControllerParams params(const YamlMap& p) {
    alg::TrackingControllerParams t;
    t.k1 = p.required<double>("k1");
    t.k2 = p.required<double>("k2");
    t.k3 = p.required<double>("k3");
    t.gamma = p.optional<double>("gamma", t.gamma);
    t.min_speed_for_turn = p.optional<double>("min_speed_for_turn", t.min_speed_for_turn);
    return t;
  }

  /// Gain condition (15) of paper 000 against the configured reference: one warning, here.
  void check_gain_condition(const ComponentConfig& c) const {
    std::optional<double> v_rm;
    if (c.params().has("reference_min_speed")) {
      v_rm = c.params().required<double>("reference_min_speed");
      if (!(*v_rm > 0.0)) c.params().fail("reference_min_speed", "must be > 0 m/s");
    }
    if (!v_rm) {
      unicycle_log().info("{}: gain condition (15) of paper 000 not checked: set reference_min_speed (m/s), the "
                          "lowest speed of the reference {} (a figure-eight's: h1 h2 sqrt(31) / 8)",
                          c.name, ref_.signal());
      return;
    }
    if (const auto warning = alg::check_gain_condition(ctl_.params(), *v_rm))
      c.warn(c.name + " (reference " + ref_.signal() + "): " + *warning);  // logged once the scenario is valid
  }

  bool output_feedback_;
  alg::TrajectoryTrackingController ctl_;
  InputPort& ref_;
  InputPort& pos_;
  InputPort* est_;
  OutputPort& out_;
};

class PathFollowingComponent final : public Component {
 public:
  explicit PathFollowingComponent(const ComponentConfig& c)
      : Component(c),
        observer_(is_second(c.params(), "feedback", "state", "observer")),
        u1_(c.params().required<double>("u1")),
        ctl_(params(c.params())),
        path_(add_input("path", {"h", "hx", "hy", "hxx", "hxy", "hyy"}, "PathSample")),
        vel_(observer_ ? add_input("heading", {"z2", "z4"}, "HeadingEstimate") : add_input("truth/state", {"theta"}, "Pose2D")),
        out_(add_output("cmd", {"v", "omega"}, "UnicycleCommand")) {
    if (!(std::isfinite(u1_) && u1_ != 0.0)) c.params().fail("u1", "must be finite and != 0 m/s");
  }

  void step(int64_t /*k*/, double /*t*/) override {
    double u2 = 0.0;
    if (path_.valid() && vel_.valid()) {
      alg::PathEvaluation e;
      e.h = path_[0];
      e.gradient = {path_[1], path_[2]};
      e.hessian << path_[3], path_[4], path_[4], path_[5];
      // State feedback (003 eq. (5)): w = u1 (cos theta, sin theta); observer-based
      // (eqs. (15)-(16)): w = z_hat.
      const Eigen::Vector2d w =
          observer_ ? vec2(vel_) : Eigen::Vector2d(u1_ * std::cos(vel_[0]), u1_ * std::sin(vel_[0]));
      u2 = ctl_.compute(e, w).u2;
    }
    out_[0] = u1_;
    out_[1] = u2;
  }

 private:
  static alg::PathFollowingParams params(const YamlMap& p) {
    alg::PathFollowingParams f;
    f.k1 = p.required<double>("k1");
    f.k2 = p.required<double>("k2");
    f.min_abs_g = p.optional<double>("min_abs_g", f.min_abs_g);
    f.max_turn_rate = p.optional<double>("max_turn_rate", f.max_turn_rate);
    return f;
  }

  bool observer_;
  double u1_;
  alg::PathFollowingController ctl_;
  InputPort& path_;
  InputPort& vel_;
  OutputPort& out_;
};

template <class T>
ComponentFactory make() {
  return [](const ComponentConfig& c) { return std::make_unique<T>(c); };
}

const ComponentRegistration kPositionSensor{"position_sensor", ComponentKind::sensor,
                                            "position {x, y}: exact, Gaussian or RFID grid (paper 000 6.3.2)",
                                            make<PositionSensorComponent>()};
const ComponentRegistration kFigureEight{"figure_eight_reference", ComponentKind::reference,
                                         "figure-eight h1 sin(2 h2 (t+t0)), h1 sin(h2 (t+t0)) (paper 000 eq. (51))",
                                         make<FigureEightComponent>()};
const ComponentRegistration kGeometricPath{"geometric_path", ComponentKind::reference,
                                           "path h(x, y) = 0 and its derivatives at the position (paper 003)",
                                           make<GeometricPathComponent>()};
const ComponentRegistration kHeadingObserver{"heading_observer", ComponentKind::estimator,
                                             "reduced-order heading observer from positions (paper 000 Thm 1)",
                                             make<HeadingObserverComponent>()};
const ComponentRegistration kVelocityObserver{"velocity_heading_observer", ComponentKind::estimator,
                                              "velocity and heading observer from positions (paper 003 Thm 1)",
                                              make<VelocityHeadingObserverComponent>()};
const ComponentRegistration kFeedforward{"reference_feedforward", ComponentKind::controller,
                                         "open loop along the reference: v = |p_r'|, omega = its heading rate",
                                         make<ReferenceFeedforward>()};
const ComponentRegistration kTracking{"trajectory_tracking", ComponentKind::controller,
                                      "state / output-feedback trajectory tracking (paper 000 eqs. (14), (27)-(28))",
                                      make<TrajectoryTrackingComponent>()};
const ComponentRegistration kPathFollowing{"path_following", ComponentKind::controller,
                                           "state-feedback / observer-based path following (paper 003 eqs. (5), (15))",
                                           make<PathFollowingComponent>()};

}  // namespace
}  // namespace plexus::scenario
