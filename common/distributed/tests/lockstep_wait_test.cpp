// The lockstep host's timeout line and its parser (lockstep_wait.hpp): what the launcher reads
// back from a service's last line to follow a failed run to its cause.
#include <gtest/gtest.h>

#include "plexus/distributed/lockstep_wait.hpp"

namespace plexus::distributed {
namespace {

TEST(LockstepWait, MessageParsesBackBehindAPrefix) {
  const std::string msg = lockstep_wait_message({"r1/cmd", "controller"}, 879, 1.0);
  EXPECT_EQ(msg, "lockstep: no sample of 'r1/cmd' (produced by 'controller') for step 879 within 1 s");
  const auto w = parse_lockstep_wait("plant_simulator r1 | plant_simulator: " + msg);
  ASSERT_TRUE(w.has_value());
  EXPECT_EQ(w->sample, "r1/cmd");
  EXPECT_EQ(w->producer, "controller");
}

TEST(LockstepWait, OtherLinesAreNoWait) {
  EXPECT_FALSE(parse_lockstep_wait("plant_simulator: ran 6000 steps"));
  // The clock's own message names its producer differently (LockstepError::awaited carries it).
  EXPECT_FALSE(parse_lockstep_wait("lockstep: no sample of 'r1/truth/state' from 'r1/plant' for step 880 within 1 s"));
  EXPECT_FALSE(parse_lockstep_wait("lockstep: no sample of 'r1/cmd' (produced by 'controller"));  // cut short
  EXPECT_FALSE(parse_lockstep_wait("lockstep: no sample of '' (produced by 'controller') for step 1 within 1 s"));
  EXPECT_FALSE(parse_lockstep_wait("lockstep: no sample of 'r1/cmd' (produced by '') for step 1 within 1 s"));
  EXPECT_FALSE(parse_lockstep_wait(""));
}

}  // namespace
}  // namespace plexus::distributed
