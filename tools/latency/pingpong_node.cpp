// pingpong_node: plexus's side of `plexus latency pingpong`. LatencyProbe samples on
// latency/ping and latency/pong through the plexus runtime (either vendor, a QoS profile).
//
//   pingpong_node pong --dds cyclone --domain 180
//   pingpong_node ping --dds fast --domain 180 --size 4096 --rate 1000 --count 5000
//
// ping publishes at --rate on an absolute-deadline schedule (or back to back with --rate 0);
// each pong is stamped on arrival by the receive thread's data callback (as ddsperf's ping
// does), and the round trip (monotonic clock, taken in ping) goes into a buffer allocated
// before the loop. Prints one JSON line (pingpong_common.hpp).
#include <atomic>
#include <csignal>
#include <thread>

#include "pingpong_common.hpp"
#include "plexus/base/cli_style.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/base/logging.hpp"
#include "plexus/base/teardown_deadline.hpp"
#include "plexus/runtime/participant.hpp"

namespace {

std::atomic<bool> g_stop{false};
void on_signal(int) { g_stop = true; }

using namespace plexus;
using latency::mono_ns;

// pong answers on the DDS receive thread (Subscriber::on_sample), as ddsperf's pong does from
// its listener: no second thread is woken per ping. The main thread only waits for the end.
int run_pong(rt::Participant& p, const rt::QosProfile& qos, const latency::PingPongOptions& o) {
  auto pub = p.publisher<msg::LatencyProbe>("latency/pong", qos);
  auto sub = p.subscriber<msg::LatencyProbe>("latency/ping", qos);
  msg::LatencyProbe buffer;
  buffer.payload().reserve(latency::kMaxPayload);
  // data_time (the ping index) and origin time travel back. Only this callback touches pub.
  sub.on_sample([&pub](msg::LatencyProbe& m, const rt::SampleMeta&) { pub.publish(m); }, std::move(buffer));
  const int64_t end = o.duration > 0 ? mono_ns() + static_cast<int64_t>(o.duration * 1e9) : INT64_MAX;
  while (!g_stop && mono_ns() < end) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  return 0;
}

int run_ping(rt::Participant& p, const rt::QosProfile& qos, const latency::PingPongOptions& o) {
  latency::PongArrivals pongs;  // before sub: its callback writes here until sub goes
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
  in.payload().reserve(latency::kMaxPayload);
  // Each pong is stamped on the receive thread (Subscriber::on_sample), as ddsperf's ping does.
  sub.on_sample([&pongs](msg::LatencyProbe& m, const rt::SampleMeta&) { pongs.arrived(m.header().data_time_ns()); },
                std::move(in));
  return latency::run_ping(
      "plexus", o,
      [&](int k) {
        if (g_stop) return false;
        out.header().origin_time_ns(0);
        out.header().data_time_ns(k);
        pub.publish(out);
        return true;
      },
      pongs);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"pingpong_node: plexus side of plexus latency pingpong"};
  app.set_version_flag("--version", std::string("pingpong_node") + " " + PLEXUS_VERSION);
  latency::PingPongOptions o;
  std::string dds = "fast", qos_file, profile = "latency", log_level = "error", transport = "auto";
  latency::add_pingpong_options(app, o);
  app.add_option("--dds", dds, "DDS vendor: fast or cyclone");
  app.add_option("--qos-file", qos_file, "QoS profiles (default: deploy/qos.yaml)");
  app.add_option("--profile", profile, "QoS profile name");
  app.add_option("--log-level", log_level, "trace, debug, info, warn, error, critical or off");
  app.add_option("--transport", transport, "auto, udp or shm (docs/runtime.md, Transports)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return plexus::parse_error_exit(app, e, "pingpong_node");
  }
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  try {
    init_logging("pingpong_" + o.role, "", log_level);
    rt::ParticipantOptions po;
    po.vendor = rt::parse_vendor(dds);
    po.domain_id = o.domain;
    po.name = "pingpong_" + o.role;
    po.network.transport = rt::parse_transport(transport);
    const auto profiles = rt::QosProfiles::load(qos_file.empty() ? rt::default_qos_file() : qos_file);
    const auto& qos = profiles.get(profile);
    auto participant = rt::Participant::create(po);
    const int rc = o.role == "pong" ? run_pong(*participant, qos, o) : run_ping(*participant, qos, o);
    return exit_within(rc, kTeardownDeadlineS, "pingpong_node");
  } catch (const InputError& e) {
    std::fprintf(stderr, "pingpong_node: error: %s\n", e.what());
    return kExitBadInput;
  }
}
