// libFuzzer target: the subscriber edge of every message type (docs/topics.md). Bytes as a
// DDS reader receives them go through both vendors' decode paths and, for the types that
// carry scenario signals, through the edge check every service applies
// (common/distributed: WireSignal::decode and InputGuard, docs/architecture.md "Bad input").
//
// Input layout (the seeds in tests/fuzz/corpus/cdr_decode/ follow it; tools: cdr_seeds.cpp):
//   byte 0      the type: index (modulo their number) into msg::all_type_supports()
//   byte 1      the signal's shape and clock: bits 0-3 = joints - 1 (types with a joint
//               count), bit 4 = realtime (epoch at the run's start on the wall clock) instead
//               of lockstep (epoch 0), bits 5-6 = the base step (1, 2, 10 or 1000 ms)
//   the rest    the serialized sample: XCDR1 with its 4-byte encapsulation header
//
// Checked, for every input: no crash, leak, hang or undefined behaviour, and no exception out
// of a decode function (one would end the DDS thread that called it). The Cyclone DDS path
// (TypeSupport::deserialize, called from common/runtime/src/cyclone/cdr_sertype.cpp) and the
// Fast DDS path (the generated PubSubType::deserialize) accept and refuse the same bytes and
// decode them to the same sample; a decoded sample serializes again within the type's
// largest size, to bytes that decode to the same sample; its JSON (plexus topic echo) prints.
// A sample the edge check accepts has every field finite and within its range.
#include <fastdds/rtps/common/SerializedPayload.h>
#include <fastdds/dds/topic/TopicDataType.hpp>

#include <spdlog/spdlog.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <exception>
#include <map>
#include <memory>
#include <string>
#include <typeinfo>
#include <vector>

#include "fuzz_support.hpp"
#include "input_guard.hpp"
#include "plexus/distributed/wire.hpp"
#include "plexus/msg/messages.hpp"

namespace {

using plexus::fuzz::finding;
namespace msg = plexus::msg;
namespace dist = plexus::distributed;

struct Sample {
  const msg::TypeSupport* ts;
  void* p;
  explicit Sample(const msg::TypeSupport* t) : ts(t), p(t->create()) {}
  ~Sample() { ts->destroy(p); }
  Sample(const Sample&) = delete;
  Sample& operator=(const Sample&) = delete;
};

std::vector<unsigned char> serialize(const msg::TypeSupport& ts, const void* sample) {
  std::vector<unsigned char> buf(ts.max_cdr_size);
  const std::size_t n = ts.serialize(sample, buf.data(), buf.size());
  if (n == 0)
    finding(std::string(ts.type_name) + ": a decoded sample does not serialize within the type's largest size");
  buf.resize(n);
  return buf;
}

bool decode_cyclone(const msg::TypeSupport& ts, const uint8_t* data, std::size_t size, void* sample) {
  try {
    return ts.deserialize(data, size, sample);
  } catch (const std::exception& e) {
    finding(std::string(ts.type_name) + ": TypeSupport::deserialize threw " + typeid(e).name() + ": " + e.what());
  }
}

bool decode_fast(const msg::TypeSupport& ts, const uint8_t* data, std::size_t size, void* sample) {
  const std::unique_ptr<eprosima::fastdds::dds::TopicDataType> type(ts.make_fast_type());
  eprosima::fastrtps::rtps::SerializedPayload_t payload(static_cast<uint32_t>(size));
  if (size > 0) std::memcpy(payload.data, data, size);
  payload.length = static_cast<uint32_t>(size);
  try {
    return type->deserialize(&payload, sample);
  } catch (const std::exception& e) {
    finding(std::string(ts.type_name) + ": the Fast DDS PubSubType::deserialize threw " + typeid(e).name() + ": " +
            e.what());
  }
}

/// The signal a service could read from a type with a joint count: every field of the type
/// whose array index is below the count, one name per member (aliases dropped).
const plexus::scenario::SignalSpec& signal_of(const dist::WireType& type, int joints) {
  static std::map<std::pair<const dist::WireType*, int>, plexus::scenario::SignalSpec> specs;
  auto [it, fresh] = specs.try_emplace({&type, joints});
  plexus::scenario::SignalSpec& spec = it->second;
  if (fresh) {
    spec.name = "r1/fuzz";
    spec.producer = "fuzz";
    spec.message = type.name;
    const dist::MessagePtr probe{type.support->create(), type.support->destroy};
    std::vector<const void*> places;
    for (const auto& s : type.slots) {
      if (static_cast<int>(s.index) >= joints) continue;
      const void* place = static_cast<const char*>(s.member(probe.get())) + s.index * sizeof(double);
      if (std::find(places.begin(), places.end(), place) != places.end()) continue;
      if (spec.fields.size() == plexus::scenario::kMaxSignalFields) break;
      places.push_back(place);
      spec.fields.push_back(s.field);
    }
  }
  return spec;
}

void edge_check(const msg::TypeSupport& ts, const void* sample, uint8_t shape) {
  const dist::WireType* type = dist::find_wire_type(ts.type_name);
  if (!type || !type->support->header) return;  // not a signal type (clock, health, latency probe, link status)
  static const int64_t kStepNs[] = {1'000'000, 2'000'000, 10'000'000, 1'000'000'000};
  const int joints = type->count ? 1 + (shape & 15) : 16;
  const int64_t step_ns = kStepNs[(shape >> 5) & 3];
  dist::WireSignal wire(signal_of(*type, joints), step_ns);
  if (shape & 16) wire.set_epoch(1'700'000'000'000'000'000);  // a realtime run's start, 2023

  plexus::scenario::SignalSample s;
  std::size_t bad = 0;
  const dist::Rejection r = wire.decode(sample, s, bad);
  if (r == dist::Rejection::none) {
    for (std::size_t i = 0; i < wire.spec().fields.size(); ++i) {
      const auto& slot = *std::find_if(type->slots.begin(), type->slots.end(),
                                       [&](const dist::WireSlot& x) { return x.field == wire.spec().fields[i]; });
      CHECK(std::isfinite(s.values[i]) && s.values[i] >= slot.min && s.values[i] <= slot.max);
    }
  } else {
    CHECK(std::string(dist::to_string(r)) != "?");
    if (r == dist::Rejection::non_finite || r == dist::Rejection::out_of_range) CHECK(bad < wire.spec().fields.size());
  }
  // The same through the guard a service host uses (counts; logs at most once a second).
  static plexus::distributed::detail::InputGuard guard("fuzz");
  const uint64_t before = guard.rejected();
  plexus::scenario::SignalSample g;
  const bool accepted = guard.accept(wire, sample, g);
  CHECK(accepted == (r == dist::Rejection::none));
  CHECK(guard.rejected() == before + (accepted ? 0 : 1));
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  spdlog::set_level(spdlog::level::off);  // InputGuard's rate-limited warnings
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  const auto& all = msg::all_type_supports();
  const msg::TypeSupport& ts = *all[data[0] % all.size()];
  const uint8_t shape = data[1];
  data += 2;
  size -= 2;

  Sample cyc(&ts), fast(&ts);
  const bool ok_cyc = decode_cyclone(ts, data, size, cyc.p);
  const bool ok_fast = decode_fast(ts, data, size, fast.p);
  if (ok_cyc != ok_fast)
    finding(std::string(ts.type_name) + ": the vendors' decode paths disagree: Cyclone " +
            (ok_cyc ? "accepts" : "refuses") + ", Fast DDS " + (ok_fast ? "accepts" : "refuses"));
  if (!ok_cyc) return 0;

  const auto bytes = serialize(ts, cyc.p);
  CHECK(bytes == serialize(ts, fast.p));
  Sample again(&ts);
  CHECK(ts.deserialize(bytes.data(), bytes.size(), again.p));
  CHECK(serialize(ts, again.p) == bytes);
  if (ts.header) CHECK(ts.header(cyc.p) != nullptr);
  try {
    CHECK(!ts.to_json(cyc.p).dump().empty());
  } catch (const std::exception& e) {
    finding(std::string(ts.type_name) + ": the sample's JSON does not print: " + e.what());
  }
  edge_check(ts, cyc.p, shape);
  return 0;
}
