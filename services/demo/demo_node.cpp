// demo_node: the two services of the backbone demo.
//
//   demo_node echo   --dds cyclone --domain 40     # republishes demo/ping on demo/pong
//   demo_node source --dds fast --domain 40 --rate 500 --count 2000
//
// The source publishes Pose2D samples on demo/ping at a fixed rate (absolute-deadline
// loop), takes the echoes from demo/pong and prints one JSON object: rates, round-trip
// percentiles from the header origin time, and loop statistics. Both exit 0 on SIGINT/SIGTERM.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <thread>
#include <vector>

#include "plexus/base/cli_style.hpp"
#include "plexus/base/clock.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/base/logging.hpp"
#include "plexus/base/teardown_deadline.hpp"
#include "plexus/runtime/participant.hpp"
#include "plexus/runtime/periodic_loop.hpp"

namespace {

std::atomic<bool> g_stop{false};
void on_signal(int) { g_stop = true; }

using namespace plexus;

bool wait_matched(auto& pub, auto& sub, double timeout_s) {
  const int64_t deadline = monotonic_ns() + static_cast<int64_t>(timeout_s * 1e9);
  while (pub.matched_count() == 0 || sub.matched_count() == 0) {
    if (g_stop || monotonic_ns() > deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return true;
}

int run_echo(rt::Participant& p, const rt::QosProfile& qos, double duration_s) {
  auto sub = p.subscriber<msg::Pose2D>("demo/ping", qos);
  auto pub = p.publisher<msg::Pose2D>("demo/pong", qos);
  msg::Pose2D m;
  const int64_t end = duration_s > 0 ? monotonic_ns() + static_cast<int64_t>(duration_s * 1e9) : INT64_MAX;
  uint64_t echoed = 0;
  while (!g_stop && monotonic_ns() < end) {
    if (!sub.wait(50'000'000)) continue;
    while (sub.take(m)) {
      pub.publish(m);  // keeps the origin time: the round trip is measured from it
      ++echoed;
    }
  }
  spdlog::info("echoed {} samples", echoed);
  return 0;
}

int run_source(rt::Participant& p, const rt::QosProfile& qos, double rate, int count, double timeout_s) {
  auto pub = p.publisher<msg::Pose2D>("demo/ping", qos);
  auto sub = p.subscriber<msg::Pose2D>("demo/pong", qos);
  if (!wait_matched(pub, sub, timeout_s)) {
    std::fprintf(stderr, "demo_node source: no echo matched within %.0f s\n", timeout_s);
    return 1;
  }
  // Warm-up: a writer can see its reader matched before that reader has matched the writer
  // (then the first samples are dropped, legitimately, under volatile durability; Fast DDS
  // -> Cyclone DDS showed up to a second of it). Ping until one echo comes back, so all four
  // endpoints know each other before anything is measured. Warm-up pings carry x = -1.
  {
    msg::Pose2D warm, back;
    warm.x(-1.0);
    bool echoed = false;
    const int64_t give_up = monotonic_ns() + static_cast<int64_t>(timeout_s * 1e9);
    while (!echoed && !g_stop && monotonic_ns() < give_up) {
      warm.header().origin_time_ns(0);
      pub.publish(warm);
      if (sub.wait(20'000'000))
        while (sub.take(back)) echoed = true;
    }
    if (!echoed) {
      std::fprintf(stderr, "demo_node source: no echo came back within %.0f s\n", timeout_s);
      return 1;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    while (sub.take(back)) {  // late warm-up echoes
    }
  }
  std::vector<int64_t> rtt;
  rtt.reserve(static_cast<std::size_t>(count));
  rt::PeriodicLoop loop({.rate_hz = rate});
  msg::Pose2D out, in;
  int sent = 0;
  const int64_t t0 = monotonic_ns();
  int64_t last_rx = t0;
  auto drain = [&] {
    while (sub.take(in)) {
      if (in.x() < 0) continue;  // a late warm-up echo
      rtt.push_back(wall_time_ns() - in.header().origin_time_ns());
      last_rx = monotonic_ns();
    }
  };
  loop.run([&](const rt::PeriodicLoop::Tick& t) {
    drain();
    if (sent < count) {
      out.header().origin_time_ns(0);  // a new chain starts here
      out.header().data_time_ns(t.deadline_ns);
      out.x(sent);
      pub.publish(out);
      ++sent;
      // Ping-pong: wait for this echo within the period, so the round trip is timestamped
      // when it arrives rather than at the next tick.
      const int64_t until = t.deadline_ns + loop.period_ns() * 9 / 10;
      for (int64_t now = monotonic_ns(); static_cast<int>(rtt.size()) < sent && now < until; now = monotonic_ns())
        if (sub.wait(until - now)) drain();
    }
    // After the last ping, wait for the missing echoes until 5 s pass without one (a loaded
    // machine can stall a process for a while; a lost sample is reported, not waited for forever).
    return !g_stop &&
           (sent < count || (static_cast<int>(rtt.size()) < count && monotonic_ns() - last_rx < 5'000'000'000));
  });
  const double elapsed = static_cast<double>(last_rx - t0) * 1e-9;
  const auto ls = loop.stats();
  std::sort(rtt.begin(), rtt.end());
  auto pct = [&](double q) {
    if (rtt.empty()) return 0.0;
    return static_cast<double>(rtt[static_cast<std::size_t>(q * static_cast<double>(rtt.size() - 1) + 0.5)]) * 1e-3;
  };
  nlohmann::json j = {{"sent", sent},
                      {"received", rtt.size()},
                      {"rate_hz", rate},
                      {"received_per_s", elapsed > 0 ? static_cast<double>(rtt.size()) / elapsed : 0.0},
                      {"rtt_p50_us", pct(0.50)},
                      {"rtt_p90_us", pct(0.90)},
                      {"rtt_p99_us", pct(0.99)},
                      {"rtt_max_us", rtt.empty() ? 0.0 : static_cast<double>(rtt.back()) * 1e-3},
                      {"loop_jitter_p99_us", ls.jitter_p99_us},
                      {"loop_overruns", ls.overruns}};
  std::printf("%s\n", j.dump().c_str());
  return rtt.size() == static_cast<std::size_t>(count) ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"demo_node: the two services of the plexus backbone demo"};
  app.set_version_flag("--version", std::string("demo_node") + " " + PLEXUS_VERSION);
  std::string role, dds = "fast", qos_file, profile = "latency", log_level = "warn";
  int domain = 40, count = 2000;
  double rate = 500, duration = 0, timeout = 15;
  app.add_option("role", role, "source or echo")->required()->check(CLI::IsMember({"source", "echo"}));
  app.add_option("--dds", dds, "DDS vendor: fast or cyclone");
  app.add_option("--domain", domain, "DDS domain id (0..232)");
  app.add_option("--qos-file", qos_file, "QoS profiles (default: deploy/qos.yaml)");
  app.add_option("--profile", profile, "QoS profile name");
  app.add_option("--rate", rate, "source: samples per second");
  app.add_option("--count", count, "source: samples to send")->check(CLI::Range(1, 10'000'000));
  app.add_option("--duration", duration, "echo: seconds to run (0: until SIGINT/SIGTERM)");
  app.add_option("--timeout", timeout, "source: seconds to wait for the echo");
  app.add_option("--log-level", log_level, "trace, debug, info, warn, error, critical or off");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return plexus::parse_error_exit(app, e, "demo_node");
  }
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  try {
    init_logging("demo_" + role, "", log_level);
    rt::ParticipantOptions po;
    po.vendor = rt::parse_vendor(dds);
    po.domain_id = domain;
    po.name = "demo_" + role;
    const auto profiles = rt::QosProfiles::load(qos_file.empty() ? rt::default_qos_file() : qos_file);
    const auto& qos = profiles.get(profile);
    auto participant = rt::Participant::create(po);
    const int rc =
        role == "echo" ? run_echo(*participant, qos, duration) : run_source(*participant, qos, rate, count, timeout);
    return exit_within(rc, kTeardownDeadlineS, "demo_node");
  } catch (const InputError& e) {
    std::fprintf(stderr, "demo_node: error: %s\n", e.what());
    return kExitBadInput;
  }
}
