// The skid-steer robot's sensors (sensor; plant_simulator; paper 001 section 4,
// docs/algorithms/skid_steer.md). Each reads the plant's truth/state and publishes
// `<robot>/<sensor name>` as its IDL type (docs/topics.md); the scenarios name them gps,
// wheels and imu, the consumers' default ports.
//
//   pose_sensor          in truth/state {x, y, theta}; out <sensor name> {x, y, theta} (Pose2D)
//     position_std (0.01 m), heading_std_deg (1), wrap_heading (true)
//   track_speed_sensor   in truth/state {v_l, v_r}; out <sensor name> {v_l, v_r}
//     (TrackSpeeds); noise_std (0)
//   imu_z_sensor         in truth/state {a_z}; out <sensor name> {a_z} (Imu, z axis);
//     noise_std (0.02), bias (0)
#include <memory>
#include <numbers>

#include "plexus/algorithms/core/random.hpp"
#include "plexus/algorithms/skid_steer/skid_steer_sensors.hpp"
#include "plexus/scenario/params.hpp"
#include "plexus/scenario/registry.hpp"
#include "services/common/input_values.hpp"

namespace plexus::scenario {
namespace {

namespace alg = plexus::algorithms;

class PoseSensorComponent final : public Component {
 public:
  explicit PoseSensorComponent(const ComponentConfig& c)
      : Component(c),
        sensor_(params(c.params())),
        rng_(c.seed),
        in_(add_input("truth/state", {"x", "y", "theta"}, "SkidSteerTruth")),
        out_(add_output(c.key, {"x", "y", "theta"}, "Pose2D")) {}
  void step(int64_t /*k*/, double /*t*/) override {
    const alg::Pose2 m = sensor_.measure(pose_of(in_), rng_);
    out_[0] = m.x;
    out_[1] = m.y;
    out_[2] = m.theta;
  }

 private:
  static alg::PoseSensorParams params(const YamlMap& p) {
    alg::PoseSensorParams s;
    s.position_std = optional_non_negative(p, "position_std", s.position_std);
    s.heading_std = optional_non_negative(p, "heading_std_deg", 1.0) * std::numbers::pi / 180.0;
    s.wrap_heading = p.optional<bool>("wrap_heading", true);
    return s;
  }
  alg::PoseSensor sensor_;
  alg::Rng rng_;
  InputPort& in_;
  OutputPort& out_;
};

class TrackSpeedSensorComponent final : public Component {
 public:
  explicit TrackSpeedSensorComponent(const ComponentConfig& c)
      : Component(c),
        sensor_(optional_non_negative(c.params(), "noise_std")),
        rng_(c.seed),
        in_(add_input("truth/state", {"v_l", "v_r"}, "SkidSteerTruth")),
        out_(add_output(c.key, {"v_l", "v_r"}, "TrackSpeeds")) {}
  void step(int64_t /*k*/, double /*t*/) override {
    const alg::TrackSpeeds m = sensor_.measure({in_[0], in_[1]}, rng_);
    out_[0] = m.v_l;
    out_[1] = m.v_r;
  }

 private:
  alg::TrackSpeedSensor sensor_;
  alg::Rng rng_;
  InputPort& in_;
  OutputPort& out_;
};

class ImuZSensorComponent final : public Component {
 public:
  explicit ImuZSensorComponent(const ComponentConfig& c)
      : Component(c),
        sensor_(optional_non_negative(c.params(), "noise_std", 0.02), c.params().optional<double>("bias", 0.0)),
        rng_(c.seed),
        in_(add_input("truth/state", {"a_z"}, "SkidSteerTruth")),
        out_(add_output(c.key, {"a_z"}, "Imu")) {}
  void step(int64_t /*k*/, double /*t*/) override { out_[0] = sensor_.measure(in_[0], rng_); }

 private:
  alg::ImuZSensor sensor_;
  alg::Rng rng_;
  InputPort& in_;
  OutputPort& out_;
};

template <class T>
ComponentFactory make() {
  return [](const ComponentConfig& c) { return std::make_unique<T>(c); };
}

const ComponentRegistration kPose{"pose_sensor", ComponentKind::sensor,
                                  "GPS position + heading with Gaussian noise (paper 001: 0.01 m, 1 deg)",
                                  make<PoseSensorComponent>()};
const ComponentRegistration kWheels{"track_speed_sensor", ComponentKind::sensor, "track speeds v_l, v_r with noise",
                                    make<TrackSpeedSensorComponent>()};
const ComponentRegistration kImuZSensor{"imu_z_sensor", ComponentKind::sensor, "IMU z-acceleration with noise and bias",
                                        make<ImuZSensorComponent>()};

}  // namespace
}  // namespace plexus::scenario
