#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "closed_loop.hpp"

namespace plexus::algorithms {
namespace {

using testing::filter_params;
using testing::run_closed_loop;

// The paper's experiment (Table 1): 5 s at 100 Hz, start upright, balance then move. The
// robot stays upright, every filter tracks the tilt, and the observable form recovers the
// gyro drift while the paper form cannot.
TEST(ClosedLoop, PaperExperimentStaysUprightAndFiltersTrack) {
  WheeledInvertedPendulum plant({});
  GyroParams gyro;
  AccelerometerParams acc;
  std::vector<AttitudeFilter> filters;
  for (auto form : {AttitudeMeasurementForm::kObservable, AttitudeMeasurementForm::kPaper}) {
    for (auto kind : {AttitudeFilterKind::kUkfAugmented, AttitudeFilterKind::kUkfAdditive, AttitudeFilterKind::kEkf}) {
      filters.emplace_back(filter_params(plant, kind, form, gyro));
    }
  }
  const auto r = run_closed_loop(plant, filters, gyro, acc, 42);
  if (std::getenv("PLEXUS_VERBOSE")) {
    std::printf("max |tilt| %.4f deg, raw accelerometer tilt error std %.4f deg\n", r.max_abs_tilt_deg,
                r.acc_tilt_error_deg.std);
    for (std::size_t i = 0; i < filters.size(); ++i) {
      const auto& e = r.tilt_error_deg[i];
      std::printf("filter %zu: mean %.5f std %.5f max %.4f min %.4f drift err %.4f deg/s\n", i, e.mean, e.std, e.max,
                  e.min, r.final_drift_error[i] * 57.29578);
    }
  }
  EXPECT_LT(r.max_abs_tilt_deg, 10.0);
  // Observable form (filters 0-2): within the paper's own figure, UKF std 0.24 deg (Table 1
  // settings, section 5). Measured 0.150 deg here; 0.137-0.170 over 30 seeds of the scenario.
  for (int i = 0; i < 3; ++i) EXPECT_LT(r.tilt_error_deg[i].std, 0.24) << "filter " << i;
  // Paper form (filters 3-5): it takes the accelerometer's tilt atan2(a_x, a_z) as the tilt,
  // so the linear acceleration of the manoeuvre is an error it cannot remove; worse, that
  // error corrupts its drift estimate (final drift error -0.52 deg/s), whose lag adds to it:
  // measured 0.979 deg against 0.891 deg for the raw accelerometer tilt on the same run
  // (1.10x). Bound: 1.25x the raw figure, a pin near today's ratio, so that the paper form
  // cannot get worse unnoticed while the observable form's bound above is the paper's.
  for (int i = 3; i < 6; ++i) EXPECT_LT(r.tilt_error_deg[i].std, 1.25 * r.acc_tilt_error_deg.std) << "filter " << i;
  // The observable form accounts for the accelerometer's linear acceleration: its tilt
  // error is several times smaller than the paper form's while the robot accelerates.
  for (int i = 0; i < 3; ++i) EXPECT_LT(2.0 * r.tilt_error_deg[i].std, r.tilt_error_deg[i + 3].std);
}

}  // namespace
}  // namespace plexus::algorithms
