// Opens a tty for the serial bridge in raw mode: frames are binary (0x00, 0x0A, 0x03, 0x11
// and 0x13 occur in them), so nothing between the wire and read() may translate, echo,
// signal or hold back a byte.
#include "plexus/link/serial_port.hpp"

#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace plexus::link {
namespace {

struct Baud {
  long rate;
  speed_t constant;
};

// The rates named by termios from 115200 up to 1000000; a device at another rate needs
// its own speed setting (BOTHER), which the bridge does not offer.
constexpr Baud kBauds[] = {{115200, B115200}, {230400, B230400}, {460800, B460800},  {500000, B500000},
                           {576000, B576000}, {921600, B921600}, {1000000, B1000000}};

std::string allowed_list() {
  std::string s;
  for (const Baud& b : kBauds) s += (s.empty() ? "" : ", ") + std::to_string(b.rate);
  return s;
}

// Sets `error` to "serial device PATH: WHAT: strerror(errno)", closes `fd` if open, and
// returns -1. errno is read first: building the message and close() may change it.
int fail(int fd, const std::string& path, const char* what, std::string& error) {
  const int err = errno;
  error = "serial device " + path + ": " + what + ": " + std::strerror(err);
  if (fd >= 0) ::close(fd);
  return -1;
}

}  // namespace

bool supported_baud(long baud) {
  for (const Baud& b : kBauds)
    if (b.rate == baud) return true;
  return false;
}

int open_serial(const std::string& path, long baud, std::string& error) {
  const Baud* rate = nullptr;
  for (const Baud& b : kBauds)
    if (b.rate == baud) rate = &b;
  if (rate == nullptr) {
    error = "serial device " + path + ": unsupported baud rate " + std::to_string(baud) +
            " (allowed: " + allowed_list() + ")";
    return -1;
  }
  // O_NOCTTY: a bridge must never acquire the device as its controlling terminal (a hang-up
  // would then signal it). O_NONBLOCK: the I/O loop polls.
  const int fd = ::open(path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return fail(-1, path, "cannot open", error);
  termios t{};
  if (::tcgetattr(fd, &t) != 0) return fail(fd, path, "not a terminal (tcgetattr)", error);
  ::cfmakeraw(&t);              // 8N1, no echo, no canonical mode, no signals, no CR/NL mapping
  t.c_cflag |= CLOCAL | CREAD;  // ignore modem lines, enable the receiver
  t.c_cflag &= ~(CRTSCTS | CSTOPB);
  t.c_cc[VMIN] = 0;  // read() returns what is there, at once
  t.c_cc[VTIME] = 0;
  if (::cfsetispeed(&t, rate->constant) != 0 || ::cfsetospeed(&t, rate->constant) != 0)
    return fail(fd, path, "cannot set the baud rate", error);
  if (::tcsetattr(fd, TCSANOW, &t) != 0) return fail(fd, path, "cannot set raw mode (tcsetattr)", error);
  // Bytes a device sent before we were listening belong to no frame we can use.
  if (::tcflush(fd, TCIOFLUSH) != 0) return fail(fd, path, "cannot flush (tcflush)", error);
  return fd;
}

}  // namespace plexus::link
