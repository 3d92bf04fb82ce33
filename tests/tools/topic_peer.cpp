// topic_peer: a plexus process with one Pose2D (or LatencyProbe) writer or reader on a topic, with a QoS
// profile, for the `plexus topic/record/replay` tests.
//
//   topic_peer pub --dds fast --domain 180 --topic tools/pose --profile sensor --rate 50 --duration 20
//   topic_peer sub --dds cyclone --domain 180 --topic tools/pose --profile sensor_reliable --duration 20
//   topic_peer sub ... --expect 100     (exit 1 unless 100 samples arrived; ends once they have)
//
// pub publishes x = k, y = 2k, theta = 0.5 (k = 1, 2, ...) until --count or --duration.
// --type probe uses LatencyProbe (a bounded sequence, not a plain type) instead of Pose2D.
#include <CLI/CLI.hpp>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <thread>

#include "plexus/base/clock.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/base/logging.hpp"
#include "plexus/runtime/participant.hpp"
#include "plexus/runtime/periodic_loop.hpp"

namespace {
std::atomic<bool> g_stop{false};
void on_signal(int) { g_stop = true; }

void fill(plexus::msg::Pose2D& m, int k) { m.x(k), m.y(2.0 * k), m.theta(0.5); }
void fill(plexus::msg::LatencyProbe& m, int k) { m.payload().assign(static_cast<std::size_t>(k % 64), 0x5a); }

template <class M>
int run(plexus::rt::Participant& p, const std::string& role, const std::string& topic,
        const plexus::rt::QosProfile& qos, double rate, int64_t end, int count, int expect, bool wait_reader) {
  using namespace plexus;
  if (role == "sub") {
    auto sub = p.subscriber<M>(topic, qos);
    M m;
    int received = 0;
    while (!g_stop && monotonic_ns() < end && (expect == 0 || received < expect)) {
      if (sub.wait(50'000'000))
        while (sub.take(m)) ++received;
    }
    if (received < expect) {
      std::fprintf(stderr, "topic_peer sub: %d samples on %s, expected at least %d\n", received, topic.c_str(), expect);
      return 1;
    }
    return 0;
  }
  auto pub = p.publisher<M>(topic, qos);
  if (wait_reader) {
    while (pub.matched_count() == 0 && !g_stop && monotonic_ns() < end)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
  }
  rt::PeriodicLoop loop({.rate_hz = rate});
  int k = 0;
  M m;
  loop.run([&](const rt::PeriodicLoop::Tick& t) {
    ++k;
    m.header().origin_time_ns(0);
    m.header().data_time_ns(t.deadline_ns);
    fill(m, k);
    pub.publish(m);
    return !g_stop && monotonic_ns() < end && (count == 0 || k < count);
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  return 0;
}
}  // namespace

int main(int argc, char** argv) {
  using namespace plexus;
  CLI::App app{"topic_peer: one Pose2D (or LatencyProbe) writer or reader"};
  std::string role, dds = "fast", topic = "tools/pose", profile = "sensor", transport = "auto", type = "pose";
  int domain = 180, count = 0, expect = 0;
  double rate = 50, duration = 20;
  bool wait_reader = false;
  app.add_option("role", role)->required()->check(CLI::IsMember({"pub", "sub"}));
  app.add_option("--dds", dds);
  app.add_option("--domain", domain);
  app.add_option("--topic", topic);
  app.add_option("--profile", profile);
  app.add_option("--rate", rate);
  app.add_option("--count", count);
  app.add_option("--duration", duration);
  app.add_option("--expect", expect, "sub: exit 1 unless at least this many samples arrived (it ends once they have)");
  app.add_flag("--wait-reader", wait_reader, "pub: start publishing once a reader matched");
  app.add_option("--transport", transport, "auto, udp or shm");
  app.add_option("--type", type, "pose (Pose2D, a plain type) or probe (LatencyProbe, not plain)")
      ->check(CLI::IsMember({"pose", "probe"}));
  CLI11_PARSE(app, argc, argv);
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  try {
    init_logging("topic_peer", "", "error");
    const auto qos = rt::QosProfiles::load(rt::default_qos_file()).get(profile);
    rt::ParticipantOptions po;
    po.vendor = rt::parse_vendor(dds);
    po.domain_id = domain;
    po.name = "topic_peer_" + role;
    po.network.transport = rt::parse_transport(transport);
    auto p = rt::Participant::create(po);
    const int64_t end = monotonic_ns() + static_cast<int64_t>(duration * 1e9);
    if (type == "probe") return run<msg::LatencyProbe>(*p, role, topic, qos, rate, end, count, expect, wait_reader);
    return run<msg::Pose2D>(*p, role, topic, qos, rate, end, count, expect, wait_reader);
  } catch (const InputError& e) {
    std::fprintf(stderr, "topic_peer: error: %s\n", e.what());
    return 2;
  }
}
