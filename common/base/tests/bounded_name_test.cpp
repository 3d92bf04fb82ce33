#include "plexus/base/bounded_name.hpp"

#include <gtest/gtest.h>

namespace {

TEST(BoundedName, NamesWithinTheLimitAreUnchanged) {
  EXPECT_EQ(plexus::bounded_name("plant_simulator r1", 251), "plant_simulator r1");
  const std::string exact(251, 'a');
  EXPECT_EQ(plexus::bounded_name(exact, 251), exact);
}

TEST(BoundedName, LongNamesAreCutToTheLimitKeepingThemApart) {
  std::string a = "localisation_observer ", b = a;
  for (int r = 1; r <= 20; ++r) {
    a += "r" + std::to_string(r) + "_observer,";
    b += "r" + std::to_string(r) + "_observer;";  // differs after the cut only
  }
  const std::string ca = plexus::bounded_name(a, 251), cb = plexus::bounded_name(b, 251);
  EXPECT_EQ(ca.size(), 251u);
  EXPECT_EQ(ca.substr(0, 234), a.substr(0, 234));
  EXPECT_EQ(ca[234], '_');  // a valid character of a DDS topic name on both vendors
  EXPECT_NE(ca, cb);
  EXPECT_EQ(ca, plexus::bounded_name(a, 251));  // every process derives the same
}

}  // namespace
