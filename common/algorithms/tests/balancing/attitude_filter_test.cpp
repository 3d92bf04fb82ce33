#include "plexus/algorithms/balancing/attitude_filter.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "../support/validation_message.hpp"
#include "closed_loop.hpp"

namespace plexus::algorithms {
namespace {

using testing::filter_params;

TEST(AttitudeFilter, SigmaPointCountsOfThePaper) {
  WheeledInvertedPendulum plant({});
  EXPECT_EQ(AttitudeFilter(filter_params(plant, AttitudeFilterKind::kUkfAugmented, AttitudeMeasurementForm::kPaper, {}))
                .sigma_points(),
            15);
  EXPECT_EQ(AttitudeFilter(filter_params(plant, AttitudeFilterKind::kUkfAdditive, AttitudeMeasurementForm::kPaper, {}))
                .sigma_points(),
            7);
  EXPECT_EQ(
      AttitudeFilter(filter_params(plant, AttitudeFilterKind::kUkfAugmented, AttitudeMeasurementForm::kObservable, {}))
          .sigma_points(),
      17);
}

// Paper form: the drift never meets a measurement. Its estimate follows the open-loop
// drift model exactly and its variance never falls below its open-loop propagation,
// whatever the data. Observable form: the variance falls well below it (to the level the
// tilt-rate noise Q_G allows) and the estimate is consistent with it.
TEST(AttitudeFilter, DriftUnobservableInPaperFormAndEstimatedWithGyro) {
  WheeledInvertedPendulum plant({});
  GyroParams gyro;
  gyro.drift_noise_psd = 0;
  gyro.gamma1 = -0.01;
  for (auto kind : {AttitudeFilterKind::kUkfAugmented, AttitudeFilterKind::kUkfAdditive, AttitudeFilterKind::kEkf}) {
    auto pp = filter_params(plant, kind, AttitudeMeasurementForm::kPaper, gyro);
    auto po = filter_params(plant, kind, AttitudeMeasurementForm::kObservable, gyro);
    po.q_drift = pp.q_drift = 1e-4;  // a slow drift model, so convergence is visible in 20 s
    std::vector<AttitudeFilter> filters{AttitudeFilter(po), AttitudeFilter(pp)};
    filters[1].reset({0, 0, 0.01});
    double open_loop_var = std::pow(pp.initial_drift_std, 2), open_loop_mean = 0.01;
    const double phi = 1 + pp.model.dt * gyro.gamma1;
    ImuSensor imu(gyro, {}, 9.81, 5);
    WheeledPendulumState s;
    for (int k = 0; k < 2000; ++k) {
      const ImuSample m = imu.measure(s, {}, 0.01);
      for (auto& f : filters) ASSERT_TRUE(f.step(0.0, m.acc_tilt, m.gyro));
      if (k > 0) {
        open_loop_mean *= phi;
        open_loop_var = phi * phi * open_loop_var + pp.q_drift * pp.q_drift;
      }
      ASSERT_NEAR(filters[1].state()(2), open_loop_mean, 1e-12) << k;
      ASSERT_GE(filters[1].covariance()(2, 2), open_loop_var * (1 - 1e-9)) << k;
    }
    if (std::getenv("PLEXUS_VERBOSE")) {
      std::printf("obs var %g open %g est %g true %g\n", filters[0].covariance()(2, 2), open_loop_var,
                  filters[0].state()(2), imu.drift());
    }
    EXPECT_LT(filters[0].covariance()(2, 2), 0.25 * open_loop_var);
    EXPECT_NEAR(filters[0].state()(2), imu.drift(), 3.0 * std::sqrt(filters[0].covariance()(2, 2)));
  }
}

TEST(AttitudeFilter, RefusesNonFiniteInput) {
  AttitudeFilter f(
      filter_params(WheeledInvertedPendulum({}), AttitudeFilterKind::kEkf, AttitudeMeasurementForm::kObservable, {}));
  EXPECT_FALSE(f.step(NAN, 0.0, 0.0));
  EXPECT_FALSE(f.step(0.0, INFINITY, 0.0));
  EXPECT_EQ(f.state(), Eigen::Vector3d::Zero());
}

TEST(AttitudeFilter, EveryValidationError) {
  auto msg = [](auto mutate) {
    auto p = filter_params(WheeledInvertedPendulum({}), AttitudeFilterKind::kUkfAugmented,
                           AttitudeMeasurementForm::kObservable, {});
    mutate(p);
    return testing::invalid_argument_message<AttitudeFilter>(p);
  };
  EXPECT_EQ(msg([](auto& p) { p.q_theta = -1; }), "attitude_filter: q_theta must be finite and >= 0 (got -1)");
  EXPECT_EQ(msg([](auto& p) { p.q_rate = NAN; }), "attitude_filter: q_rate must be finite and >= 0 (got nan)");
  EXPECT_EQ(msg([](auto& p) { p.q_drift = -1; }), "attitude_filter: q_drift must be finite and >= 0 (got -1)");
  EXPECT_EQ(msg([](auto& p) { p.r_tilt = 0; }), "attitude_filter: r_tilt must be finite and > 0 (got 0)");
  EXPECT_EQ(msg([](auto& p) { p.r_gyro = 0; }), "attitude_filter: r_gyro must be finite and > 0 (got 0)");
  EXPECT_EQ(msg([](auto& p) { p.initial_theta_std = 0; }),
            "attitude_filter: initial_theta_std must be finite and > 0 (got 0)");
  EXPECT_EQ(msg([](auto& p) { p.initial_rate_std = 0; }),
            "attitude_filter: initial_rate_std must be finite and > 0 (got 0)");
  EXPECT_EQ(msg([](auto& p) { p.initial_drift_std = 0; }),
            "attitude_filter: initial_drift_std must be finite and > 0 (got 0)");
  EXPECT_EQ(msg([](auto& p) { p.sigma.alpha = 0; }), "augmented_ukf: alpha must be finite and > 0 (got 0)");
  EXPECT_EQ(msg([](auto& p) { p.sigma.kappa = -3.5; }),
            "additive_ukf: kappa must be > -L = -3 (L + kappa > 0) (got -3.5)");
  EXPECT_EQ(msg([](auto& p) { p.model.dt = 0; }), "attitude_model: dt must be finite and > 0 (got 0)");
}

}  // namespace
}  // namespace plexus::algorithms
