#include "plexus/web/ws_transport.hpp"

#define ASIO_STANDALONE
#include <websocketpp/config/asio_no_tls.hpp>
#include <websocketpp/server.hpp>

#include <algorithm>
#include <map>
#include <stdexcept>
#include <thread>

namespace plexus::web {

using Server = websocketpp::server<websocketpp::config::asio>;
using Hdl = websocketpp::connection_hdl;

struct WsTransport::Impl {
  Server server;
  Handlers handlers;
  std::thread io;
  std::map<uint64_t, Hdl> clients;
  std::map<Hdl, uint64_t, std::owner_less<Hdl>> ids;
  uint64_t next_id = 1;

  Server::connection_ptr con(uint64_t client) const {
    const auto it = clients.find(client);
    if (it == clients.end()) return nullptr;
    std::error_code ec;
    auto c = const_cast<Server&>(server).get_con_from_hdl(it->second, ec);
    return ec ? nullptr : c;
  }
  void forget(Hdl h) {
    const auto it = ids.find(h);
    if (it == ids.end()) return;
    const uint64_t id = it->second;
    clients.erase(id);
    ids.erase(it);
    if (handlers.on_close) handlers.on_close(id);
  }
};

WsTransport::WsTransport(const std::string& address, int port, const std::string& subprotocol, Handlers handlers)
    : impl_(std::make_unique<Impl>()) {
  Impl& d = *impl_;
  d.handlers = std::move(handlers);
  d.server.clear_access_channels(websocketpp::log::alevel::all);
  d.server.clear_error_channels(websocketpp::log::elevel::all);
  d.server.init_asio();
  d.server.set_reuse_addr(true);
  d.server.set_validate_handler([&d, subprotocol](Hdl h) {
    const auto c = d.server.get_con_from_hdl(h);
    const auto& asked = c->get_requested_subprotocols();
    if (std::find(asked.begin(), asked.end(), subprotocol) == asked.end()) return false;
    c->select_subprotocol(subprotocol);
    return true;
  });
  d.server.set_open_handler([&d](Hdl h) {
    const uint64_t id = d.next_id++;
    d.clients[id] = h;
    d.ids[h] = id;
    if (d.handlers.on_open) d.handlers.on_open(id);
  });
  d.server.set_http_handler([&d](Hdl h) {
    const auto c = d.server.get_con_from_hdl(h);
    HttpReply reply;
    if (c->get_request().get_method() != "GET")
      reply = {405, "text/plain; charset=utf-8", "only GET\n"};
    else if (d.handlers.on_http)
      reply = d.handlers.on_http(c->get_resource());
    c->set_status(static_cast<websocketpp::http::status_code::value>(reply.status));
    c->append_header("Content-Type", reply.content_type);
    c->append_header("Cache-Control", "no-store");
    c->set_body(reply.body);
  });
  d.server.set_close_handler([&d](Hdl h) { d.forget(h); });
  d.server.set_fail_handler([&d](Hdl h) { d.forget(h); });
  d.server.set_message_handler([&d](Hdl h, Server::message_ptr m) {
    if (m->get_opcode() != websocketpp::frame::opcode::text || !d.handlers.on_text) return;
    const auto it = d.ids.find(h);
    if (it != d.ids.end()) d.handlers.on_text(it->second, m->get_payload());
  });
  const std::string where = address + ":" + std::to_string(port);
  std::error_code ec;
  const auto ip = asio::ip::make_address(address, ec);
  if (ec) throw std::runtime_error("'" + address + "' is not an IP address");
  d.server.listen(asio::ip::tcp::endpoint(ip, static_cast<unsigned short>(port)), ec);
  if (ec) throw std::runtime_error("cannot listen on " + where + ": " + ec.message());
  d.server.start_accept(ec);
  if (ec) throw std::runtime_error("cannot accept on " + where + ": " + ec.message());
  d.server.start_perpetual();  // runs until stop(), with or without connections
  d.io = std::thread([&d] { d.server.run(); });
}

WsTransport::~WsTransport() {
  impl_->server.stop();
  if (impl_->io.joinable()) impl_->io.join();
}

void WsTransport::post(std::function<void()> fn) { asio::post(impl_->server.get_io_service(), std::move(fn)); }

bool WsTransport::send_text(uint64_t client, const std::string& text) {
  const auto c = impl_->con(client);
  return c && !c->send(text, websocketpp::frame::opcode::text);
}

bool WsTransport::send_binary(uint64_t client, const unsigned char* data, std::size_t size) {
  const auto c = impl_->con(client);
  return c && !c->send(data, size, websocketpp::frame::opcode::binary);
}

std::size_t WsTransport::buffered(uint64_t client) const {
  const auto c = impl_->con(client);
  return c ? c->get_buffered_amount() : 0;
}

void WsTransport::close_all(const std::string& reason) {
  std::error_code ec;
  impl_->server.stop_listening(ec);
  for (const auto& [id, h] : impl_->clients) impl_->server.close(h, websocketpp::close::status::going_away, reason, ec);
}

}  // namespace plexus::web
