// libFuzzer target: the QoS profile file parser (common/runtime/src/qos.cpp; the format of
// deploy/qos.yaml, docs/runtime.md). The input is the text of a QoS file.
//
// Checked: QosProfiles::parse returns profiles or refuses the text with an InputError of
// one line that names the file; nothing else escapes, no crash, leak, hang or undefined
// behaviour. Every profile it accepts is one both vendors can apply as it is: depth in
// 1..100000, every duration 0 (none/infinite) or within [1 ns, 1e9 s] (Fast DDS holds whole
// seconds in an int32, Cyclone DDS nanoseconds in an int64; a value beyond them would wrap
// in the conversion, one below 1 ns would turn into 0, which means something else).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>
#include <typeinfo>

#include "fuzz_support.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/runtime/qos.hpp"

namespace {

using plexus::fuzz::finding;
using plexus::rt::QosProfile;

void check_duration(double s) {
  CHECK(std::isfinite(s));
  CHECK(s == 0.0 || (s >= 1e-9 && s <= 1e9));
}

void check_profile(const std::string& name, const QosProfile& p) {
  CHECK(p.name == name);
  CHECK(p.depth >= 1 && p.depth <= 100000);
  check_duration(p.max_blocking_time_s);
  check_duration(p.deadline_s);
  check_duration(p.liveliness_lease_s);
  check_duration(p.lifespan_s);
  check_duration(p.latency_budget_s);
  CHECK(!plexus::rt::describe(p).empty());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  const std::string origin = "fuzz/qos.yaml";
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const auto profiles = plexus::rt::QosProfiles::parse(text, origin);
    CHECK(!profiles.all().empty());
    for (const auto& [name, p] : profiles.all()) {
      check_profile(name, p);
      CHECK(&profiles.get(name) == &p);
    }
    if (!profiles.contains("no such profile")) {
      try {
        profiles.get("no such profile");
        finding("get() of an unknown profile did not throw");
      } catch (const plexus::InputError& e) {
        CHECK(std::string(e.what()).rfind(origin + ": unknown QoS profile", 0) == 0);
      }
    }
  } catch (const plexus::InputError& e) {
    plexus::fuzz::check_one_line(e.what());
    if (std::string(e.what()).rfind(origin, 0) != 0)
      finding(std::string("the refusal does not name the file: ") + e.what());
  } catch (const std::exception& e) {
    finding(std::string("an exception other than InputError escaped the QoS parser: ") + typeid(e).name() + ": " +
            e.what());
  }
  return 0;
}
