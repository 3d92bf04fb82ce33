#include "plexus/scenario/digest.hpp"

#include <gtest/gtest.h>

#include <cstring>

namespace plexus::scenario {
namespace {

TEST(Digest, Fnv1aKnownVectors) {
  EXPECT_EQ(hex16(fnv1a64("", 0)), "cbf29ce484222325");
  EXPECT_EQ(hex16(fnv1a64("a", 1)), "af63dc4c8601ec8c");
  EXPECT_EQ(hex16(fnv1a64("foobar", 6)), "85944171f73967e8");
}

TEST(Digest, CoversOnlyPlantStateStepsAndValues) {
  RunLog log;
  log.base_step = 0.1;
  SignalTrace plant{{"r/truth/state", {"x", "y"}, 1, "r/plant", true, ""}, {0, 1}, {1.0, 2.0, 3.0, 4.0}};
  SignalTrace other{{"r/gps", {"x"}, 1, "r/gps", false, ""}, {0}, {9.0}};
  log.signals = {plant, other};
  // By hand: FNV-1a over step 0, 1.0, 2.0, step 1, 3.0, 4.0 as raw bytes.
  unsigned char bytes[48];
  const int64_t s0 = 0, s1 = 1;
  const double v[4] = {1.0, 2.0, 3.0, 4.0};
  std::memcpy(bytes, &s0, 8);
  std::memcpy(bytes + 8, v, 16);
  std::memcpy(bytes + 24, &s1, 8);
  std::memcpy(bytes + 32, v + 2, 16);
  EXPECT_EQ(run_digest(log), fnv1a64(bytes, sizeof bytes));
  log.signals[1].values[0] = 10.0;  // not plant state: digest unchanged
  EXPECT_EQ(run_digest(log), fnv1a64(bytes, sizeof bytes));
  log.signals[0].values[3] = 4.5;
  EXPECT_NE(run_digest(log), fnv1a64(bytes, sizeof bytes));
}

TEST(Digest, DerivedSeedsDependOnNameAndScenarioSeed) {
  EXPECT_EQ(derive_seed(1, "r1/gps"), derive_seed(1, "r1/gps"));
  EXPECT_NE(derive_seed(1, "r1/gps"), derive_seed(1, "r1/rfid"));
  EXPECT_NE(derive_seed(1, "r1/gps"), derive_seed(2, "r1/gps"));
}

}  // namespace
}  // namespace plexus::scenario
