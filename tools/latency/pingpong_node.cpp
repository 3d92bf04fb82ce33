// pingpong_node: plexus's side of `plexus latency pingpong`. LatencyProbe samples on
// latency/ping and latency/pong through the plexus runtime (either vendor, a QoS profile).
//
//   pingpong_node pong --dds cyclone --domain 180
//   pingpong_node ping --dds fast --domain 180 --size 4096 --rate 1000 --count 5000
//
// ping publishes at --rate on an absolute-deadline schedule (or back to back with --rate 0),
// waits for each pong and records the round trip (monotonic clock, taken in ping) into a
// buffer allocated before the loop. Prints one JSON line (pingpong_common.hpp).
#include <atomic>
#include <csignal>
#include <thread>

#include "pingpong_common.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/base/logging.hpp"
#include "plexus/runtime/participant.hpp"

namespace {

std::atomic<bool> g_stop{false};
void on_signal(int) { g_stop = true; }

using namespace plexus;
using latency::mono_ns;

int run_pong(rt::Participant& p, const rt::QosProfile& qos, const latency::PingPongOptions& o) {
  auto sub = p.subscriber<msg::LatencyProbe>("latency/ping", qos);
  auto pub = p.publisher<msg::LatencyProbe>("latency/pong", qos);
  msg::LatencyProbe m;
  m.payload().reserve(65536);
  const int64_t end = o.duration > 0 ? mono_ns() + static_cast<int64_t>(o.duration * 1e9) : INT64_MAX;
  while (!g_stop && mono_ns() < end) {
    if (!sub.wait(50'000'000)) continue;
    while (sub.take(m)) pub.publish(m);  // data_time (the ping index) and origin time travel back
  }
  return 0;
}

int run_ping(rt::Participant& p, const rt::QosProfile& qos, const latency::PingPongOptions& o) {
  auto pub = p.publisher<msg::LatencyProbe>("latency/ping", qos);
  auto sub = p.subscriber<msg::LatencyProbe>("latency/pong", qos);
  const int64_t match_end = mono_ns() + static_cast<int64_t>(o.timeout * 1e9);
  while ((pub.matched_count() == 0 || sub.matched_count() == 0) && !g_stop) {
    if (mono_ns() > match_end) {
      std::fprintf(stderr, "pingpong_node ping: no pong matched within %.0f s\n", o.timeout);
      return 1;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // both directions matched
  msg::LatencyProbe out, in;
  out.payload().assign(static_cast<std::size_t>(o.size), 0x5a);
  in.payload().reserve(65536);
  std::vector<int64_t> rtt;
  rtt.reserve(static_cast<std::size_t>(o.count));
  const int total = o.warmup + o.count;
  const int64_t period = o.rate > 0 ? static_cast<int64_t>(1e9 / o.rate) : 0;
  int sent = 0;
  int64_t next = mono_ns(), t_start = 0;
  for (int k = 0; k < total && !g_stop; ++k) {
    if (period > 0) {
      latency::sleep_until_ns(next);
      next += period;
      const int64_t now = mono_ns();
      while (next < now) next += period;  // overrun: skip periods, keep the phase
    }
    if (k == o.warmup) t_start = mono_ns();
    out.header().origin_time_ns(0);
    out.header().data_time_ns(k);
    const int64_t t0 = mono_ns();
    pub.publish(out);
    if (k >= o.warmup) ++sent;
    // Wait for this pong (older ones from timed-out pings are dropped).
    const int64_t give_up = t0 + 1'000'000'000;
    bool got = false;
    while (!got && !g_stop) {
      const int64_t now = mono_ns();
      if (now >= give_up) break;
      if (!sub.wait(give_up - now)) continue;
      while (sub.take(in)) {
        if (in.header().data_time_ns() == k) {
          got = true;
          if (k >= o.warmup) rtt.push_back(mono_ns() - t0);
        }
      }
    }
  }
  const double elapsed = static_cast<double>(mono_ns() - t_start) * 1e-9;
  latency::print_result("plexus", o, rtt, sent, elapsed);
  return static_cast<int>(rtt.size()) == o.count ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"pingpong_node: plexus side of plexus latency pingpong"};
  latency::PingPongOptions o;
  std::string dds = "fast", qos_file, profile = "latency", log_level = "error";
  latency::add_pingpong_options(app, o);
  app.add_option("--dds", dds, "DDS vendor: fast or cyclone");
  app.add_option("--qos-file", qos_file, "QoS profiles (default: deploy/qos.yaml)");
  app.add_option("--profile", profile, "QoS profile name");
  app.add_option("--log-level", log_level, "trace, debug, info, warn, error");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : kExitBadInput;
  }
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  try {
    init_logging("pingpong_" + o.role, "", log_level);
    rt::ParticipantOptions po;
    po.vendor = rt::parse_vendor(dds);
    po.domain_id = o.domain;
    po.name = "pingpong_" + o.role;
    const auto profiles = rt::QosProfiles::load(qos_file.empty() ? rt::default_qos_file() : qos_file);
    const auto& qos = profiles.get(profile);
    auto participant = rt::Participant::create(po);
    return o.role == "pong" ? run_pong(*participant, qos, o) : run_ping(*participant, qos, o);
  } catch (const InputError& e) {
    std::fprintf(stderr, "pingpong_node: error: %s\n", e.what());
    return kExitBadInput;
  }
}
