// A WebSocket server that also answers plain HTTP GETs: websocketpp on standalone asio, one
// I/O thread. Used by foxglove_bridge (the Foxglove protocol) and by `plexus launch --monitor`
// (its page and the page's status feed). Kept to this interface (standard types only)
// because Debian's websocketpp 0.8 does not compile as C++20: ws_transport.cpp alone is built
// as C++17 (CMakeLists.txt).
//
// Clients are numbered; every callback runs on the I/O thread, and so must every call but
// post() (which queues a function to run there) and the constructor and destructor.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

namespace plexus::web {

/// The answer to an HTTP GET that is not a WebSocket upgrade.
struct HttpReply {
  int status = 404;
  std::string content_type = "text/plain; charset=utf-8";
  std::string body = "not found\n";
};

class WsTransport {
 public:
  struct Handlers {
    std::function<void(uint64_t client)> on_open;
    std::function<void(uint64_t client)> on_close;
    std::function<void(uint64_t client, const std::string& text)> on_text;
    /// A GET of `path` (the request's resource, query included); unset: 404 for every path.
    std::function<HttpReply(const std::string& path)> on_http;
  };
  /// Listens on address:port with `subprotocol` (a client that does not offer it is refused)
  /// and starts the I/O thread. std::runtime_error("cannot listen on A:P: why") on failure.
  WsTransport(const std::string& address, int port, const std::string& subprotocol, Handlers handlers);
  ~WsTransport();  // stops the I/O thread
  WsTransport(const WsTransport&) = delete;
  WsTransport& operator=(const WsTransport&) = delete;

  void post(std::function<void()> fn);
  bool send_text(uint64_t client, const std::string& text);
  bool send_binary(uint64_t client, const unsigned char* data, std::size_t size);
  /// Bytes queued on the client's socket, not yet sent.
  std::size_t buffered(uint64_t client) const;
  /// Stops accepting and closes every connection ("going away").
  void close_all(const std::string& reason);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace plexus::web
