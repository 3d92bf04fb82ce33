// bad_sample_publisher: publishes samples of a typed service topic with one field set to a
// given value (NaN, inf, out of range), to test the subscriber edge check end to end.
//
//   bad_sample_publisher --dds fast --domain 7 --topic r1/position --type PositionMeasurement
//                        --field x --value nan --count 5
//
// Waits for a matched reader, publishes `count` samples at 50 Hz (reliable), and exits 0.
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <thread>

#include "plexus/base/clock.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/distributed/wire.hpp"
#include "plexus/runtime/participant.hpp"

int main(int argc, char** argv) {
  using namespace plexus;
  CLI::App app{"bad_sample_publisher: one field of a typed topic set to a given value"};
  std::string dds = "fast", topic, type, field, value;
  int domain = 0, count = 5;
  app.add_option("--dds", dds);
  app.add_option("--domain", domain);
  app.add_option("--topic", topic)->required();
  app.add_option("--type", type)->required();
  app.add_option("--field", field)->required();
  app.add_option("--value", value)->required();
  app.add_option("--count", count);
  CLI11_PARSE(app, argc, argv);
  try {
    scenario::SignalSpec spec;
    spec.name = topic;
    spec.fields = {field};
    spec.producer = "bad_sample_publisher";
    spec.message = type;
    rt::ParticipantOptions po;
    po.vendor = rt::parse_vendor(dds);
    po.domain_id = domain;
    po.name = "bad_sample_publisher";
    auto p = rt::Participant::create(po);
    const auto profiles = rt::QosProfiles::load(rt::default_qos_file());
    distributed::WirePublisher pub(*p, spec, 10'000'000, profiles.get("state"));  // the topic is the signal's name
    const int64_t give_up = monotonic_ns() + 10'000'000'000;
    while (pub.matched_count() == 0) {
      if (monotonic_ns() > give_up) throw std::runtime_error("no reader of " + topic + " within 10 s");
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    scenario::SignalSample s;
    s.values[0] = std::stod(value);  // "nan", "inf", "2e6"
    for (int i = 0; i < count; ++i) {
      s.step = (wall_time_ns() / 10'000'000);  // data time: now (wall clock, as a realtime producer)
      pub.publish(s, 0);
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(500));  // let reliable delivery finish
    std::printf("published %d samples of %s with %s = %s\n", count, topic.c_str(), field.c_str(), value.c_str());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bad_sample_publisher: %s\n", e.what());
    return 2;
  }
}
