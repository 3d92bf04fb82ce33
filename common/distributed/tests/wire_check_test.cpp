// The wire contract's error paths that need no DDS: WireSignal::check (a bridge's edge
// check on values it holds), decode's time rules (negative time, the epoch, the nearest
// step), find_wire_type on names it does not know, and the binding errors' messages.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <string>

#include "plexus/base/input_error.hpp"
#include "plexus/distributed/wire.hpp"

namespace plexus::distributed {
namespace {

constexpr int64_t kStepNs = 10'000'000;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

scenario::SignalSpec wire_spec(std::string name, std::vector<std::string> fields, std::string message) {
  scenario::SignalSpec s;
  s.name = std::move(name);
  s.fields = std::move(fields);
  s.producer = "r1/gps";
  s.message = std::move(message);
  return s;
}

scenario::SignalSample sample(int64_t step, std::initializer_list<double> values) {
  scenario::SignalSample s;
  s.step = step;
  std::size_t i = 0;
  for (double v : values) s.values[i++] = v;
  return s;
}

template <class F>
std::string input_error_of(F&& fn) {
  try {
    fn();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

// --- WireSignal::check ----------------------------------------------------------

TEST(WireCheck, AcceptsInRangeValuesAndLeavesBadFieldAlone) {
  const auto s = wire_spec("r1/gps", {"x", "y", "z", "stddev"}, "PositionMeasurement");
  const WireSignal wire(s, kStepNs);
  std::size_t bad = 99;
  EXPECT_EQ(wire.check(sample(0, {1.0, -2.0, 3.0, 0.5}), bad), Rejection::none);
  // The bounds themselves are in range (inclusive).
  EXPECT_EQ(wire.check(sample(0, {1e6, -1e6, 0.0, 0.0}), bad), Rejection::none);
  EXPECT_EQ(bad, 99u);
}

TEST(WireCheck, RefusesNonFiniteValuesNamingTheField) {
  const auto s = wire_spec("r1/gps", {"x", "y", "z", "stddev"}, "PositionMeasurement");
  const WireSignal wire(s, kStepNs);
  std::size_t bad = 99;
  EXPECT_EQ(wire.check(sample(0, {kNaN, 0, 0, 0}), bad), Rejection::non_finite);
  EXPECT_EQ(bad, 0u);
  EXPECT_EQ(wire.check(sample(0, {0, kInf, 0, 0}), bad), Rejection::non_finite);
  EXPECT_EQ(bad, 1u);
  EXPECT_EQ(wire.check(sample(0, {0, 0, -kInf, 0}), bad), Rejection::non_finite);
  EXPECT_EQ(bad, 2u);
}

TEST(WireCheck, RefusesOutOfRangeValuesNamingTheField) {
  const auto s = wire_spec("r1/gps", {"x", "y", "z", "stddev"}, "PositionMeasurement");
  const WireSignal wire(s, kStepNs);
  std::size_t bad = 99;
  EXPECT_EQ(wire.check(sample(0, {0, 1e6 * 1.0001, 0, 0}), bad), Rejection::out_of_range);  // beyond 1000 km
  EXPECT_EQ(bad, 1u);
  EXPECT_EQ(wire.check(sample(0, {0, 0, 0, -0.1}), bad), Rejection::out_of_range);  // a negative stddev
  EXPECT_EQ(bad, 3u);
}

TEST(WireCheck, ReportsTheFirstBadFieldInTheSignalsOrder) {
  // The signal's field order, not the message's: theta is field 0 here.
  const auto s = wire_spec("r1/pose", {"theta", "y", "x"}, "Pose2D");
  const WireSignal wire(s, kStepNs);
  std::size_t bad = 99;
  EXPECT_EQ(wire.check(sample(0, {0, 2e6, kNaN}), bad), Rejection::out_of_range);
  EXPECT_EQ(bad, 1u);
  EXPECT_EQ(wire.check(sample(0, {kNaN, 2e6, 0}), bad), Rejection::non_finite);
  EXPECT_EQ(bad, 0u);
}

TEST(WireCheck, ChecksOnlyTheSignalsFields) {
  // Values past the signal's fields are not members: whatever they hold, they pass.
  const auto s = wire_spec("r1/pose", {"x"}, "Pose2D");
  const WireSignal wire(s, kStepNs);
  std::size_t bad = 99;
  EXPECT_EQ(wire.check(sample(0, {1.0, kNaN, 1e300}), bad), Rejection::none);
}

// --- decode: time ---------------------------------------------------------------

TEST(WireDecode, NegativeTimeIsRefusedAndLeavesTheSampleAlone) {
  const auto s = wire_spec("r1/pose", {"x", "y", "theta"}, "Pose2D");
  const WireSignal wire(s, kStepNs);
  msg::Pose2D m;
  m.x(1.0);
  m.header().data_time_ns(-1);
  auto out = sample(7, {3.0});
  std::size_t bad = 99;
  EXPECT_EQ(wire.decode(&m, out, bad), Rejection::negative_time);
  EXPECT_EQ(out.step, 7);
  EXPECT_EQ(out.values[0], 3.0);
  EXPECT_EQ(bad, 99u);
  m.header().data_time_ns(0);  // time 0 is step 0, valid
  EXPECT_EQ(wire.decode(&m, out, bad), Rejection::none);
  EXPECT_EQ(out.step, 0);
  EXPECT_EQ(out.values[0], 1.0);
}

TEST(WireDecode, StepIsTheNearestOneToTheDataTime) {
  const auto s = wire_spec("r1/pose", {"x"}, "Pose2D");
  const WireSignal wire(s, kStepNs);
  msg::Pose2D m;
  scenario::SignalSample out;
  std::size_t bad = 0;
  const std::pair<int64_t, int64_t> cases[] = {
      {0, 0}, {kStepNs / 2 - 1, 0}, {kStepNs / 2, 1}, {3 * kStepNs - 1, 3}, {3 * kStepNs + kStepNs / 2 - 1, 3}};
  for (const auto& [t, step] : cases) {
    m.header().data_time_ns(t);
    ASSERT_EQ(wire.decode(&m, out, bad), Rejection::none) << t;
    EXPECT_EQ(out.step, step) << t;
  }
}

// Found by fuzzing the subscriber edge (tests/fuzz, cdr_decode): the nearest step was
// (t + step/2) / step, and a data time near the int64 limit overflowed the sum (undefined
// behaviour; in practice a huge negative step).
TEST(WireDecode, LatestDataTimeDoesNotOverflow) {
  const auto s = wire_spec("r1/pose", {"x"}, "Pose2D");
  const WireSignal wire(s, kStepNs);
  msg::Pose2D m;
  scenario::SignalSample out;
  std::size_t bad = 0;
  constexpr int64_t kMax = std::numeric_limits<int64_t>::max();
  m.header().data_time_ns(kMax);
  ASSERT_EQ(wire.decode(&m, out, bad), Rejection::none);
  EXPECT_EQ(out.step, kMax / kStepNs);  // 9223372036854775807 = 922337203685 steps + 4775807 ns < half a step
  m.header().data_time_ns(kMax - 4'775'807 - kStepNs + kStepNs / 2);  // half way below the last whole step
  ASSERT_EQ(wire.decode(&m, out, bad), Rejection::none);
  EXPECT_EQ(out.step, kMax / kStepNs);
}

TEST(WireDecode, BeforeTheEpochIsANegativeStepNotAnError) {
  // Realtime: data times are wall-clock; a sample from before the run's start decodes to a
  // negative step (not yet valid for any reader), while a negative time is refused.
  const auto s = wire_spec("r1/pose", {"x"}, "Pose2D");
  WireSignal wire(s, kStepNs);
  const int64_t epoch = 1'700'000'000'000'000'000;
  wire.set_epoch(epoch);
  msg::Pose2D m;
  scenario::SignalSample out;
  std::size_t bad = 0;
  m.header().data_time_ns(epoch + 5 * kStepNs);
  ASSERT_EQ(wire.decode(&m, out, bad), Rejection::none);
  EXPECT_EQ(out.step, 5);
  m.header().data_time_ns(epoch - kStepNs);
  ASSERT_EQ(wire.decode(&m, out, bad), Rejection::none);
  EXPECT_EQ(out.step, -1);
  m.header().data_time_ns(epoch - kStepNs / 2 - 1);  // nearer step -1 than step 0
  ASSERT_EQ(wire.decode(&m, out, bad), Rejection::none);
  EXPECT_EQ(out.step, -1);
  m.header().data_time_ns(epoch - kStepNs / 2);  // half way: rounds up, as after the epoch
  ASSERT_EQ(wire.decode(&m, out, bad), Rejection::none);
  EXPECT_EQ(out.step, 0);
  // encode stamps the epoch back: encode, decode is the identity on the step.
  wire.encode(sample(-3, {1.0}), &m);
  EXPECT_EQ(m.header().data_time_ns(), epoch - 3 * kStepNs);
  ASSERT_EQ(wire.decode(&m, out, bad), Rejection::none);
  EXPECT_EQ(out.step, -3);
}

TEST(WireDecode, WrongJointCountLeavesTheSampleAlone) {
  const auto s = wire_spec("arm/joint_states", {"phi1", "phi2", "dphi1", "dphi2"}, "JointState");
  const WireSignal wire(s, kStepNs);
  msg::JointState m;
  wire.encode(sample(2, {0.1, 0.2, 0.3, 0.4}), &m);
  EXPECT_EQ(m.count(), 2);
  m.count(3);
  auto out = sample(9, {5.0});
  std::size_t bad = 99;
  EXPECT_EQ(wire.decode(&m, out, bad), Rejection::wrong_count);
  EXPECT_EQ(out.step, 9);
  EXPECT_EQ(out.values[0], 5.0);
  EXPECT_EQ(bad, 99u);
  // A wrong count wins over bad values (the message is not this signal's shape at all).
  m.position()[0] = kNaN;
  EXPECT_EQ(wire.decode(&m, out, bad), Rejection::wrong_count);
}

// --- names ----------------------------------------------------------------------

TEST(WireTypeNames, UnknownNamesFindNothing) {
  ASSERT_NE(find_wire_type("Pose2D"), nullptr);
  EXPECT_EQ(find_wire_type("plexus::msg::Pose2D"), find_wire_type("Pose2D"));
  EXPECT_EQ(find_wire_type("Pose3D"), nullptr);
  EXPECT_EQ(find_wire_type(""), nullptr);
  EXPECT_EQ(find_wire_type("pose2d"), nullptr);          // names are case-sensitive
  EXPECT_EQ(find_wire_type("plexus::msg::"), nullptr);   // the scope alone
  EXPECT_EQ(find_wire_type("plexus::Pose2D"), nullptr);  // another scope
  EXPECT_EQ(find_wire_type("other::msg::Pose2D"), nullptr);
  EXPECT_EQ(find_wire_type("Pose2D "), nullptr);
  EXPECT_EQ(find_wire_type("plexus::msg::plexus::msg::Pose2D"), nullptr);  // the scope is stripped once
}

TEST(WireTypeNames, EveryRejectionHasItsOwnText) {
  std::set<std::string> texts;
  for (auto r : {Rejection::none, Rejection::negative_time, Rejection::non_finite, Rejection::out_of_range,
                 Rejection::wrong_count}) {
    const std::string t = to_string(r);
    EXPECT_NE(t, "?");
    EXPECT_TRUE(texts.insert(t).second) << t;
  }
}

TEST(WireBinding, ErrorsNameTheSignalItsProducerAndTheCause) {
  const auto no_type = wire_spec("r1/x", {"x"}, "");
  EXPECT_EQ(input_error_of([&] { const WireSignal w(no_type, kStepNs); }),
            "signal 'r1/x' (produced by 'r1/gps') has no IDL message type, so it cannot travel over DDS; run this "
            "scenario with `plexus sim`");
  const auto unknown = wire_spec("r1/x", {"x"}, "Pose3D");
  EXPECT_EQ(input_error_of([&] { const WireSignal w(unknown, kStepNs); }),
            "signal 'r1/x' (produced by 'r1/gps'): 'Pose3D' is not a known message type (idl/plexus/msg, or a package "
            "of a plugin the scenario loads)");
  const auto bad_field = wire_spec("r1/x", {"x", "w"}, "Pose2D");
  EXPECT_EQ(input_error_of([&] { const WireSignal w(bad_field, kStepNs); }),
            "signal 'r1/x' (produced by 'r1/gps'): field 'w' is not a member of Pose2D (its fields: x, y, theta; "
            "docs/topics.md)");
  const auto twice = wire_spec("r1/x", {"x", "x"}, "Pose2D");
  EXPECT_EQ(
      input_error_of([&] { const WireSignal w(twice, kStepNs); }),
      "signal 'r1/x' (produced by 'r1/gps'): field 'x' fills a member of Pose2D that another of its fields fills");
}

}  // namespace
}  // namespace plexus::distributed
