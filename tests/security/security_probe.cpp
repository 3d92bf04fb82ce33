// security_probe: a publisher or subscriber of one topic, with or without DDS Security, for
// the tests of tests/security/ (who can talk to whom, what is on the wire).
//
//   security_probe pub --dds fast --domain 100 --security PKI --identity a --label MARKER --duration 5
//   security_probe sub --dds cyclone --domain 100 --security PKI --identity b --label MARKER --expect 5 --duration 20
//
// pub publishes a TerrainClass sample whose `label` is MARKER (and confidence 0.7071067811865476) every
// 50 ms for --duration seconds, whether or not a reader matched (an intruder publishes
// blindly), and prints how many it published and the readers it matched.
// sub reads for up to --duration seconds and prints `received N, with label M, matched W`.
// It exits 0 when at least --expect samples carried the label and no sample carried another
// (an intruder's), 1 otherwise; it stops once --expect are in and --min-duration has passed.
// With --expect 0 it reads for the whole --duration and passes only if nothing arrived.
// Bad arguments or security files: one line, exit 2.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <cstring>
#include <string>
#include <thread>

#include "plexus/base/clock.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/base/logging.hpp"
#include "plexus/runtime/participant.hpp"

int main(int argc, char** argv) {
  using namespace plexus;
  CLI::App app{"security_probe: one topic, with or without DDS Security"};
  app.require_subcommand(1);
  std::string dds = "fast", topic = "secure/probe", label = "plexus-probe", pki, identity, governance,
              transport = "auto";
  int domain = 100, expect = 1;
  double duration = 10, min_duration = 0;
  for (auto* sub : {app.add_subcommand("pub", "publish"), app.add_subcommand("sub", "subscribe")}) {
    sub->add_option("--dds", dds);
    sub->add_option("--domain", domain);
    sub->add_option("--topic", topic);
    sub->add_option("--label", label, "the sample's label (at most 31 characters)");
    sub->add_option("--duration", duration, "seconds");
    sub->add_option("--security", pki, "PKI folder: DDS Security on");
    sub->add_option("--identity", identity, "identity in the PKI folder");
    sub->add_option("--governance", governance, "governance document (default PKI/governance.p7s)");
    sub->add_option("--transport", transport, "auto, udp or shm (a capture sees only udp)");
  }
  app.get_subcommand("sub")->add_option("--expect", expect, "samples with the label to wait for (0: none may arrive)");
  app.get_subcommand("sub")->add_option("--min-duration", min_duration,
                                        "seconds to read at least (intruders publish too)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    std::fprintf(stderr, "security_probe: %s\n", e.what());
    return 2;
  }
  const bool publishing = app.got_subcommand("pub");
  try {
    init_logging("security_probe", "", "warn");
    if (label.size() > 31) throw InputError("--label: at most 31 characters");
    rt::ParticipantOptions po;
    po.vendor = rt::parse_vendor(dds);
    po.domain_id = domain;
    po.name = std::string("security_probe ") + (publishing ? "pub" : "sub");
    po.network.transport = rt::parse_transport(transport);
    if (!pki.empty()) {
      if (identity.empty()) throw InputError("--security needs --identity");
      po.security = rt::security_from_pki(pki, identity, governance);
    }
    auto p = rt::Participant::create(po);
    const auto profiles = rt::QosProfiles::load(rt::default_qos_file());
    const auto& qos = profiles.get("state");
    const int64_t end = monotonic_ns() + static_cast<int64_t>(duration * 1e9);
    if (publishing) {
      auto pub = p->publisher<msg::TerrainClass>(topic, qos);
      msg::TerrainClass m;
      std::memset(m.label().data(), 0, m.label().size());
      std::memcpy(m.label().data(), label.data(), label.size());
      m.confidence(0.7071067811865476);  // bytes cd 3b 7f 66 9e a0 e6 3f: found in a capture if sent in the clear
      int n = 0, matched = 0;
      while (monotonic_ns() < end) {
        m.windows(static_cast<uint32_t>(++n));
        m.header().origin_time_ns(0);
        pub.publish(m);
        matched = std::max(matched, pub.matched_count());
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
      }
      std::printf("published %d, matched %d\n", n, matched);
      return 0;
    }
    auto sub = p->subscriber<msg::TerrainClass>(topic, qos);
    int received = 0, with_label = 0, matched = 0;
    msg::TerrainClass m;
    const int64_t min_end = monotonic_ns() + static_cast<int64_t>(min_duration * 1e9);
    while (monotonic_ns() < end && !(expect > 0 && with_label >= expect && monotonic_ns() >= min_end)) {
      matched = std::max(matched, sub.matched_count());
      if (!sub.wait(50'000'000)) continue;
      while (sub.take(m)) {
        ++received;
        if (std::strncmp(m.label().data(), label.c_str(), m.label().size()) == 0) ++with_label;
      }
    }
    std::printf("received %d, with label %d, matched %d\n", received, with_label, matched);
    return with_label >= expect && received == with_label ? 0 : 1;
  } catch (const InputError& e) {
    std::fprintf(stderr, "security_probe: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "security_probe: failed: %s\n", e.what());
    return 1;
  }
}
