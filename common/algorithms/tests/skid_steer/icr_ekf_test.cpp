#include "plexus/algorithms/skid_steer/icr_ekf.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

#include "../support/validation_message.hpp"
#include "plexus/algorithms/core/random.hpp"
#include "plexus/algorithms/skid_steer/driving_pattern.hpp"
#include "plexus/algorithms/skid_steer/skid_steer_plant.hpp"
#include "plexus/algorithms/skid_steer/skid_steer_sensors.hpp"

namespace plexus::algorithms {
namespace {

IcrMatrix finite_difference_jacobian(const IcrVector& x, const TrackSpeeds& u, double dt) {
  IcrMatrix J;
  for (int j = 0; j < 6; ++j) {
    const double h = 1e-6 * (1.0 + std::abs(x(j)));
    IcrVector xp = x, xm = x;
    xp(j) += h;
    xm(j) -= h;
    J.col(j) = (IcrEkf::transition(xp, u, dt) - IcrEkf::transition(xm, u, dt)) / (2.0 * h);
  }
  return J;
}

TEST(IcrEkf, AnalyticJacobianMatchesFiniteDifferences) {
  Rng rng(11);
  for (int trial = 0; trial < 500; ++trial) {
    IcrVector x;
    const double yr = rng.uniform(-1.5, -0.05);
    x << rng.uniform(-10, 10), rng.uniform(-10, 10), rng.uniform(-7, 7), rng.uniform(0.05, 1.5), yr, rng.uniform(-1, 1);
    const TrackSpeeds u{rng.uniform(-1, 1), rng.uniform(-1, 1)};
    const double dt = rng.uniform(0.001, 0.1);
    const IcrMatrix F = IcrEkf::jacobian(x, u, dt);
    const IcrMatrix J = finite_difference_jacobian(x, u, dt);
    EXPECT_LT((F - J).cwiseAbs().maxCoeff(), 1e-6 * (1.0 + J.cwiseAbs().maxCoeff())) << "trial " << trial;
  }
}

TEST(IcrEkf, JacobianHasTheRandomWalkStructure) {
  IcrVector x;
  x << 1, 2, 0.3, 0.3, -0.5, -0.1;
  const IcrMatrix F = IcrEkf::jacobian(x, {0.2, 0.6}, 0.05);
  EXPECT_TRUE(F.bottomRows<3>().isApprox(
      (Eigen::Matrix<double, 3, 6>() << 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1).finished()));
  EXPECT_DOUBLE_EQ(F(0, 0), 1.0);
  EXPECT_DOUBLE_EQ(F(2, 5), 0.0);  // the heading rate does not depend on x_G
}

/// A run on one terrain with the paper's sensors; returns the filter after `seconds`.
struct SimRun {
  SkidSteerPlant plant;
  DrivingPattern drive;
  PoseSensor gps{{}};
  IcrEkf ekf;
  Rng plant_rng{1}, sensor_rng{2};
  double t = 0.0;
  static constexpr double kStep = 0.01;

  SimRun(const IcrEkfParams& p, std::vector<TerrainSegment> schedule = {{0.0, 0}})
      : plant(plant_params(std::move(schedule))), drive(DrivingPatternParams{}), ekf(p) {
    ekf.reset(gps.measure(plant.state().pose, sensor_rng));
  }
  static SkidSteerPlantParams plant_params(std::vector<TerrainSegment> schedule) {
    SkidSteerPlantParams pp;
    pp.schedule = std::move(schedule);
    return pp;
  }
  void advance(double seconds, const std::function<void()>& each_update = {}) {
    const long n = std::lround(seconds / kStep);
    for (long i = 0; i < n; ++i) {
      const TrackSpeeds u = drive.at(t);
      plant.step(t, u, plant_rng);
      t += kStep;
      ekf.predict(u, kStep);
      if (std::lround(t / kStep) % 5 == 0) {  // 20 Hz GPS
        ekf.update(gps.measure(plant.state().pose, sensor_rng));
        if (each_update) each_update();
      }
    }
  }
};

double icr_error(const IcrEkf& ekf, const IcrParams& truth) {
  const IcrParams e = ekf.icr();
  return std::max({std::abs(e.y_l - truth.y_l), std::abs(e.y_r - truth.y_r), std::abs(e.x_G - truth.x_G)});
}

TEST(IcrEkf, ConvergesToTheTrueIcrsOnOneTerrain) {
  SimRun run{IcrEkfParams{}};
  EXPECT_GT(icr_error(run.ekf, run.plant.state().icr), 0.5);  // starts at (1, -1, 1)
  run.advance(20.0);
  EXPECT_LT(icr_error(run.ekf, run.plant.state().icr), 0.02);
  EXPECT_EQ(run.ekf.rejected_predictions(), 0);
}

TEST(IcrEkf, CovarianceStaysSymmetricPositiveDefiniteOverLongRuns) {
  for (const auto model :
       {ProcessNoiseModel::kDtSquared, ProcessNoiseModel::kContinuous, ProcessNoiseModel::kPerStep}) {
    IcrEkfParams p;
    p.process_noise = model;
    SimRun run{p, {{0.0, 0}, {100.0, 1}, {200.0, 2}}};
    double worst_asym = 0.0, min_eig = 1e300;
    run.advance(300.0, [&] {
      const IcrMatrix& P = run.ekf.covariance();
      worst_asym = std::max(worst_asym, (P - P.transpose()).cwiseAbs().maxCoeff());
      min_eig = std::min(min_eig, Eigen::SelfAdjointEigenSolver<IcrMatrix>(P).eigenvalues().minCoeff());
    });
    EXPECT_EQ(worst_asym, 0.0);
    EXPECT_GT(min_eig, 0.0);
    EXPECT_TRUE(run.ekf.state().allFinite());
  }
}

TEST(IcrEkf, HeadingResidualIsWrapped) {
  IcrEkfParams p;
  IcrEkf ekf(p);
  ekf.reset({0.0, 0.0, std::numbers::pi - 0.01});
  // The sensor reports -pi + 0.01: 0.02 rad from the estimate, not 2 pi - 0.02.
  ASSERT_TRUE(ekf.update({0.0, 0.0, -std::numbers::pi + 0.01}));
  EXPECT_NEAR(ekf.pose().theta, std::numbers::pi - 0.01, 0.021);
  EXPECT_LT(ekf.last_nis(), 1.0);
}

TEST(IcrEkf, ResetToPbKeepsTheStateAndSetsTheCovariance) {
  SimRun run{IcrEkfParams{}};
  run.advance(5.0);
  const IcrVector x = run.ekf.state();
  run.ekf.reset_covariance_to_p_b();
  EXPECT_EQ(run.ekf.state(), x);
  EXPECT_TRUE(run.ekf.covariance().isApprox(IcrMatrix(IcrEkfParams::paper_p_b().asDiagonal())));
}

TEST(IcrEkf, TrackSidesAreEnforcedAfterUpdates) {
  IcrEkfParams p;
  p.initial_icr = {0.05, -0.05, 0.0};
  p.p0_diag << 1e-4, 1e-4, 1e-4, 1.0, 1.0, 1.0;
  IcrEkf ekf(p);
  ekf.reset({});
  // Driving straight at 1 m/s with the right track at 0.5 m/s would need y_l = -y_r...
  // Instead feed a heading that says the robot turned right a lot: the unconstrained update
  // pushes y_r across the centreline.
  for (int i = 0; i < 20; ++i) {
    ekf.predict({0.5, 0.1}, 0.05);
    ekf.update({0.0, 0.0, 0.0});
    EXPECT_GE(ekf.icr().y_l, p.track_side_margin);
    EXPECT_LE(ekf.icr().y_r, -p.track_side_margin);
  }
  EXPECT_GT(ekf.side_clamps(), 0);
  p.enforce_track_sides = false;
  IcrEkf free(p);
  free.reset({});
  for (int i = 0; i < 20; ++i) {
    free.predict({0.5, 0.1}, 0.05);
    free.update({0.0, 0.0, 0.0});
  }
  EXPECT_EQ(free.side_clamps(), 0);
}

TEST(IcrEkf, SingularIcrEstimateRejectsThePrediction) {
  IcrEkfParams p;
  p.enforce_track_sides = false;
  p.initial_icr = {0.0005, 0.0, 0.0};
  IcrEkf ekf(p);
  EXPECT_FALSE(ekf.predict({0.1, 0.2}, 0.01));
  EXPECT_FALSE(ekf.predict({0.1, 0.2}, 0.0));
  EXPECT_EQ(ekf.rejected_predictions(), 2);
}

TEST(IcrEkf, PaperTuning) {
  const double d3 = 3.0 * std::numbers::pi / 180.0;
  EXPECT_DOUBLE_EQ(IcrEkfParams::paper_q()(2), d3 * d3);
  EXPECT_DOUBLE_EQ(IcrEkfParams::paper_q()(3), 1e-4);
  EXPECT_DOUBLE_EQ(IcrEkfParams::paper_r()(0), 1e-4);
  EXPECT_DOUBLE_EQ(IcrEkfParams::paper_p_b()(5), 0.25);
  const IcrEkfParams p;
  EXPECT_EQ(p.initial_icr.y_l, 1.0);
  EXPECT_EQ(p.initial_icr.y_r, -1.0);
  EXPECT_EQ(p.initial_icr.x_G, 1.0);
}

TEST(IcrEkf, RejectsBadParameters) {
  using testing::invalid_argument_message;
  IcrEkfParams p;
  p.q_diag(4) = -1;
  EXPECT_EQ(invalid_argument_message<IcrEkf>(p), "icr_ekf: q_diag[4] must be finite and >= 0 (got -1)");
  p = {};
  p.r_diag(2) = 0;
  EXPECT_EQ(invalid_argument_message<IcrEkf>(p), "icr_ekf: r_diag[2] must be finite and > 0 (got 0)");
  p = {};
  p.p_b_diag(0) = std::nan("");
  EXPECT_EQ(invalid_argument_message<IcrEkf>(p), "icr_ekf: p_b_diag[0] must be finite and > 0 (got nan)");
  p = {};
  p.p0_diag(1) = -2;
  EXPECT_EQ(invalid_argument_message<IcrEkf>(p), "icr_ekf: p0_diag[1] must be finite and > 0 (got -2)");
  p = {};
  p.initial_icr = {0.2, 0.1, 0.0};
  EXPECT_EQ(invalid_argument_message<IcrEkf>(p),
            "icr_ekf: initial_icr must have y_l >= track_side_margin and y_r <= -track_side_margin when "
            "enforce_track_sides is on");
  p.enforce_track_sides = false;
  p.initial_icr = {-1.0, 1.0, 0.0};
  EXPECT_EQ(invalid_argument_message<IcrEkf>(p),
            "icr_ekf: initial_icr: y_l - y_r must be > 0 (y_l left of y_r) (got -2)");
  p = {};
  p.min_track_separation = 0;
  EXPECT_EQ(invalid_argument_message<IcrEkf>(p), "icr_ekf: min_track_separation must be finite and > 0 (got 0)");
  p = {};
  p.track_side_margin = -1;
  EXPECT_EQ(invalid_argument_message<IcrEkf>(p), "icr_ekf: track_side_margin must be finite and >= 0 (got -1)");
  EXPECT_THROW(process_noise_model_from_string("dt"), std::invalid_argument);
  EXPECT_EQ(process_noise_model_from_string("continuous"), ProcessNoiseModel::kContinuous);
}

}  // namespace
}  // namespace plexus::algorithms
