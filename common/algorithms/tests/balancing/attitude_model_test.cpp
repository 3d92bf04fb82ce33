#include "plexus/algorithms/balancing/attitude_model.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "../support/validation_message.hpp"
#include "plexus/algorithms/balancing/imu_sensor.hpp"

namespace plexus::algorithms {
namespace {

using testing::invalid_argument_message;

AttitudeModelParams params(AttitudeProcessModel process) {
  AttitudeModelParams p;
  p.coefficients = WheeledInvertedPendulum({}).coefficients();
  p.gamma1 = -0.05;
  p.gamma2 = 0.001;
  p.process = process;
  return p;
}

// The EKF's analytic Jacobians agree with central finite differences, for the nonlinear
// and the linear process models and the accelerometer measurement model.
TEST(AttitudeModel, JacobiansAgreeWithFiniteDifferences) {
  for (auto process : {AttitudeProcessModel::kNonlinear, AttitudeProcessModel::kLinear}) {
    AttitudeModel m(params(process));
    for (const Eigen::Vector3d& x : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.3, -1.2, 0.01),
                                     Eigen::Vector3d(-0.8, 2.5, -0.02), Eigen::Vector3d(1.2, 0.4, 0.0)}) {
      for (double T : {-1.0, 0.0, 0.7}) {
        const Eigen::Matrix3d F = m.jacobian(x, T);
        const Eigen::RowVector3d H = m.accelerometer_tilt_gradient(x, T);
        const double h = 1e-6;
        for (int j = 0; j < 3; ++j) {
          Eigen::Vector3d d = Eigen::Vector3d::Zero();
          d(j) = h;
          const Eigen::Vector3d col = (m.predict(x + d, T) - m.predict(x - d, T)) / (2 * h);
          EXPECT_LT((col - F.col(j)).norm(), 1e-6 * (1 + F.col(j).norm())) << "F col " << j;
          const double hd = (m.accelerometer_tilt(x + d, T) - m.accelerometer_tilt(x - d, T)) / (2 * h);
          EXPECT_NEAR(hd, H(j), 1e-6 * (1 + std::abs(H(j)))) << "H " << j;
        }
      }
    }
  }
}

// The accelerometer model is the sensor's noise-free reading: with the plant's own
// accelerations the atan2 of the specific force equals accelerometer_tilt(x, T).
TEST(AttitudeModel, AccelerometerModelMatchesTheSensor) {
  WheeledInvertedPendulum plant({});
  AttitudeModel m(params(AttitudeProcessModel::kNonlinear));
  for (double T : {-1.0, 0.3}) {
    const WheeledPendulumState s{0.0, 0.4, 0.2, -0.7};
    const auto acc = plant.accelerations(s, T);
    double fx, fz;
    ImuSensor::specific_force(s, acc, m.params().accelerometer_height, m.params().gravity, fx, fz);
    EXPECT_NEAR(std::atan2(-fx, fz), m.accelerometer_tilt({s.theta, s.theta_dot, 0.0}, T), 1e-12);
  }
  // At rest the accelerometer tilt is the tilt; under torque it is not (linear acceleration).
  const double rest_tilt = m.accelerometer_tilt({0.1, 0.0, 0.0}, 0.0);
  EXPECT_GT(std::abs(rest_tilt - 0.1), 1e-4);  // free fall of an unbalanced body: theta'' != 0
  const AttitudeModel upright(params(AttitudeProcessModel::kNonlinear));
  EXPECT_NEAR(upright.accelerometer_tilt({0.0, 0.0, 0.0}, 0.0), 0.0, 1e-15);
}

// The paper's measurement (tilt only) leaves the drift unobservable; adding the gyro
// makes the whole state observable.
TEST(AttitudeModel, DriftUnobservableInPaperFormObservableWithGyro) {
  for (auto process : {AttitudeProcessModel::kNonlinear, AttitudeProcessModel::kLinear}) {
    AttitudeModel m(params(process));
    for (const Eigen::Vector3d& x : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.2, 0.5, 0.01)}) {
      EXPECT_EQ(m.observability_rank(x, 0.3, AttitudeMeasurementForm::kPaper), 2);
      EXPECT_EQ(m.observability_rank(x, 0.3, AttitudeMeasurementForm::kObservable), 3);
    }
  }
}

TEST(AttitudeModel, GyroSaturates) {
  AttitudeModelParams p = params(AttitudeProcessModel::kNonlinear);
  p.gyro_range = 1.0;
  AttitudeModel m(p);
  EXPECT_EQ(m.gyro({0, 2.0, 0.1}), 1.0);
  EXPECT_EQ(m.gyro_slope({0, 2.0, 0.1}), 0.0);
  EXPECT_EQ(m.gyro({0, 0.5, 0.1}), 0.6);
  EXPECT_EQ(m.gyro_slope({0, 0.5, 0.1}), 1.0);
}

TEST(AttitudeModel, EveryValidationError) {
  auto msg = [](auto mutate) {
    AttitudeModelParams p = params(AttitudeProcessModel::kNonlinear);
    mutate(p);
    return invalid_argument_message<AttitudeModel>(p);
  };
  EXPECT_EQ(msg([](auto& p) { p.dt = 0; }), "attitude_model: dt must be finite and > 0 (got 0)");
  EXPECT_EQ(msg([](auto& p) { p.gamma1 = NAN; }), "attitude_model: gamma1 must be finite (got nan)");
  EXPECT_EQ(msg([](auto& p) { p.gamma2 = INFINITY; }), "attitude_model: gamma2 must be finite (got inf)");
  EXPECT_EQ(msg([](auto& p) { p.gyro_range = -1; }),
            "attitude_model: gyro_range must be > 0 (infinity allowed) (got -1)");
  EXPECT_EQ(msg([](auto& p) { p.accelerometer_height = NAN; }),
            "attitude_model: accelerometer_height must be finite (got nan)");
  EXPECT_EQ(msg([](auto& p) { p.gravity = 0; }), "attitude_model: gravity must be finite and > 0 (got 0)");
  EXPECT_EQ(msg([](auto& p) { p.coefficients.alpha1 = 1.0; }), "attitude_model: alpha1 must be in [0, 1) (got 1)");
  EXPECT_EQ(msg([](auto& p) { p.coefficients.alpha2 = NAN; }), "attitude_model: alpha2 must be finite (got nan)");
  EXPECT_EQ(msg([](auto& p) { p.coefficients.alpha3 = NAN; }), "attitude_model: alpha3 must be finite (got nan)");
  EXPECT_EQ(msg([](auto& p) { p.coefficients.alpha4 = NAN; }), "attitude_model: alpha4 must be finite (got nan)");
  EXPECT_EQ(msg([](auto& p) { p.coefficients.torque_gain = NAN; }),
            "attitude_model: torque_gain must be finite (got nan)");
}

}  // namespace
}  // namespace plexus::algorithms
