// The edge check on received signals: what passes, what is refused, and that a refusal
// leaves the destination sample untouched.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "input_guard.hpp"

namespace plexus::distributed::detail {
namespace {

scenario::SignalSpec spec3() {
  scenario::SignalSpec s;
  s.name = "r1/gps";
  s.fields = {"x", "y", "theta"};
  s.producer = "gps";
  return s;
}

msg::Signal message(int64_t step, double x, double y, double theta) {
  msg::Signal m;
  m.step_index(step);
  m.count(3);
  m.field_values()[0] = x;
  m.field_values()[1] = y;
  m.field_values()[2] = theta;
  return m;
}

TEST(SignalCodec, RoundTripsFiniteValues) {
  scenario::SignalSample in;
  in.step = 42;
  in.values[0] = 1.5;
  in.values[1] = -2.0;
  in.values[2] = 0.25;
  msg::Signal m;
  to_message(in, 3, 10'000'000, m);
  EXPECT_EQ(m.header().data_time_ns(), 420'000'000);
  scenario::SignalSample out;
  std::size_t bad = 99;
  ASSERT_EQ(from_message(m, 3, out, bad), Rejection::none);
  EXPECT_EQ(out.step, 42);
  EXPECT_EQ(out.values[0], 1.5);
  EXPECT_EQ(out.values[2], 0.25);
  EXPECT_EQ(bad, 99u);
}

TEST(SignalCodec, RefusesEachKindOfBadSample) {
  scenario::SignalSample out;
  out.step = 7;
  out.values[0] = 3.0;
  std::size_t bad = 0;
  EXPECT_EQ(from_message(message(1, 0, std::nan(""), 0), 3, out, bad), Rejection::non_finite);
  EXPECT_EQ(bad, 1u);
  EXPECT_EQ(from_message(message(1, 0, 0, std::numeric_limits<double>::infinity()), 3, out, bad),
            Rejection::non_finite);
  EXPECT_EQ(bad, 2u);
  EXPECT_EQ(from_message(message(-1, 0, 0, 0), 3, out, bad), Rejection::negative_step);
  EXPECT_EQ(from_message(message(1, 0, 0, 0), 2, out, bad), Rejection::wrong_width);
  // A refused sample never reaches the destination (no half-written estimator input).
  EXPECT_EQ(out.step, 7);
  EXPECT_EQ(out.values[0], 3.0);
}

TEST(InputGuard, CountsRefusalsAndPassesGoodSamples) {
  InputGuard guard("test host");
  const auto spec = spec3();
  scenario::SignalSample s;
  EXPECT_TRUE(guard.accept(message(0, 1, 2, 3), spec, s));
  EXPECT_EQ(guard.rejected(), 0u);
  for (int i = 0; i < 5; ++i) EXPECT_FALSE(guard.accept(message(i + 1, std::nan(""), 0, 0), spec, s));
  EXPECT_FALSE(guard.accept(message(9, 0, 0, -std::numeric_limits<double>::infinity()), spec, s));
  EXPECT_EQ(guard.rejected(), 6u);
  EXPECT_EQ(s.step, 0);
  EXPECT_EQ(s.values[0], 1.0);
}

}  // namespace
}  // namespace plexus::distributed::detail
