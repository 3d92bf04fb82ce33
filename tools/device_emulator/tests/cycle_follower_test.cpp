// CycleFollower (tools/device_emulator/cycle_follower.hpp): a device following the run's
// cycle (docs/bridges.md, "Cycle sync"). The bridge's side is simulated with the device
// clock's exact map: the cycle frame says when one of the run's steps falls in device time.
#include "cycle_follower.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace plexus::emulator {
namespace {

constexpr int64_t kStep = 1'000'000;            // 1 kHz
constexpr int64_t kT0 = 1'796'000'000'123'456;  // the run's step 0, CLOCK_REALTIME ns

// A cycle frame for the run of kT0 and kStep, at its step `k`, in the device clock `clock`.
void cycle_frame(const DeviceClockModel& clock, int64_t k, uint8_t out[link::kCyclePayload]) {
  link::put_f64_le(out, clock.at(kT0 + k * kStep));
  link::put_f64_le(out + 8, static_cast<double>(kStep) * 1e-9 * (1.0 + clock.drift_ppm * 1e-6));
  link::put_f64_le(out + 16, static_cast<double>(k));
}

TEST(CycleFollower, PutsTheNextTickOnTheRunsStepAndNumbersIt) {
  // A device clock 2.5 s ahead and 150 ppm fast, powered up 40 s before the run.
  const DeviceClockModel clock{kT0 - 40'000'000'000, 2.5, 150.0};
  CycleFollower follow(kStep);
  uint8_t frame[link::kCyclePayload];
  cycle_frame(clock, -180, frame);  // sent before the run's start
  for (const int64_t off : {-499'000, -1, 0, 1, 123'456, 499'000}) {
    // The device's next tick, off the run's step 37 by `off`.
    const int64_t next = kT0 + 37 * kStep + off;
    int64_t shift = 0, step = 0;
    ASSERT_TRUE(follow.shift_for(frame, sizeof frame, clock, next, shift, step));
    EXPECT_EQ(step, 37);
    EXPECT_NEAR(static_cast<double>(next + shift - (kT0 + 37 * kStep)), 0.0, 2.0) << "off " << off;  // ns
    EXPECT_LE(std::abs(shift), kStep / 2);
  }
  EXPECT_EQ(follow.syncs(), 6u);
  EXPECT_NEAR(follow.first_shift_us(), 499.0, 0.01);
  EXPECT_NEAR(follow.max_shift_us(), 499.0, 0.01);  // the last one moved it back
}

TEST(CycleFollower, RefusesWhatIsNoCycle) {
  const DeviceClockModel clock{kT0, 0.0, 0.0};
  CycleFollower follow(kStep);
  uint8_t frame[link::kCyclePayload];
  int64_t shift = 0, step = 0;
  cycle_frame(clock, 5, frame);
  EXPECT_FALSE(follow.shift_for(frame, 16, clock, kT0, shift, step));  // the wrong length
  link::put_f64_le(frame + 16, 5.5);                                   // a step that is no integer
  EXPECT_FALSE(follow.shift_for(frame, sizeof frame, clock, kT0, shift, step));
  cycle_frame(clock, 5, frame);
  link::put_f64_le(frame + 8, 0.002);  // a step of 2 ms: not the device's own
  EXPECT_FALSE(follow.shift_for(frame, sizeof frame, clock, kT0, shift, step));
  link::put_f64_le(frame + 8, NAN);
  EXPECT_FALSE(follow.shift_for(frame, sizeof frame, clock, kT0, shift, step));
  EXPECT_EQ(follow.refused(), 4u);
  EXPECT_EQ(follow.syncs(), 0u);
}

}  // namespace
}  // namespace plexus::emulator
