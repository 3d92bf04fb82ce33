#include "device_link.hpp"

#include <unistd.h>

#include "plexus/base/input_error.hpp"
#include "plexus/link/serial_port.hpp"

namespace plexus::bridge {
namespace {

class SerialLink final : public DeviceLink {
 public:
  SerialLink(std::string device, long baud) : device_(std::move(device)), baud_(baud) {}
  bool open(std::string& error) override {
    fd_ = link::open_serial(device_, baud_, error);
    return fd_ >= 0;
  }
  bool reports_loss() const override { return true; }
  std::string describe() const override { return "serial " + device_ + " at " + std::to_string(baud_) + " baud"; }

 private:
  std::string device_;
  long baud_;
};

class UdpLink final : public DeviceLink {
 public:
  UdpLink(link::UdpEndpoint local, link::UdpEndpoint peer) : local_(std::move(local)), peer_(std::move(peer)) {}
  bool open(std::string& error) override {
    fd_ = link::open_udp(local_, peer_, error);
    return fd_ >= 0;
  }
  bool reports_loss() const override { return false; }
  std::string describe() const override {
    return "udp " + local_.address + ":" + std::to_string(local_.port) + " -> " + peer_.address + ":" +
           std::to_string(peer_.port);
  }

 private:
  link::UdpEndpoint local_, peer_;
};

}  // namespace

void DeviceLink::close() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

std::unique_ptr<DeviceLink> serial_link(std::string device, long baud) {
  return std::make_unique<SerialLink>(std::move(device), baud);
}

std::unique_ptr<DeviceLink> udp_link(const std::string& bind, const std::string& peer, const std::string& where) {
  link::UdpEndpoint local, remote;
  std::string error;
  if (!link::parse_endpoint(bind, where + ".bind", local, error) ||
      !link::parse_endpoint(peer, where + ".peer", remote, error))
    throw InputError(error);
  // A port that cannot be bound (in use, or an address not of this host) is a configuration
  // error, exit 2 at start; an absent device is retried, a busy port would be forever.
  const int fd = link::open_udp(local, remote, error);
  if (fd < 0) throw InputError(where + ".bind: " + error);
  ::close(fd);
  return std::make_unique<UdpLink>(std::move(local), std::move(remote));
}

}  // namespace plexus::bridge
