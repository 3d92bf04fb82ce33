// The bridge's end of the link to its device: a tty in raw mode or a connected UDP socket.
// Both are read and written through one file descriptor (a read on the UDP socket returns
// one datagram, a write sends one), so the bridge's I/O loop treats them alike; what
// differs is opening, and how a lost device shows (a tty reports it, UDP only falls silent).
#pragma once

#include <memory>
#include <string>

#include "plexus/link/udp_socket.hpp"

namespace plexus::bridge {

class DeviceLink {
 public:
  virtual ~DeviceLink() = default;
  /// Opens the device; false with `error` set (one line) if it is absent or refuses.
  virtual bool open(std::string& error) = 0;
  void close();
  int fd() const { return fd_; }
  bool is_open() const { return fd_ >= 0; }
  /// True if the device reports its loss (a tty: hang-up, EIO); false if only silence shows it.
  virtual bool reports_loss() const = 0;
  /// "serial /dev/ttyUSB0 at 1000000 baud", "udp 127.0.0.1:47001 -> 127.0.0.1:47002".
  virtual std::string describe() const = 0;

 protected:
  int fd_ = -1;
};

std::unique_ptr<DeviceLink> serial_link(std::string device, long baud);
/// Throws InputError naming `where` for an endpoint that does not parse.
std::unique_ptr<DeviceLink> udp_link(const std::string& bind, const std::string& peer, const std::string& where);

}  // namespace plexus::bridge
