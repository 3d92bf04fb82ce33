// foxglove_bridge: a live view of a plexus domain in Foxglove or Lichtblick (docs/viewing.md).
//
//   foxglove_bridge --dds fast --domain 0 --port 8765
//   then open ws://127.0.0.1:8765 in Foxglove ("Foxglove WebSocket" connection).
//
// Serves the Foxglove WebSocket protocol (foxglove.websocket.v1) on 127.0.0.1 by default:
// every typed topic on the domain, with its omgidl schema and the CDR as it was on the wire
// (foxglove_server.hpp). Runs until SIGINT/SIGTERM, then prints one JSON line with its
// counters (frames sent and dropped, latency from DDS to the socket) and exits 0. Bad
// options or a port in use: one line naming the option, exit 2.
#include <CLI/CLI.hpp>

#include <csignal>
#include <cstdio>

#include "foxglove_server.hpp"
#include "plexus/base/cli_style.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/base/logging.hpp"
#include "plexus/service/dds_options.hpp"

namespace {
std::atomic<bool> g_stop{false};
void on_signal(int) { g_stop = true; }
}  // namespace

int main(int argc, char** argv) {
  using namespace plexus;
  CLI::App app{
      "foxglove_bridge: the typed topics of a DDS domain on the Foxglove WebSocket protocol (docs/viewing.md)"};
  app.set_version_flag("--version", std::string("foxglove_bridge ") + PLEXUS_VERSION);
  scenario::ServiceDdsOptions net;
  net.add_to(app);
  foxglove::BridgeOptions o;
  double max_buffer_mb = 4.0;
  std::string log_level = "warn";
  app.add_option("--address", o.address, "Address to serve on (default 127.0.0.1: this machine only)");
  app.add_option("--port", o.port, "TCP port (default 8765, Foxglove's)")->check(CLI::Range(1, 65535));
  app.add_option("--max-client-buffer", max_buffer_mb,
                 "MB a client's socket may hold unsent before its frames are dropped (default 4)")
      ->check(CLI::Range(0.01, 1024.0));
  app.add_option("--log-level", log_level, "trace, debug, info, warn, error, critical or off (default warn)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return parse_error_exit(app, e, "foxglove_bridge");
  }
  try {
    o.max_client_buffer_bytes = static_cast<std::size_t>(max_buffer_mb * 1024 * 1024);
    init_logging("foxglove_bridge", "", log_level);
    auto participant = rt::Participant::create(net.participant("foxglove_bridge", "foxglove_bridge"));
    foxglove::FoxgloveServer server(*participant, o);
    std::signal(SIGINT, on_signal);
    std::signal(SIGTERM, on_signal);
    std::fprintf(stderr, "foxglove_bridge: serving domain %d (%s) on ws://%s:%d\n", net.domain, net.dds.c_str(),
                 o.address.c_str(), o.port);
    server.run_until(g_stop);
    std::printf("%s\n", server.stats().dump().c_str());
    std::fflush(stdout);
    return 0;
  } catch (const InputError& e) {
    std::fprintf(stderr, "foxglove_bridge: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "foxglove_bridge: error: %s\n", e.what());
    return 1;
  }
}
