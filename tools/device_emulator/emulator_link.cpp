#include "emulator_link.hpp"

#include <fcntl.h>
#include <pty.h>
#include <sys/stat.h>
#include <sys/uio.h>
#include <termios.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "plexus/base/clock.hpp"

namespace plexus::emulator {
namespace {

bool set_flags(int fd) {
  const int fl = ::fcntl(fd, F_GETFL);
  return fl >= 0 && ::fcntl(fd, F_SETFL, fl | O_NONBLOCK) == 0 && ::fcntl(fd, F_SETFD, FD_CLOEXEC) == 0;
}

std::string endpoint_text(const link::UdpEndpoint& e) { return e.address + ":" + std::to_string(e.port); }

}  // namespace

EmulatorLink::EmulatorLink(LinkOptions options)
    : opt_(std::move(options)), ring_(opt_.ring_bytes), chunks_(kMaxChunks) {
  byte_ns_ = opt_.baud > 0 ? 10.0e9 / static_cast<double>(opt_.baud) : 0.0;
  if (opt_.kind == LinkOptions::Kind::pty) tmp_link_ = opt_.pty_path + ".tmp" + std::to_string(::getpid());
}

EmulatorLink::~EmulatorLink() { close(); }

bool EmulatorLink::open(std::string& error) {
  const bool ok = opt_.kind == LinkOptions::Kind::pty ? open_pty(error) : open_udp(error);
  if (ok) line_free_ns_ = static_cast<double>(monotonic_ns());
  return ok;
}

bool EmulatorLink::open_pty(std::string& error) {
  const std::string& path = opt_.pty_path;
  struct stat st {};
  if (::lstat(path.c_str(), &st) == 0 && !S_ISLNK(st.st_mode)) {
    error = "--pty " + path + ": exists and is not a symlink (refusing to replace it)";
    return false;
  }
  int master = -1, slave = -1;
  if (::openpty(&master, &slave, nullptr, nullptr, nullptr) != 0) {
    error = "--pty " + path + ": openpty: " + std::strerror(errno);
    return false;
  }
  auto fail = [&](const char* what) {
    error = "--pty " + path + ": " + what + ": " + std::strerror(errno);
    ::close(master);
    ::close(slave);
    return false;
  };
  // Raw mode on the slave: no echo, no line editing, no CR/NL mapping, so every byte the
  // master writes reaches the bridge unchanged, and every byte the bridge writes reaches us.
  termios t{};
  if (::tcgetattr(slave, &t) != 0) return fail("tcgetattr");
  ::cfmakeraw(&t);
  t.c_cflag |= CLOCAL | CREAD;
  if (::tcsetattr(slave, TCSANOW, &t) != 0) return fail("tcsetattr");
  if (!set_flags(master) || !set_flags(slave)) return fail("fcntl");
  if (::ttyname_r(slave, slave_name_, sizeof slave_name_) != 0) return fail("ttyname");
  // Atomically: a bridge retrying the path sees the old link or the new one, never none.
  ::unlink(tmp_link_.c_str());
  if (::symlink(slave_name_, tmp_link_.c_str()) != 0) return fail("cannot create the symlink");
  if (::rename(tmp_link_.c_str(), path.c_str()) != 0) {
    const int err = errno;
    ::unlink(tmp_link_.c_str());
    errno = err;
    return fail("cannot create the symlink");
  }
  fd_ = master;
  slave_fd_ = slave;
  return true;
}

bool EmulatorLink::open_udp(std::string& error) {
  std::string e;
  const int fd = link::open_udp(opt_.bind, opt_.peer, e);
  if (fd < 0) {
    error = "--udp-bind " + endpoint_text(opt_.bind) + " --udp-peer " + endpoint_text(opt_.peer) + ": " + e;
    return false;
  }
  fd_ = fd;
  return true;
}

void EmulatorLink::close() {
  drop_all_queued();
  need_delimiter_ = false;
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  if (slave_fd_ >= 0) {
    ::close(slave_fd_);
    slave_fd_ = -1;
    // Like a USB adapter's device node, the path goes away while the device is unplugged
    // (only if it is still ours: another emulator may have taken the path over).
    char target[sizeof slave_name_] = {};
    const ssize_t n = ::readlink(opt_.pty_path.c_str(), target, sizeof target - 1);
    if (n > 0 && std::strcmp(target, slave_name_) == 0) ::unlink(opt_.pty_path.c_str());
  }
}

bool EmulatorLink::reopen() {
  if (is_open()) return true;
  std::string error;
  if (open(error)) {
    ++c_.reopens;
    return true;
  }
  ++c_.link_errors;
  uint64_t held = 0;
  if (log_limit_.allow(monotonic_ns(), held))
    spdlog::warn("reopen failed: {} ({} more since the last line)", error, held);
  return false;
}

std::string EmulatorLink::describe() const {
  if (opt_.kind == LinkOptions::Kind::pty) return "pty " + opt_.pty_path + " -> " + slave_name_;
  return "udp " + endpoint_text(opt_.bind) + " -> " + endpoint_text(opt_.peer);
}

void EmulatorLink::count_error(const char* what, int err) {
  ++c_.link_errors;
  uint64_t held = 0;
  if (log_limit_.allow(monotonic_ns(), held))
    spdlog::warn("link {} error: {} ({} more since the last line; all counted in link_errors)", what,
                 std::strerror(err), held);
}

std::size_t EmulatorLink::read_some() {
  if (fd_ < 0) return 0;
  for (;;) {
    const ssize_t n = ::read(fd_, rx_, sizeof rx_);
    if (n > 0) {
      c_.bytes_received += static_cast<uint64_t>(n);
      return static_cast<std::size_t>(n);
    }
    if (n < 0 && errno == EINTR) continue;
    if (n == 0 || errno == EAGAIN || errno == EWOULDBLOCK) return 0;
    // A pty master reads EIO while no slave is open; we hold one, but a hang-up is not an
    // error for the device either way: nothing to read.
    if (opt_.kind == LinkOptions::Kind::pty && errno == EIO) return 0;
    count_error("read", errno);  // UDP: ECONNREFUSED (the peer's port is closed), for one
    return 0;
  }
}

bool EmulatorLink::room_for(std::size_t n) const {
  return chunk_count_ < chunks_.size() && n <= ring_.size() - ring_used_;
}

bool EmulatorLink::queue(const uint8_t* data, std::size_t n, bool is_frame) {
  if (n == 0) return true;
  if (!room_for(n)) {
    if (is_frame)
      ++c_.frames_dropped_tx;
    else
      c_.bytes_dropped_tx += n;
    return false;
  }
  const std::size_t tail = (ring_head_ + ring_used_) % ring_.size();
  const std::size_t first = std::min(n, ring_.size() - tail);
  std::memcpy(ring_.data() + tail, data, first);
  if (first < n) std::memcpy(ring_.data(), data + first, n - first);
  ring_used_ += n;
  Chunk& c = chunks_[(chunk_head_ + chunk_count_) % chunks_.size()];
  c = Chunk{static_cast<uint32_t>(n), 0, is_frame};
  ++chunk_count_;
  return true;
}

void EmulatorLink::pop_head(bool written) {
  const Chunk& c = chunks_[chunk_head_];
  if (c.frame) {
    if (written)
      ++c_.frames_sent;
    else
      ++c_.write_drops;
  }
  ring_head_ = (ring_head_ + c.len) % ring_.size();
  ring_used_ -= c.len;
  chunk_head_ = (chunk_head_ + 1) % chunks_.size();
  --chunk_count_;
}

void EmulatorLink::drop_all_queued() {
  ring_head_ = ring_used_ = 0;
  chunk_head_ = chunk_count_ = 0;
}

long EmulatorLink::write_head(std::size_t off, std::size_t n) {
  const std::size_t start = (ring_head_ + off) % ring_.size();
  const std::size_t first = std::min(n, ring_.size() - start);
  iovec iov[2] = {{ring_.data() + start, first}, {ring_.data(), n - first}};
  for (;;) {
    const ssize_t w = ::writev(fd_, iov, first < n ? 2 : 1);
    if (w < 0 && errno == EINTR) continue;
    return static_cast<long>(w);
  }
}

/// The line's schedule: a line idle for longer than one loop period has no more than one
/// period's worth of bytes to catch up with. `allowed`: bytes it could have carried by now.
bool EmulatorLink::line_free(int64_t now_ns, std::size_t& allowed) {
  if (byte_ns_ <= 0.0) {
    allowed = SIZE_MAX;
    return true;
  }
  const double now = static_cast<double>(now_ns);
  line_free_ns_ = std::max(line_free_ns_, now - static_cast<double>(opt_.period_ns));
  const double spare = now - line_free_ns_;
  allowed = spare > 0.0 ? static_cast<std::size_t>(spare / byte_ns_) : 0;
  return line_free_ns_ <= now;
}

void EmulatorLink::flush(int64_t now_ns) {
  if (fd_ < 0) return;
  if (opt_.kind == LinkOptions::Kind::udp) {
    // One datagram per chunk, whole, when the line is free; it keeps the line busy for its length.
    std::size_t allowed = 0;
    while (chunk_count_ > 0 && line_free(now_ns, allowed)) {
      const Chunk& c = chunks_[chunk_head_];
      line_free_ns_ += static_cast<double>(c.len) * byte_ns_;
      const long w = write_head(0, c.len);
      if (w >= 0) {
        c_.bytes_sent += static_cast<uint64_t>(w);
        pop_head(true);
        continue;
      }
      const int err = errno;
      if (err != EAGAIN && err != EWOULDBLOCK && err != ENOBUFS) count_error("write", err);
      pop_head(false);  // the datagram is lost, as on a congested network
    }
    return;
  }
  // pty: a byte stream, at most `allowed` bytes now.
  std::size_t allowed = 0;
  line_free(now_ns, allowed);
  while (chunk_count_ > 0 && allowed > 0) {
    long w = 0;
    Chunk& c = chunks_[chunk_head_];
    if (need_delimiter_) {
      // The frame before was cut short: end it, so the bridge resyncs here instead of
      // losing the next frame too.
      const uint8_t zero = 0;
      do w = ::write(fd_, &zero, 1);
      while (w < 0 && errno == EINTR);
      if (w == 1) {
        need_delimiter_ = false;
        ++c_.bytes_sent;
        --allowed;
        line_free_ns_ += byte_ns_;
        continue;
      }
    } else {
      const std::size_t n = std::min<std::size_t>(c.len - c.off, allowed);
      w = write_head(c.off, n);
      if (w > 0) {
        c.off += static_cast<uint32_t>(w);
        c_.bytes_sent += static_cast<uint64_t>(w);
        allowed -= static_cast<std::size_t>(w);
        line_free_ns_ += static_cast<double>(w) * byte_ns_;
        if (c.off == c.len) pop_head(true);
        continue;
      }
    }
    // Nobody takes the bytes (the pty's buffer is full: no bridge reads it), or an error:
    // the line carries them to no one. The rest of this chunk is lost; the time it takes
    // on the line is spent anyway, so drops too happen at the line rate.
    const int err = w < 0 ? errno : EAGAIN;
    if (err != EAGAIN && err != EWOULDBLOCK) count_error("write", err);
    const std::size_t rest = c.len - c.off;
    if (c.off > 0) need_delimiter_ = true;
    pop_head(false);
    allowed -= std::min(allowed, rest);
    line_free_ns_ += static_cast<double>(rest) * byte_ns_;
    if (err != EAGAIN && err != EWOULDBLOCK) return;  // do not spin on a broken link
  }
}

}  // namespace plexus::emulator
