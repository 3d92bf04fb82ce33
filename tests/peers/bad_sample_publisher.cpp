// bad_sample_publisher: publishes samples of a typed service topic with one field set to a
// given value (NaN, inf, out of range), to test the subscriber edge check end to end.
//
//   bad_sample_publisher --dds fast --domain 7 --topic r1/position --type PositionMeasurement
//                        --field x --value nan --count 5
//
// Waits for a matched reader (and 1 s more), publishes `count` samples at most at 50 Hz
// (reliable, each acknowledged before the next), and exits 0.
//
// --health TOPIC (the subscriber's heartbeat): afterwards, waits until the heartbeat's
// rejected_inputs has grown by `count`, and resends what is missing, at most twice. A reader
// that discovers this writer after the writer discovered it (under load, more than the 1 s
// allowed) acknowledges what was written before as a volatile reader and never delivers it
// (a DDS rule, not the edge check). A sample that reached the subscriber and was accepted
// is never made up for: it is the failure the edge-check test looks for, and the count
// comes out short (exit 1).
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <thread>

#include "plexus/base/clock.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/distributed/wire.hpp"
#include "plexus/msg/messages.hpp"
#include "plexus/runtime/participant.hpp"

int main(int argc, char** argv) {
  using namespace plexus;
  CLI::App app{"bad_sample_publisher: one field of a typed topic set to a given value"};
  std::string dds = "fast", topic, type, field, value;
  std::string health;
  int domain = 0, count = 5;
  app.add_option("--dds", dds);
  app.add_option("--domain", domain);
  app.add_option("--topic", topic)->required();
  app.add_option("--type", type)->required();
  app.add_option("--field", field)->required();
  app.add_option("--value", value)->required();
  app.add_option("--count", count);
  app.add_option("--health", health, "the subscriber's heartbeat topic: confirm that every sample was counted");
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
    std::optional<rt::Subscriber<msg::Heartbeat>> beats;
    if (!health.empty()) beats.emplace(p->subscriber<msg::Heartbeat>(health, profiles.get("health")));
    const int64_t give_up = monotonic_ns() + 10'000'000'000;
    while (pub.matched_count() == 0) {
      if (monotonic_ns() > give_up) throw std::runtime_error("no reader of " + topic + " within 10 s");
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    // The writer matched the reader; give the reader time to match the writer too (a volatile
    // reader that discovers a writer late may skip what it wrote before), also under load.
    std::this_thread::sleep_for(std::chrono::milliseconds(1000));
    scenario::SignalSample s;
    s.values[0] = std::stod(value);  // "nan", "inf", "2e6"
    // The subscriber's refusal count once it reaches `target` (heartbeats come once a second),
    // or the highest seen within `timeout_ns` (-1: no heartbeat).
    auto refused = [&](int64_t target, int64_t timeout_ns) -> int64_t {
      int64_t n = -1;
      msg::Heartbeat hb;
      for (const int64_t until = monotonic_ns() + timeout_ns; n < target && monotonic_ns() < until;) {
        while (beats->take(hb)) n = std::max(n, static_cast<int64_t>(hb.rejected_inputs()));
        if (n < target) beats->wait(100'000'000);
      }
      return n;
    };
    int64_t before = 0;
    if (beats) {
      before = refused(0, 5'000'000'000);
      if (before < 0) throw std::runtime_error("no heartbeat on " + health + " within 5 s");
    }
    auto send = [&](int n) {
      for (int i = 0; i < n; ++i) {
        s.step = (wall_time_ns() / 10'000'000);  // data time: now (wall clock, as a realtime producer)
        pub.publish(s, 0);
        // Each sample acknowledged before the next (keep_last 1 keeps only the newest), and
        // 20 ms apart so that a 100 Hz reader takes each one before the next arrives. An
        // acknowledgement is not a delivery: a reader that discovered this writer late
        // acknowledges and drops (see the top of this file, --health).
        if (!pub.wait_for_acks(5'000'000'000))
          throw std::runtime_error("sample " + std::to_string(i + 1) + " of " + topic + " not acknowledged within 5 s");
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
      }
    };
    send(count);
    for (int round = 0; beats && round < 3; ++round) {
      // Up to 6 s for the beat that counts them all (beats come once a second, later under
      // load): a slow beat must not be taken for a lost sample, or the resend over-counts.
      const int64_t counted = refused(before + count, 6'000'000'000) - before;
      if (counted >= count) break;
      if (round == 2 || counted < 0) {
        std::fprintf(stderr, "bad_sample_publisher: %s counted %lld of %d samples\n", health.c_str(),
                     static_cast<long long>(counted), count);
        return 1;
      }
      std::printf("%s counted %lld of %d samples: resending %lld (not delivered)\n", health.c_str(),
                  static_cast<long long>(counted), count, static_cast<long long>(count - counted));
      send(static_cast<int>(count - counted));
    }
    std::printf("published %d samples of %s with %s = %s\n", count, topic.c_str(), field.c_str(), value.c_str());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bad_sample_publisher: %s\n", e.what());
    return 2;
  }
}
