// The wire contract and the edge check on received signals: fields land in the named
// members of their IDL type, what passes, what is refused, and that a refusal leaves the
// destination sample untouched.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "input_guard.hpp"
#include "plexus/base/input_error.hpp"

namespace plexus::distributed::detail {
namespace {

constexpr int64_t kStepNs = 10'000'000;

scenario::SignalSpec spec(std::string name, std::vector<std::string> fields, std::string message) {
  scenario::SignalSpec s;
  s.name = std::move(name);
  s.fields = std::move(fields);
  s.producer = "test";
  s.message = std::move(message);
  return s;
}

msg::Pose2D pose(int64_t step, double x, double y, double theta) {
  msg::Pose2D m;
  m.header().data_time_ns(step * kStepNs);
  m.x(x);
  m.y(y);
  m.theta(theta);
  return m;
}

TEST(WireSignal, FieldsLandInTheirNamedMembers) {
  const auto s = spec("r1/reference", {"x", "y", "dx", "dy", "ddx", "ddy"}, "PlanarReference");
  const WireSignal wire(s, kStepNs);
  scenario::SignalSample in;
  in.step = 42;
  for (std::size_t i = 0; i < 6; ++i) in.values[i] = 1.0 + static_cast<double>(i);
  msg::PlanarReference m;
  wire.encode(in, &m);
  EXPECT_EQ(m.header().data_time_ns(), 420'000'000);
  EXPECT_EQ(m.position()[0], 1.0);
  EXPECT_EQ(m.position()[1], 2.0);
  EXPECT_EQ(m.velocity()[1], 4.0);
  EXPECT_EQ(m.acceleration()[0], 5.0);
  scenario::SignalSample out;
  std::size_t bad = 99;
  ASSERT_EQ(wire.decode(&m, out, bad), Rejection::none);
  EXPECT_EQ(out.step, 42);
  for (std::size_t i = 0; i < 6; ++i) EXPECT_EQ(out.values[i], in.values[i]);
  EXPECT_EQ(bad, 99u);
}

TEST(WireSignal, FieldOrderIsTheSignalsNotTheMessages) {
  // A consumer's fields in another order than the members: still bound by name.
  const auto s = spec("r1/heading", {"z4", "theta", "L", "z3"}, "HeadingEstimate");
  const WireSignal wire(s, kStepNs);
  scenario::SignalSample in;
  in.step = 1;
  in.values[0] = 0.5, in.values[1] = 0.25, in.values[2] = 0.6, in.values[3] = -0.5;
  msg::HeadingEstimate m;
  wire.encode(in, &m);
  EXPECT_EQ(m.heading(), 0.25);
  EXPECT_EQ(m.direction()[0], -0.5);
  EXPECT_EQ(m.direction()[1], 0.5);
  EXPECT_EQ(m.gain(), 0.6);
  EXPECT_EQ(m.speed(), 0.0);  // not in the signal: zero
}

TEST(WireSignal, JointMessagesCarryTheirCountAndRefuseAnother) {
  std::vector<std::string> fields;
  for (int i = 1; i <= 6; ++i) fields.push_back("phi" + std::to_string(i));
  for (int i = 1; i <= 6; ++i) fields.push_back("dphi" + std::to_string(i));
  const auto s = spec("arm/joint_states", fields, "JointState");
  const WireSignal wire(s, kStepNs);
  scenario::SignalSample in;
  in.step = 3;
  for (std::size_t i = 0; i < 12; ++i) in.values[i] = 0.1 * static_cast<double>(i);
  msg::JointState m;
  wire.encode(in, &m);
  EXPECT_EQ(m.count(), 6);
  EXPECT_EQ(m.velocity()[5], in.values[11]);
  scenario::SignalSample out;
  std::size_t bad = 0;
  EXPECT_EQ(wire.decode(&m, out, bad), Rejection::none);
  m.count(17);  // more than MAX_JOINTS
  EXPECT_EQ(wire.decode(&m, out, bad), Rejection::wrong_count);
  m.count(5);
  EXPECT_EQ(wire.decode(&m, out, bad), Rejection::wrong_count);
}

TEST(WireSignal, BadBindingsAreInputErrors) {
  const auto unknown_type = spec("r1/x", {"x"}, "NoSuchType");
  EXPECT_THROW(WireSignal(unknown_type, kStepNs), InputError);
  const auto no_type = spec("r1/x", {"x"}, "");
  EXPECT_THROW(WireSignal(no_type, kStepNs), InputError);
  const auto unknown_field = spec("r1/x", {"x", "w"}, "Pose2D");
  EXPECT_THROW(WireSignal(unknown_field, kStepNs), InputError);
  const auto aliased = spec("r1/heading", {"z2", "z3"}, "HeadingEstimate");  // both direction[0]
  EXPECT_THROW(WireSignal(aliased, kStepNs), InputError);
}

TEST(WireSignal, RefusesEachKindOfBadSample) {
  const auto s = spec("r1/gps", {"x", "y", "theta"}, "Pose2D");
  const WireSignal wire(s, kStepNs);
  scenario::SignalSample out;
  out.step = 7;
  out.values[0] = 3.0;
  std::size_t bad = 0;
  auto m = pose(1, 0, std::nan(""), 0);
  EXPECT_EQ(wire.decode(&m, out, bad), Rejection::non_finite);
  EXPECT_EQ(bad, 1u);
  m = pose(1, 0, 0, std::numeric_limits<double>::infinity());
  EXPECT_EQ(wire.decode(&m, out, bad), Rejection::non_finite);
  EXPECT_EQ(bad, 2u);
  m = pose(1, 2e6, 0, 0);  // 2000 km: out of a position's physical range
  EXPECT_EQ(wire.decode(&m, out, bad), Rejection::out_of_range);
  EXPECT_EQ(bad, 0u);
  m = pose(-1, 0, 0, 0);
  EXPECT_EQ(wire.decode(&m, out, bad), Rejection::negative_time);
  // A refused sample never reaches the destination (no half-written estimator input).
  EXPECT_EQ(out.step, 7);
  EXPECT_EQ(out.values[0], 3.0);
}

TEST(WireSignal, RangeChecksUseTheMembersBounds) {
  const auto s = spec("r1/terrain", {"class", "confidence"}, "TerrainClass");
  const WireSignal wire(s, kStepNs);
  msg::TerrainClass m;
  m.terrain_id(2);
  m.confidence(1.5);  // a fraction
  scenario::SignalSample out;
  std::size_t bad = 0;
  EXPECT_EQ(wire.decode(&m, out, bad), Rejection::out_of_range);
  EXPECT_EQ(bad, 1u);
  m.confidence(0.8);
  ASSERT_EQ(wire.decode(&m, out, bad), Rejection::none);
  EXPECT_EQ(out.values[0], 2.0);
}

TEST(InputGuard, CountsRefusalsAndPassesGoodSamples) {
  InputGuard guard("test host");
  const auto s = spec("r1/gps", {"x", "y", "theta"}, "Pose2D");
  const WireSignal wire(s, kStepNs);
  scenario::SignalSample out;
  auto m = pose(0, 1, 2, 3);
  EXPECT_TRUE(guard.accept(wire, &m, out));
  EXPECT_EQ(guard.rejected(), 0u);
  for (int i = 0; i < 5; ++i) {
    m = pose(i + 1, std::nan(""), 0, 0);
    EXPECT_FALSE(guard.accept(wire, &m, out));
  }
  m = pose(9, 0, 0, -std::numeric_limits<double>::infinity());
  EXPECT_FALSE(guard.accept(wire, &m, out));
  EXPECT_EQ(guard.rejected(), 6u);
  EXPECT_EQ(out.step, 0);
  EXPECT_EQ(out.values[0], 1.0);
}

TEST(WireTypes, EveryTypeHasItsTypeSupportAndDistinctFieldNames) {
  ASSERT_FALSE(msg::all_wire_types().empty());
  for (const WireType* t : msg::all_wire_types()) {
    ASSERT_NE(t->support, nullptr) << t->name;
    EXPECT_EQ(std::string(t->support->type_name), std::string("plexus::msg::") + t->name);
    EXPECT_EQ(find_wire_type(t->name), t);
    for (std::size_t i = 0; i < t->slots.size(); ++i)
      for (std::size_t j = 0; j < i; ++j) EXPECT_NE(t->slots[i].field, t->slots[j].field) << t->name;
  }
}

// The largest value a slot's member type holds (the edge check cannot be tested beyond it).
double type_max(WireSlot::Kind k) {
  using K = WireSlot::Kind;
  switch (k) {
    case K::i8: return 127;
    case K::u8: return 255;
    case K::i16: return 32767;
    case K::u16: return 65535;
    case K::i32: return 2147483647.0;
    case K::u32: return 4294967295.0;
    case K::boolean: return 1;
    default: return std::numeric_limits<double>::infinity();
  }
}

}  // namespace
}  // namespace plexus::distributed::detail

namespace plexus::distributed::detail {
namespace {

// Every member of every message type a service reads: a non-finite value, or one beyond its
// physical range, refuses the whole sample and leaves the destination untouched.
TEST(WireTypes, EveryMemberOfEveryTypeIsCheckedAtTheEdge) {
  for (const WireType* tp : msg::all_wire_types()) {
    const WireType& t = *tp;
    if (!t.support->header) continue;  // not a signal type: the step travels in the header
    for (const auto& slot : t.slots) {
      if (slot.kind == WireSlot::Kind::i64 || slot.kind == WireSlot::Kind::u64) continue;  // counters and times
      scenario::SignalSpec s = spec("r1/x", {slot.field}, t.name);
      const WireSignal wire(s, kStepNs);
      scenario::SignalSample good;
      good.step = 5;
      good.values[0] = std::max(slot.min, std::min(slot.max, 0.0));  // in range
      const MessagePtr m = wire.make_message();
      wire.encode(good, m.get());
      scenario::SignalSample out;
      out.step = 1;
      out.values[0] = 42.0;
      std::size_t bad = 99;
      ASSERT_EQ(wire.decode(m.get(), out, bad), Rejection::none) << t.name << "." << slot.field;
      out.step = 1;
      out.values[0] = 42.0;
      if (slot.kind == WireSlot::Kind::f64 || slot.kind == WireSlot::Kind::f32) {
        scenario::SignalSample nan = good;
        nan.values[0] = std::numeric_limits<double>::quiet_NaN();
        wire.encode(nan, m.get());
        EXPECT_EQ(wire.decode(m.get(), out, bad), Rejection::non_finite) << t.name << "." << slot.field;
      }
      if (std::isfinite(slot.max) && slot.max < type_max(slot.kind)) {
        // Beyond the top of its range (integers: within what their type can hold).
        scenario::SignalSample far = good;
        far.values[0] = std::min(slot.max * 2 + 1, type_max(slot.kind));
        wire.encode(far, m.get());
        EXPECT_EQ(wire.decode(m.get(), out, bad), Rejection::out_of_range) << t.name << "." << slot.field;
      }
      EXPECT_EQ(out.step, 1) << t.name << "." << slot.field;  // a refusal writes nothing
      EXPECT_EQ(out.values[0], 42.0) << t.name << "." << slot.field;
    }
  }
}

}  // namespace
}  // namespace plexus::distributed::detail
