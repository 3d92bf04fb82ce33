#include "plexus/base/teardown_deadline.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

namespace {

// A teardown that never ends (a deadlocked vendor shutdown, as eProsima/Fast-DDS#4026) is cut
// at the deadline, with the code the program meant to exit with and one line naming it.
TEST(TeardownDeadline, AHungTeardownExitsWithTheIntendedCode) {
  EXPECT_EXIT(
      {
        plexus::exit_within(3, 0.2, "hung_program");
        for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));
      },
      ::testing::ExitedWithCode(3), "hung_program: teardown did not finish within 0.2 s");
}

// Arming it again moves the deadline and the code: the last word counts.
TEST(TeardownDeadline, TheLastArmingCounts) {
  EXPECT_EXIT(
      {
        plexus::exit_within(1, 0.1, "rearmed");
        plexus::exit_within(4, 0.3, "rearmed");
        for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));
      },
      ::testing::ExitedWithCode(4), "within 0.3 s");
}

// A teardown that ends in time is not touched: the process exits as it would have.
TEST(TeardownDeadline, AFinishedTeardownExitsNormally) {
  EXPECT_EXIT(
      {
        const int rc = plexus::exit_within(5, 5.0, "quick");
        std::exit(rc == 5 ? 0 : 9);
      },
      ::testing::ExitedWithCode(0), "");
}

}  // namespace
