// attitude_filter (estimator; attitude_filter): the tilt / tilt rate / gyro-drift filter
// of the balancing robot, UKF (augmented, additive) or EKF (paper 002;
// docs/algorithms/balancing.md). Angles travel in rad and rad/s; YAML keys with _deg /
// _degps / _degps2 are in degrees, as in the paper's Table 1. Ports bind to
// `<robot>/<port>` unless remapped; the output names its IDL type (docs/topics.md).
//
//   in imu {acc_x, acc_z, gyro} (Imu), cmd {torque} (WheelTorqueCommand); out attitude
//     {theta, theta_dot, drift, theta_std} (AttitudeEstimate; remap `attitude` to run a
//     second filter beside it).
//   filter: ukf_augmented | ukf_additive | ekf;
//   measurement: observable (default) | paper; process_model: nonlinear (default) | linear;
//   q_theta_deg (0.2), q_rate_degps (0.05), q_drift_degps (0.3), r_tilt_deg (0.2),
//   r_gyro_degps (0.5), initial_theta_std_deg (0.5), initial_rate_std_degps (1),
//   initial_drift_std_degps (1), alpha (1), beta (2), kappa (0).
//   It runs one cycle per new IMU sample with dt = the IMU's period, imu_rate (Hz, default
//   its own rate; run it at the IMU's rate or faster). Sample times (realtime;
//   docs/distributed.md, "Late samples"): the realtime host runs each step once its IMU
//   sample has arrived; a sample that never came in time (a newer one arrived first) is
//   bridged by a prediction over its period with the held torque before the newer sample's
//   cycle, so the filter's time stays the samples' (gaps counts the periods bridged). Its model is its own parameters,
//   with the plant's and the sensor's key names and defaults: body_mass, com_height, body_inertia, wheel_mass,
//   wheel_radius, wheel_inertia, gravity, max_torque, and the IMU's gamma1, gamma2_degps2, gyro_range_degps,
//   accel_height.
#include <cmath>
#include <memory>

#include "plexus/algorithms/balancing/attitude_filter.hpp"
#include "plexus/algorithms/balancing/imu_sensor.hpp"
#include "plexus/algorithms/balancing/wheeled_inverted_pendulum.hpp"
#include "plexus/scenario/params.hpp"
#include "plexus/scenario/registry.hpp"
#include "services/common/balancing_params.hpp"

namespace plexus::scenario {
namespace {

namespace alg = plexus::algorithms;

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

class AttitudeFilterComponent final : public Component {
 public:
  explicit AttitudeFilterComponent(const ComponentConfig& c)
      : Component(c),
        imu_(add_input("imu", {"acc_x", "acc_z", "gyro"}, "Imu")),
        cmd_(add_input("cmd", {"torque"}, "WheelTorqueCommand")),
        out_(add_output("attitude", {"theta", "theta_dot", "drift", "theta_std"}, "AttitudeEstimate")),
        filter_(params(c)),
        base_step_(c.base_step),
        imu_dt_(imu_period(c)) {}

  uint64_t dropped_late_samples() const override { return gaps_; }

  void step(int64_t /*k*/, double /*t*/) override {
    // Runs at its own rate; the torque is the command held since the previous step (k-1).
    if (imu_.valid() && imu_.sample().step != last_imu_step_) {
      // IMU periods between the previous sample and this one that brought no sample (0 in
      // `plexus sim` and lockstep): predicted over, then this sample's cycle.
      if (last_imu_step_ >= 0) {
        const auto missed =
            std::llround(static_cast<double>(imu_.sample().step - last_imu_step_) * base_step_ / imu_dt_) - 1;
        for (long long i = 0; i < missed; ++i) filter_.predict(cmd_.valid() ? cmd_[0] : 0.0);
        if (missed > 0) gaps_ += static_cast<uint64_t>(missed);
      }
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
  double base_step_;
  double imu_dt_;
  uint64_t gaps_ = 0;  ///< IMU periods with no sample, bridged by a prediction
};

const ComponentRegistration kFilter{
    "attitude_filter", ComponentKind::estimator,
    "tilt / rate / gyro-drift UKF (augmented, additive) or EKF (paper 002); out attitude {theta, theta_dot, drift, "
    "theta_std}",
    [](const ComponentConfig& c) { return std::make_unique<AttitudeFilterComponent>(c); }};

}  // namespace
}  // namespace plexus::scenario
