// The balancing robot's sensors (sensor; plant_simulator; paper 002 section 4.1,
// docs/algorithms/balancing.md). Angles travel in rad and rad/s; YAML keys with _degps /
// _degps2 are in degrees, as in the paper's Table 1. The scenarios name them imu and
// odometry, the consumers' default ports.
//
//   balancing_imu   in truth/state {theta, theta_dot, x_ddot, theta_ddot}; out <sensor name>
//     {gyro, acc_x, acc_z} (Imu: gyro about the wheel axis y, accelerometer x and z);
//     gravity (9.81, as the plant's)
//     gyro_noise_degps (0.5), gyro_range_degps (150), gamma1 (1/s, -0.01), gamma2_degps2 (0),
//     drift_noise_psd (rad^2/s^3, 1e-6), initial_drift_degps (0.5), accel_noise (m/s^2,
//     0.0343), accel_height (m, 0.12), accel_range (m/s^2, 19.62)
//   wheel_odometry  in truth/state {x, v}; out <sensor name> {x, v} (TravelState: the
//     wheel encoders' travel and speed); noise_std (m and m/s, 0)
#include <memory>

#include "plexus/algorithms/balancing/imu_sensor.hpp"
#include "plexus/algorithms/balancing/wheeled_inverted_pendulum.hpp"
#include "plexus/algorithms/core/random.hpp"
#include "plexus/scenario/params.hpp"
#include "plexus/scenario/registry.hpp"

namespace plexus::scenario {
namespace {

namespace alg = plexus::algorithms;

struct ImuInfo {
  alg::GyroParams gyro;
  alg::AccelerometerParams acc;
};

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

class BalancingImuComponent final : public Component {
 public:
  explicit BalancingImuComponent(const ComponentConfig& c)
      : Component(c),
        info_(imu_params(c.params())),
        imu_(info_.gyro, info_.acc, c.params().optional<double>("gravity", alg::WheeledPendulumParams{}.gravity),
             c.seed),
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

const ComponentRegistration kBalancingImu{
    "balancing_imu", ComponentKind::sensor,
    "gyro with drift and saturation + 2-axis accelerometer tilt (paper 002 section 4.1); out {gyro, acc_x, acc_z}",
    [](const ComponentConfig& c) { return std::make_unique<BalancingImuComponent>(c); }};
const ComponentRegistration kBalancingOdometry{
    "wheel_odometry", ComponentKind::sensor, "wheel encoders: travel and speed {x, v} with optional noise",
    [](const ComponentConfig& c) { return std::make_unique<WheelOdometryComponent>(c); }};

}  // namespace
}  // namespace plexus::scenario
