// `plexus launch --monitor PORT` (docs/viewing.md): one page on http://127.0.0.1:PORT/ that
// shows the run live, fed over a WebSocket on the same port (subprotocol plexus.monitor.v1):
// a "hello" message when a page connects (the scenario, its signals and their fields), then
// a "status" message four times a second (monitor_view.hpp). The page asks for the plotted
// field with {"plot": {"signal": S, "field": F}}. The plot is drawn by dygraphs, from Debian's
// libjs-dygraphs, served beside the page. GET /status.json answers the last status.
//
// publish() may be called from any thread; it never blocks on a client: a page that does not
// keep up (over 1 MB queued) misses statuses, counted in dropped().
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "plexus/web/ws_transport.hpp"

namespace plexus::cli {

class WebMonitor {
 public:
  /// Listens on 127.0.0.1:port. `hello`: {"scenario", "mode", "signals": [{"name", "fields"}]}.
  /// InputError when the port cannot be listened on, or dygraphs is not installed.
  WebMonitor(int port, nlohmann::json hello);
  ~WebMonitor();
  WebMonitor(const WebMonitor&) = delete;
  WebMonitor& operator=(const WebMonitor&) = delete;

  /// Sends `status` to every page, and keeps it for /status.json and the next page to connect.
  void publish(const nlohmann::json& status);
  /// The field the pages asked to plot: true, with it, when it changed (or a page connected
  /// and needs the whole trace) since the last call.
  bool plot_request(std::string& signal, std::string& field, bool& reset);
  uint64_t dropped() const { return dropped_.load(); }

 private:
  void on_text(uint64_t client, const std::string& text);
  web::HttpReply on_http(const std::string& path);

  nlohmann::json hello_;
  std::string hello_text_, page_, dygraph_js_, dygraph_css_;
  std::mutex mu_;  // the four below, and ws_ while it is set
  std::string last_status_;
  std::string plot_signal_, plot_field_;
  bool plot_changed_ = false, plot_reset_ = false;
  std::set<uint64_t> clients_;  // I/O thread only
  std::atomic<uint64_t> dropped_{0};
  std::unique_ptr<web::WsTransport> ws_;  // last: its thread stops first
};

}  // namespace plexus::cli
