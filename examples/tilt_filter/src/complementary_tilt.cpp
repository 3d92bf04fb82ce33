// complementary_tilt (estimator): the tilt of a balancing robot from its IMU,
//   theta_k = a (theta_{k-1} + gyro_k dt) + (1 - a) atan2(-f_x, f_z),   a = tau / (tau + dt),
// with dt the time between two IMU samples, taken from the samples' own steps (so a late or
// missed sample is integrated over the time it really covers). The accelerometer's tilt
// convention is the balancing_imu sensor's (plexus docs/topics.md, Imu).
//
//   in  imu   plexus::msg::Imu              (angular_velocity[1] = gyro, linear_acceleration[0], [2])
//   out tilt  mylab::msg::TiltEstimate
//   parameters: tau (s, > 0, default 0.5), initial_tilt_deg (default 0)
#include <cmath>
#include <memory>

#include "mylab_msgs/messages.hpp"
#include "plexus/scenario/params.hpp"
#include "plexus/scenario/registry.hpp"

namespace {

using plexus::scenario::Component;
using plexus::scenario::ComponentConfig;

struct Params {
  double tau = 0.5;           // s
  double initial_tilt = 0.0;  // rad
};

Params read_params(const ComponentConfig& c) {
  Params p;
  p.tau = c.params().optional<double>("tau", p.tau);
  if (!(p.tau > 0.0) || !std::isfinite(p.tau)) c.params().fail("tau", "must be a time constant > 0 s");
  p.initial_tilt = c.params().optional<double>("initial_tilt_deg", 0.0) * M_PI / 180.0;
  if (!(std::abs(p.initial_tilt) < M_PI)) c.params().fail("initial_tilt_deg", "must lie within +-180 deg");
  return p;
}

class ComplementaryTilt final : public Component {
 public:
  explicit ComplementaryTilt(const ComponentConfig& c)
      : Component(c),
        imu_(add_input<plexus::msg::Imu>("imu")),
        out_(add_output<mylab::msg::TiltEstimate>("tilt")),
        p_(read_params(c)),
        base_step_(c.base_step),
        theta_(p_.initial_tilt) {}

  void step(int64_t /*k*/, double /*t*/) override {
    if (imu_.valid() && imu_.sample().step != last_step_) {
      const double accel = std::atan2(-imu_->linear_acceleration()[0], imu_->linear_acceleration()[2]);
      if (last_step_ < 0) {
        theta_ = accel;  // the first sample: start from the accelerometer
      } else {
        const double dt = static_cast<double>(imu_.sample().step - last_step_) * base_step_;
        const double a = p_.tau / (p_.tau + dt);
        theta_ = a * (theta_ + imu_->angular_velocity()[1] * dt) + (1.0 - a) * accel;
      }
      last_step_ = imu_.sample().step;
      accel_ = accel;
    }
    out_->tilt() = theta_;
    out_->accel_tilt() = accel_;
    out_->tau() = p_.tau;
  }

 private:
  plexus::scenario::TypedInput<plexus::msg::Imu>& imu_;
  plexus::scenario::TypedOutput<mylab::msg::TiltEstimate>& out_;
  Params p_;
  double base_step_;
  double theta_;
  double accel_ = 0.0;
  int64_t last_step_ = -1;
};

const plexus::scenario::ComponentRegistration kComplementaryTilt{
    "complementary_tilt", plexus::scenario::ComponentKind::estimator,
    "complementary tilt filter: gyro integrated, pulled to the accelerometer's tilt (time constant tau)",
    [](const ComponentConfig& c) { return std::make_unique<ComplementaryTilt>(c); }};

}  // namespace
