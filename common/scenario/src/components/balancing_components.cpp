// Registry entries of the balancing family (paper 002; docs/algorithms/balancing.md).
// Angles travel in rad and rad/s; YAML keys with _deg / _degps are in degrees, as in the
// paper's Table 1.
//
//   wheeled_inverted_pendulum (plant)  in cmd {torque} (WheelTorqueCommand); out truth/state
//     {x, v, theta, theta_dot, x_ddot, theta_ddot} (BalancingTruth). body_mass, com_height, body_inertia, wheel_mass, wheel_radius,
//     wheel_inertia, gravity, max_torque (WheeledPendulumParams defaults), theta0_deg (0),
//     torque_noise_std (N m, 0: actuation noise drawn from the plant's seed), substeps (4, RK4)
//   balancing_imu (sensor)  in truth/state; out <sensor name> {gyro, acc_x, acc_z} (Imu: gyro
//     about the wheel axis y, accelerometer x and z); gravity (9.81, as the plant's)
//     gyro_noise_degps (0.5), gyro_range_degps (150), gamma1 (1/s, -0.01), gamma2_degps2 (0),
//     drift_noise_psd (rad^2/s^3, 1e-6), initial_drift_degps (0.5), accel_noise (m/s^2,
//     0.0343), accel_height (m, 0.12), accel_range (m/s^2, 19.62)
//   wheel_odometry (sensor)  in truth/state {x, v}; out <sensor name> {x, v} (TravelState: the
//     wheel encoders' travel and speed); noise_std (m and m/s, 0)
//   motion_profile (reference)  out reference {x, v} (TravelState): hold_time (1), ramp_time
//     (1.5), speed (0.3)
//   attitude_filter (estimator)  in imu {acc_x, acc_z, gyro}, cmd {torque}; out attitude
//     {theta, theta_dot, drift, theta_std} (AttitudeEstimate; remap `attitude` to run a
//     second filter beside it). filter: ukf_augmented | ukf_additive | ekf;
//     measurement: observable (default) | paper; process_model: nonlinear (default) | linear;
//     q_theta_deg (0.2), q_rate_degps (0.05), q_drift_degps (0.3), r_tilt_deg (0.2),
//     r_gyro_degps (0.5), initial_theta_std_deg (0.5), initial_rate_std_degps (1),
//     initial_drift_std_degps (1), alpha (1), beta (2), kappa (0).
//     It runs one cycle per new IMU sample with dt = the IMU's period, imu_rate (Hz, default
//     its own rate; run it at the IMU's rate or faster). Its model is its own parameters, with
//     the plant's and the sensor's key names and defaults: body_mass, com_height,
//     body_inertia, wheel_mass, wheel_radius, wheel_inertia, gravity, max_torque, and the
//     IMU's gamma1, gamma2_degps2, gyro_range_degps, accel_height.
//   balancing_controller (controller)  in odometry {x, v} (wheel encoders), attitude {theta,
//     theta_dot}, reference {x, v}; out cmd {torque} (WheelTorqueCommand). poles (list of 4,
//     [-2, -3, -9, -10]); its model: the plant's keys (body_mass .. max_torque), same defaults.
#include <cmath>
#include <map>
#include <memory>
#include <numbers>
#include <string>

#include "plexus/algorithms/balancing/attitude_filter.hpp"
#include "plexus/algorithms/balancing/balancing_controller.hpp"
#include "plexus/algorithms/balancing/imu_sensor.hpp"
#include "plexus/algorithms/balancing/wheeled_inverted_pendulum.hpp"
#include "plexus/algorithms/core/random.hpp"
#include "plexus/scenario/params.hpp"
#include "plexus/scenario/registry.hpp"

namespace plexus::scenario {
namespace {

namespace alg = plexus::algorithms;
constexpr double kRad = std::numbers::pi / 180.0;

struct ImuInfo {
  alg::GyroParams gyro;
  alg::AccelerometerParams acc;
};

/// Optional angle-like key given in degrees (deg, deg/s, deg/s^2), returned in radians;
/// exactly `fallback_rad` when absent. `min` is "> 0", ">= 0" or "" (any finite value).
double degrees(const YamlMap& p, const std::string& key, double fallback_rad, const std::string& min = "") {
  if (!p.has(key)) return fallback_rad;
  const double v = p.required<double>(key);
  const bool ok = std::isfinite(v) && (min == "> 0" ? v > 0.0 : min == ">= 0" ? v >= 0.0 : true);
  if (!ok) p.fail(key, "must be finite" + (min.empty() ? std::string() : " and " + min) + " (got " + std::to_string(v) + ")");
  return v * kRad;
}

std::string choice(const YamlMap& p, const std::string& key, const std::string& fallback,
                   std::initializer_list<const char*> allowed) {
  const auto s = p.optional<std::string>(key, fallback);
  std::string list;
  for (const char* a : allowed) {
    if (s == a) return s;
    list += list.empty() ? a : std::string(", ") + a;
  }
  p.fail(key, "expected one of " + list + ", got '" + s + "'");
}

// ------------------------------------------------------------------------------ plant

alg::WheeledPendulumParams pendulum_params(const YamlMap& p) {
  alg::WheeledPendulumParams w;
  w.body_mass = p.optional<double>("body_mass", w.body_mass);
  w.com_height = p.optional<double>("com_height", w.com_height);
  w.body_inertia = p.optional<double>("body_inertia", w.body_inertia);
  w.wheel_mass = p.optional<double>("wheel_mass", w.wheel_mass);
  w.wheel_radius = p.optional<double>("wheel_radius", w.wheel_radius);
  w.wheel_inertia = p.optional<double>("wheel_inertia", w.wheel_inertia);
  w.gravity = p.optional<double>("gravity", w.gravity);
  w.max_torque = p.optional<double>("max_torque", w.max_torque);
  return w;
}

class PendulumPlantComponent final : public Component {
 public:
  explicit PendulumPlantComponent(const ComponentConfig& c)
      : Component(c),
        plant_(pendulum_params(c.params())),
        h_(c.period()),
        torque_noise_(optional_non_negative(c.params(), "torque_noise_std")),
        substeps_(c.params().optional<int>("substeps", 4)),
        rng_(c.seed),
        cmd_(add_input("cmd", {"torque"}, "WheelTorqueCommand")),
        out_(add_output("truth/state", {"x", "v", "theta", "theta_dot", "x_ddot", "theta_ddot"}, "BalancingTruth")) {
    if (substeps_ < 1) c.params().fail("substeps", "must be >= 1");
    state_.theta = degrees(c.params(), "theta0_deg", 0.0);
    acc_ = plant_.accelerations(state_, 0.0);
  }

  void step(int64_t k, double /*t*/) override {
    if (k > 0) {
      double T = cmd_.valid() ? cmd_[0] : 0.0;
      if (torque_noise_ > 0.0) T += torque_noise_ * rng_.normal();
      acc_ = plant_.step(state_, T, h_, substeps_);
    }
    out_[0] = state_.x;
    out_[1] = state_.v;
    out_[2] = state_.theta;
    out_[3] = state_.theta_dot;
    out_[4] = acc_.x_ddot;
    out_[5] = acc_.theta_ddot;
  }

 private:
  alg::WheeledInvertedPendulum plant_;
  double h_;
  double torque_noise_;
  int substeps_;
  alg::Rng rng_;
  alg::WheeledPendulumState state_;
  alg::WheeledPendulumAccelerations acc_;
  InputPort& cmd_;
  OutputPort& out_;
};

// ------------------------------------------------------------------------------ sensor

ImuInfo imu_params(const YamlMap& p) {
  ImuInfo i;
  i.gyro.noise_std = degrees(p, "gyro_noise_degps", i.gyro.noise_std, ">= 0");
  i.gyro.range = degrees(p, "gyro_range_degps", i.gyro.range, "> 0");
  i.gyro.gamma1 = p.optional<double>("gamma1", i.gyro.gamma1);
  i.gyro.gamma2 = degrees(p, "gamma2_degps2", i.gyro.gamma2);
  i.gyro.drift_noise_psd = p.optional<double>("drift_noise_psd", i.gyro.drift_noise_psd);
  i.gyro.initial_drift = degrees(p, "initial_drift_degps", i.gyro.initial_drift);
  i.acc.noise_std = p.optional<double>("accel_noise", i.acc.noise_std);
  i.acc.height = p.optional<double>("accel_height", i.acc.height);
  i.acc.range = p.optional<double>("accel_range", i.acc.range);
  return i;
}

/// The IMU's sample period as a filter sees it: `imu_rate` (Hz, a divisor of the base rate),
/// default the filter's own rate. Computed as the sensor computes its period (whole base steps).
double imu_period(const ComponentConfig& c) {
  if (!c.params().has("imu_rate")) return c.period();
  const double rate = c.params().required<double>("imu_rate");
  const double steps = std::round(1.0 / (rate * c.base_step));
  if (!(rate > 0.0) || steps < 1.0 || std::abs(1.0 / (rate * c.base_step) - steps) > 1e-6 * steps)
    c.params().fail("imu_rate", "must be > 0 Hz and divide the base rate");
  return static_cast<double>(static_cast<int64_t>(steps)) * c.base_step;
}

class BalancingImuComponent final : public Component {
 public:
  explicit BalancingImuComponent(const ComponentConfig& c)
      : Component(c),
        info_(imu_params(c.params())),
        imu_(info_.gyro, info_.acc, c.params().optional<double>("gravity", alg::WheeledPendulumParams{}.gravity), c.seed),
        dt_(c.period()),
        in_(add_input("truth/state", {"theta", "theta_dot", "x_ddot", "theta_ddot"}, "BalancingTruth")),
        out_(add_output(c.key, {"gyro", "acc_x", "acc_z"}, "Imu")) {}

  void step(int64_t /*k*/, double /*t*/) override {
    alg::WheeledPendulumState s;
    s.theta = in_[0];
    s.theta_dot = in_[1];
    const alg::ImuSample m = imu_.measure(s, {in_[2], in_[3]}, dt_);
    out_[0] = m.gyro;
    out_[1] = m.acc_x;
    out_[2] = m.acc_z;
  }

 private:
  ImuInfo info_;
  alg::ImuSensor imu_;
  double dt_;
  InputPort& in_;
  OutputPort& out_;
};

// ------------------------------------------------------------------------------ reference

/// The wheel encoders: travel x and speed v, with optional Gaussian noise.
class WheelOdometryComponent final : public Component {
 public:
  explicit WheelOdometryComponent(const ComponentConfig& c)
      : Component(c),
        noise_std_(optional_non_negative(c.params(), "noise_std")),
        rng_(c.seed),
        in_(add_input("truth/state", {"x", "v"}, "BalancingTruth")),
        out_(add_output(c.key, {"x", "v"}, "TravelState")) {}

  void step(int64_t /*k*/, double /*t*/) override {
    for (std::size_t i = 0; i < 2; ++i) out_[i] = noise_std_ > 0.0 ? in_[i] + noise_std_ * rng_.normal() : in_[i];
  }

 private:
  double noise_std_;
  alg::Rng rng_;
  InputPort& in_;
  OutputPort& out_;
};

class MotionProfileComponent final : public Component {
 public:
  explicit MotionProfileComponent(const ComponentConfig& c)
      : Component(c), profile_(params(c.params())), out_(add_output("reference", {"x", "v"}, "TravelState")) {}

  void step(int64_t /*k*/, double t) override {
    const alg::MotionReference r = profile_.sample(t);
    out_[0] = r.x;
    out_[1] = r.v;
  }

 private:
  static alg::MotionProfileParams params(const YamlMap& p) {
    alg::MotionProfileParams m;
    m.hold_time = p.optional<double>("hold_time", m.hold_time);
    m.ramp_time = p.optional<double>("ramp_time", m.ramp_time);
    m.speed = p.optional<double>("speed", m.speed);
    return m;
  }

  alg::MotionProfile profile_;
  OutputPort& out_;
};

// ------------------------------------------------------------------------------ estimator

class AttitudeFilterComponent final : public Component {
 public:
  explicit AttitudeFilterComponent(const ComponentConfig& c)
      : Component(c),
        imu_(add_input("imu", {"acc_x", "acc_z", "gyro"}, "Imu")),
        cmd_(add_input("cmd", {"torque"}, "WheelTorqueCommand")),
        out_(add_output("attitude", {"theta", "theta_dot", "drift", "theta_std"}, "AttitudeEstimate")),
        filter_(params(c)) {}

  void step(int64_t /*k*/, double /*t*/) override {
    // Runs at its own rate; the torque is the command held since the previous step (k-1).
    if (imu_.valid() && imu_.sample().step != last_imu_step_) {
      last_imu_step_ = imu_.sample().step;
      // The accelerometer's tilt, atan2(-f_x, f_z), as ImuSensor defines it (paper 002 section 4.1).
      filter_.step(cmd_.valid() ? cmd_[0] : 0.0, std::atan2(-imu_[0], imu_[1]), imu_[2]);
    }
    const auto& x = filter_.state();
    out_[0] = x(0);
    out_[1] = x(1);
    out_[2] = x(2);
    out_[3] = std::sqrt(filter_.covariance()(0, 0));
  }

 private:
  static alg::AttitudeFilterParams params(const ComponentConfig& c) {
    const YamlMap& p = c.params();
    alg::AttitudeFilterParams f;
    const auto kind = choice(p, "filter", "ukf_augmented", {"ukf_augmented", "ukf_additive", "ekf"});
    f.kind = kind == "ekf"            ? alg::AttitudeFilterKind::kEkf
             : kind == "ukf_additive" ? alg::AttitudeFilterKind::kUkfAdditive
                                      : alg::AttitudeFilterKind::kUkfAugmented;
    f.measurement = choice(p, "measurement", "observable", {"observable", "paper"}) == "paper"
                        ? alg::AttitudeMeasurementForm::kPaper
                        : alg::AttitudeMeasurementForm::kObservable;
    f.model.process = choice(p, "process_model", "nonlinear", {"nonlinear", "linear"}) == "linear"
                          ? alg::AttitudeProcessModel::kLinear
                          : alg::AttitudeProcessModel::kNonlinear;
    // The filter's model is its own parameters (the robot's and the IMU's keys, same names
    // and defaults as the plant and the balancing_imu sensor): it runs without them.
    const alg::WheeledPendulumParams plant = pendulum_params(p);
    f.model.coefficients = alg::WheeledInvertedPendulum(plant).coefficients();
    f.model.gravity = plant.gravity;
    const alg::GyroParams gyro;
    const alg::AccelerometerParams acc;
    f.model.gamma1 = p.optional<double>("gamma1", gyro.gamma1);
    f.model.gamma2 = degrees(p, "gamma2_degps2", gyro.gamma2);
    f.model.gyro_range = degrees(p, "gyro_range_degps", gyro.range, "> 0");
    f.model.accelerometer_height = p.optional<double>("accel_height", acc.height);
    f.model.dt = imu_period(c);  // one filter cycle per IMU sample
    f.q_theta = degrees(p, "q_theta_deg", f.q_theta, ">= 0");
    f.q_rate = degrees(p, "q_rate_degps", f.q_rate, ">= 0");
    f.q_drift = degrees(p, "q_drift_degps", f.q_drift, ">= 0");
    f.r_tilt = degrees(p, "r_tilt_deg", f.r_tilt, "> 0");
    f.r_gyro = degrees(p, "r_gyro_degps", f.r_gyro, "> 0");
    f.initial_theta_std = degrees(p, "initial_theta_std_deg", f.initial_theta_std, "> 0");
    f.initial_rate_std = degrees(p, "initial_rate_std_degps", f.initial_rate_std, "> 0");
    f.initial_drift_std = degrees(p, "initial_drift_std_degps", f.initial_drift_std, "> 0");
    f.sigma.alpha = p.optional<double>("alpha", f.sigma.alpha);
    f.sigma.beta = p.optional<double>("beta", f.sigma.beta);
    f.sigma.kappa = p.optional<double>("kappa", f.sigma.kappa);
    return f;
  }

  InputPort& imu_;
  InputPort& cmd_;
  OutputPort& out_;
  alg::AttitudeFilter filter_;
  int64_t last_imu_step_ = -1;
};

// ------------------------------------------------------------------------------ controller

alg::BalancingControllerParams controller_params(const YamlMap& p) {
  alg::BalancingControllerParams b;
  if (p.has("poles")) {
    const auto poles = p.sequence("poles");
    if (poles.size() != 4) p.fail("poles", "must list 4 poles, got " + std::to_string(poles.size()));
    for (std::size_t i = 0; i < 4; ++i) b.poles[i] = poles[i].as<double>();
  }
  return b;
}

class BalancingControllerComponent final : public Component {
 public:
  explicit BalancingControllerComponent(const ComponentConfig& c)
      : Component(c),
        plant_(pendulum_params(c.params())),  // its model: the robot's keys, as the plant reads them
        ctl_(controller_params(c.params()), plant_),
        state_(add_input("odometry", {"x", "v"}, "TravelState")),
        est_(add_input("attitude", {"theta", "theta_dot"}, "AttitudeEstimate")),
        ref_(add_input("reference", {"x", "v"}, "TravelState")),
        out_(add_output("cmd", {"torque"}, "WheelTorqueCommand")) {}

  void step(int64_t /*k*/, double /*t*/) override {
    const alg::MotionReference r{ref_[0], ref_[1]};
    out_[0] = est_.valid() ? ctl_.torque(state_[0], state_[1], est_[0], est_[1], r) : 0.0;
  }

 private:
  alg::WheeledInvertedPendulum plant_;
  alg::BalancingController ctl_;
  InputPort& state_;
  InputPort& est_;
  InputPort& ref_;
  OutputPort& out_;
};

const ComponentRegistration kPlant{
    "wheeled_inverted_pendulum", ComponentKind::plant,
    "two-wheeled balancing robot (paper 002 eq. (10)); in cmd {torque}, out truth/state {x, v, theta, theta_dot, x_ddot, theta_ddot}",
    [](const ComponentConfig& c) { return std::make_unique<PendulumPlantComponent>(c); }};
const ComponentRegistration kImu{
    "balancing_imu", ComponentKind::sensor,
    "gyro with drift and saturation + 2-axis accelerometer tilt (paper 002 section 4.1); out {gyro, acc_x, acc_z}",
    [](const ComponentConfig& c) { return std::make_unique<BalancingImuComponent>(c); }};
const ComponentRegistration kOdometry{
    "wheel_odometry", ComponentKind::sensor, "wheel encoders: travel and speed {x, v} with optional noise",
    [](const ComponentConfig& c) { return std::make_unique<WheelOdometryComponent>(c); }};
const ComponentRegistration kProfile{
    "motion_profile", ComponentKind::reference, "balance, then ramp to a speed; out reference {x, v}",
    [](const ComponentConfig& c) { return std::make_unique<MotionProfileComponent>(c); }};
const ComponentRegistration kFilter{
    "attitude_filter", ComponentKind::estimator,
    "tilt / rate / gyro-drift UKF (augmented, additive) or EKF (paper 002); out attitude {theta, theta_dot, drift, theta_std}",
    [](const ComponentConfig& c) { return std::make_unique<AttitudeFilterComponent>(c); }};
const ComponentRegistration kController{
    "balancing_controller", ComponentKind::controller,
    "pole-placement state feedback on the estimated attitude + encoders; out cmd {torque}",
    [](const ComponentConfig& c) { return std::make_unique<BalancingControllerComponent>(c); }};

}  // namespace
}  // namespace plexus::scenario
