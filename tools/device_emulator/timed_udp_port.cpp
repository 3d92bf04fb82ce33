#include "timed_udp_port.hpp"

#include <poll.h>
#include <sys/socket.h>
#include <time.h>

#include <algorithm>
#include <cstring>

#include "plexus/base/clock.hpp"
#include "plexus/link/protocol.hpp"

namespace plexus::emulator {
namespace {

constexpr std::size_t kRingSlots = 512;

void sleep_until_wall(int64_t wall_ns) {
  timespec ts{static_cast<time_t>(wall_ns / 1'000'000'000), static_cast<long>(wall_ns % 1'000'000'000)};
  while (clock_nanosleep(CLOCK_REALTIME, TIMER_ABSTIME, &ts, nullptr) == EINTR) {}
}

}  // namespace

TimedUdpPort::TimedUdpPort(int fd, DeviceClockModel clock, double jitter_s, uint64_t seed)
    : fd_(fd), clock_(clock), jitter_s_(jitter_s), rng_(seed) {
  in_.slots.resize(kRingSlots);
  out_.slots.resize(kRingSlots);
  receiver_ = std::thread([this] { receive_loop(); });
  sender_ = std::thread([this] { send_loop(); });
}

TimedUdpPort::~TimedUdpPort() {
  stop_ = true;
  send_cv_.notify_all();
  receiver_.join();
  sender_.join();
}

int64_t TimedUdpPort::delay_ns() {
  if (jitter_s_ <= 0) return 0;
  return static_cast<int64_t>(std::uniform_real_distribution<double>(0.0, jitter_s_)(rng_) * 1e9);
}

bool TimedUdpPort::push(Ring& r, const uint8_t* data, std::size_t n, int64_t now_ns) {
  if (r.count == r.slots.size() || n > sizeof(Datagram::bytes)) {
    ++c_.ring_drops;
    return false;
  }
  Datagram& d = r.slots[(r.head + r.count) % r.slots.size()];
  d.due_ns = std::max(r.last_due, now_ns + delay_ns());
  r.last_due = d.due_ns;
  d.len = static_cast<uint16_t>(n);
  std::memcpy(d.bytes, data, n);
  ++r.count;
  return true;
}

bool TimedUdpPort::queue(const uint8_t* data, std::size_t n) {
  std::lock_guard<std::mutex> lk(mu_);
  const bool ok = push(out_, data, n, wall_time_ns());
  if (ok) send_cv_.notify_one();
  return ok;
}

bool TimedUdpPort::pop_in(Datagram& d) {
  std::lock_guard<std::mutex> lk(mu_);
  if (in_.count == 0 || in_.slots[in_.head].due_ns > wall_time_ns()) return false;
  d = in_.slots[in_.head];
  in_.head = (in_.head + 1) % in_.slots.size();
  --in_.count;
  ++c_.datagrams_in;
  return true;
}

TimedPortCounters TimedUdpPort::counters() const {
  std::lock_guard<std::mutex> lk(mu_);
  return c_;
}

void TimedUdpPort::answer(const link::Frame& request, int64_t now_ns) {
  // t2: the device's clock when the request arrived (its delay is over now); t3: as the
  // response leaves the device (its own delay on the line follows).
  uint8_t payload[24];
  clock_.answer(request.payload, now_ns, payload);
  uint8_t frame[link::kMaxEncodedFrame];
  const std::size_t len = link::encode_frame(link::kTimeResponseId, response_seq_++, payload, sizeof payload, frame);
  std::lock_guard<std::mutex> lk(mu_);
  ++c_.time_requests;
  if (push(out_, frame, len, wall_time_ns())) send_cv_.notify_one();
}

void TimedUdpPort::receive_loop() {
  uint8_t buf[2048];
  while (!stop_.load(std::memory_order_relaxed)) {
    pollfd p{fd_, POLLIN, 0};
    if (::poll(&p, 1, 50) <= 0) continue;
    const ssize_t n = ::recv(fd_, buf, sizeof buf, 0);
    if (n <= 0) continue;
    const int64_t arrived = wall_time_ns();
    bool request = false;
    link::Frame req;
    decoder_.feed(buf, static_cast<std::size_t>(n), [&](const link::Frame& f) {
      if (f.id == link::kTimeRequestId && f.payload_size == 24) request = true, req = f;
    });
    if (!request) {
      std::lock_guard<std::mutex> lk(mu_);
      (void)push(in_, buf, static_cast<std::size_t>(n), arrived);
      continue;
    }
    int64_t due;
    {
      std::lock_guard<std::mutex> lk(mu_);
      due = std::max(in_.last_due, arrived + delay_ns());
      in_.last_due = due;
    }
    sleep_until_wall(due);
    answer(req, due);
  }
}

void TimedUdpPort::send_loop() {
  std::unique_lock<std::mutex> lk(mu_);
  Datagram d;
  while (!stop_.load(std::memory_order_relaxed)) {
    if (out_.count == 0) {
      send_cv_.wait_for(lk, std::chrono::milliseconds(50));
      continue;
    }
    const int64_t due = out_.slots[out_.head].due_ns;
    if (due > wall_time_ns()) {
      lk.unlock();
      sleep_until_wall(std::min(due, wall_time_ns() + 50'000'000));
      lk.lock();
      continue;
    }
    d = out_.slots[out_.head];
    out_.head = (out_.head + 1) % out_.slots.size();
    --out_.count;
    lk.unlock();
    const bool sent = ::send(fd_, d.bytes, d.len, 0) == static_cast<ssize_t>(d.len);
    lk.lock();
    ++(sent ? c_.datagrams_out : c_.send_errors);
  }
}

}  // namespace plexus::emulator
