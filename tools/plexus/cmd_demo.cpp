// plexus demo: two services exchanging samples over Fast DDS, over Cyclone DDS and across
// the two; prints rates and round-trip latency percentiles for each vendor pair.
#include <nlohmann/json.hpp>

#include <cstdio>
#include <thread>

#include "child_process.hpp"
#include "command.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/runtime/qos.hpp"

namespace plexus::cli {

Command add_demo_command(CLI::App& root) {
  struct Opts {
    double rate = 500;
    int count = 2000;
    int domain = 40;
    std::string qos_file, profile = "latency";
    bool json = false;
  };
  auto o = std::make_shared<Opts>();
  Command c;
  c.app = root.add_subcommand("demo", "Run the backbone demo: ping-pong between two services on every vendor pair");
  c.app->add_option("--rate", o->rate, "samples per second")->check(CLI::Range(1.0, 20000.0));
  c.app->add_option("--count", o->count, "samples per vendor pair")->check(CLI::Range(10, 1'000'000));
  c.app->add_option("--domain", o->domain, "first DDS domain id (one per pair)")->check(CLI::Range(0, 229));
  c.app->add_option("--qos-file", o->qos_file, "QoS profiles file (default: deploy/qos.yaml)");
  c.app->add_option("--profile", o->profile, "QoS profile name");
  c.app->add_flag("--json", o->json, "print one JSON object instead of a table");
  c.run = [o] {
    const std::string qos_file = o->qos_file.empty() ? rt::default_qos_file() : o->qos_file;
    rt::QosProfiles::load(qos_file).get(o->profile);  // bad file or profile: exit 2 before starting anything
    const std::pair<const char*, const char*> pairs[] = {
        {"fast", "fast"}, {"cyclone", "cyclone"}, {"fast", "cyclone"}, {"cyclone", "fast"}};
    nlohmann::json all = nlohmann::json::object();
    if (!o->json)
      std::printf(
          "plexus demo: %d samples at %.0f Hz per pair, QoS profile '%s', loopback only\n\n"
          "%-18s %10s %10s %10s %10s %10s %10s\n",
          o->count, o->rate, o->profile.c_str(), "source -> echo", "recv/s", "rtt p50", "rtt p90", "rtt p99", "rtt max",
          "lost");
    int failures = 0;
    int domain = o->domain;
    for (const auto& [src, echo] : pairs) {
      const std::string d = std::to_string(domain++);
      const pid_t echo_pid = spawn("demo_node", {"echo", "--dds", echo, "--domain", d, "--qos-file", qos_file,
                                                 "--profile", o->profile, "--log-level", "error"});
      std::string out;
      const int rc =
          run_capture("demo_node",
                      {"source", "--dds", src, "--domain", d, "--qos-file", qos_file, "--profile", o->profile, "--rate",
                       std::to_string(o->rate), "--count", std::to_string(o->count), "--log-level", "error"},
                      out);
      stop(echo_pid);
      const std::string name = std::string(src) + "->" + echo;
      nlohmann::json r;
      try {
        r = nlohmann::json::parse(out);
      } catch (const nlohmann::json::exception&) {
        r = {{"error", "source produced no result (exit " + std::to_string(rc) + ")"}};
      }
      if (rc != 0) ++failures;
      all[name] = r;
      if (!o->json) {
        if (r.contains("error")) {
          std::printf("%-18s %s\n", name.c_str(), r["error"].get<std::string>().c_str());
        } else {
          std::printf("%-18s %10.1f %8.0fus %8.0fus %8.0fus %8.0fus %10d\n", name.c_str(),
                      r["received_per_s"].get<double>(), r["rtt_p50_us"].get<double>(), r["rtt_p90_us"].get<double>(),
                      r["rtt_p99_us"].get<double>(), r["rtt_max_us"].get<double>(),
                      r["sent"].get<int>() - r["received"].get<int>());
        }
      }
    }
    if (o->json)
      std::printf("%s\n", all.dump().c_str());
    else
      std::printf(
          "\nround trip = source publish -> echo take + publish -> source take, header origin time to receipt.\n");
    return failures == 0 ? 0 : 1;
  };
  return c;
}

}  // namespace plexus::cli
