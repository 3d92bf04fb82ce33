#include "web_monitor.hpp"

#include <fstream>
#include <sstream>
#include <utility>

#include "plexus/base/input_error.hpp"

namespace plexus::cli {

extern const char kMonitorPage[];  // monitor_page.html, compiled in (CMakeLists.txt)

namespace {

constexpr const char* kSubprotocol = "plexus.monitor.v1";
constexpr std::size_t kMaxQueuedBytes = 1 << 20;  // a page further behind misses statuses

std::string read_asset(const std::string& name) {
  const std::string path = std::string(PLEXUS_DYGRAPHS_DIR) + "/" + name;
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError("--monitor: " + path + " is missing: the page plots with dygraphs, Debian's libjs-dygraphs " +
                     "(tools/setup/install_deps.sh installs it)");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

WebMonitor::WebMonitor(int port, nlohmann::json hello)
    : hello_(std::move(hello)),
      page_(kMonitorPage),
      dygraph_js_(read_asset("dygraph.min.js")),
      dygraph_css_(read_asset("dygraph.min.css")) {
  hello_["type"] = "hello";
  hello_text_ = hello_.dump();
  web::WsTransport::Handlers h;
  h.on_open = [this](uint64_t client) {
    std::lock_guard lock(mu_);  // also until ws_ is set, for a page that connects at once
    clients_.insert(client);
    ws_->send_text(client, hello_text_);
    if (!last_status_.empty()) ws_->send_text(client, last_status_);
    plot_reset_ = true;  // the new page needs the whole trace
  };
  h.on_close = [this](uint64_t client) { clients_.erase(client); };
  h.on_text = [this](uint64_t client, const std::string& text) { on_text(client, text); };
  h.on_http = [this](const std::string& path) { return on_http(path); };
  try {
    std::lock_guard lock(mu_);
    ws_ = std::make_unique<web::WsTransport>("127.0.0.1", port, kSubprotocol, std::move(h));
  } catch (const std::exception& e) {
    throw InputError("--monitor " + std::to_string(port) + ": " + e.what());
  }
}

WebMonitor::~WebMonitor() {
  if (!ws_) return;
  ws_->post([this] { ws_->close_all("plexus launch ended"); });
  ws_.reset();
}

void WebMonitor::publish(const nlohmann::json& status) {
  std::string text = status.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  {
    std::lock_guard lock(mu_);
    last_status_ = text;
  }
  ws_->post([this, text = std::move(text)] {
    for (const uint64_t c : clients_) {
      if (ws_->buffered(c) > kMaxQueuedBytes) {
        ++dropped_;
        continue;
      }
      ws_->send_text(c, text);
    }
  });
}

bool WebMonitor::plot_request(std::string& signal, std::string& field, bool& reset) {
  std::lock_guard lock(mu_);
  if (!plot_changed_ && !plot_reset_) return false;
  signal = plot_signal_;
  field = plot_field_;
  reset = plot_reset_;
  plot_changed_ = plot_reset_ = false;
  return true;
}

// {"plot": {"signal": S, "field": F}}: S and F as the hello message lists them. Anything else
// is answered with an error message (the page shows it) and changes nothing.
void WebMonitor::on_text(uint64_t client, const std::string& text) {
  const auto msg = nlohmann::json::parse(text, nullptr, false);
  std::string error;
  if (msg.is_discarded() || !msg.is_object() || !msg.contains("plot") || !msg["plot"].is_object() ||
      !msg["plot"].value("signal", nlohmann::json()).is_string() ||
      !msg["plot"].value("field", nlohmann::json()).is_string()) {
    error = "expected {\"plot\": {\"signal\": S, \"field\": F}}";
  } else {
    const std::string signal = msg["plot"]["signal"], field = msg["plot"]["field"];
    bool known = false;
    for (const auto& s : hello_["signals"])
      if (s["name"] == signal)
        for (const auto& f : s["fields"]) known = known || f == field;
    if (!known) {
      error = "no field '" + field + "' in signal '" + signal + "'";
    } else {
      std::lock_guard lock(mu_);
      plot_signal_ = signal;
      plot_field_ = field;
      plot_changed_ = true;
    }
  }
  if (!error.empty()) ws_->send_text(client, nlohmann::json{{"type", "error"}, {"error", error}}.dump());
}

web::HttpReply WebMonitor::on_http(const std::string& path) {
  const std::string p = path.substr(0, path.find('?'));
  if (p == "/" || p == "/index.html") return {200, "text/html; charset=utf-8", page_};
  if (p == "/dygraph.min.js") return {200, "text/javascript; charset=utf-8", dygraph_js_};
  if (p == "/dygraph.min.css") return {200, "text/css; charset=utf-8", dygraph_css_};
  if (p == "/status.json") {
    std::lock_guard lock(mu_);
    return {last_status_.empty() ? 503 : 200, "application/json", last_status_.empty() ? "{}\n" : last_status_};
  }
  return {};
}

}  // namespace plexus::cli
