// Numbers in messages and CSV files (plexus/scenario/format.hpp): the shortest text that reads
// back as the same double, and one spelling of NaN whatever its sign bit.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "plexus/scenario/format.hpp"

namespace plexus::scenario {
namespace {

TEST(FormatNumber, ShortestTextReadsBackExactly) {
  for (const double v : {0.1, 1.0 / 3.0, -2.5e-300, 1e22, 6.02214076e23, 0.0}) {
    const std::string text = format_number(v);
    EXPECT_EQ(std::stod(text), v) << text;
  }
  EXPECT_EQ(format_number(0.1), "0.1");
  EXPECT_EQ(format_number(-1.5), "-1.5");
}

TEST(FormatNumber, NanHasOneSpelling) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(format_number(nan), "nan");
  EXPECT_EQ(format_number(-nan), "nan");
  EXPECT_EQ(format_number(std::copysign(nan, -1.0)), "nan");
}

TEST(AppendNumber, AppendsWhatFormatNumberReturns) {
  std::string line = "t";
  for (const double v : {0.25, -3.0, std::numeric_limits<double>::quiet_NaN(), 1e-7}) {
    line += ',';
    append_number(line, v);
  }
  EXPECT_EQ(line, "t,0.25,-3,nan,1e-07");
}

}  // namespace
}  // namespace plexus::scenario
