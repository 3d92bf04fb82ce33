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
    std::printf("max |tilt| %.4f deg\n", r.max_abs_tilt_deg);
    for (std::size_t i = 0; i < filters.size(); ++i) {
      const auto& e = r.tilt_error_deg[i];
      std::printf("filter %zu: mean %.5f std %.5f max %.4f min %.4f drift err %.4f deg/s\n", i, e.mean, e.std, e.max,
                  e.min, r.final_drift_error[i] * 57.29578);
    }
  }
  EXPECT_LT(r.max_abs_tilt_deg, 10.0);
  for (const auto& e : r.tilt_error_deg) EXPECT_LT(e.std, 1.0);
  // The observable form accounts for the accelerometer's linear acceleration: its tilt
  // error is several times smaller than the paper form's while the robot accelerates.
  for (int i = 0; i < 3; ++i) EXPECT_LT(2.0 * r.tilt_error_deg[i].std, r.tilt_error_deg[i + 3].std);
}

}  // namespace
}  // namespace plexus::algorithms
