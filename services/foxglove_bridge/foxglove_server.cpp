#include "foxglove_server.hpp"

#include <algorithm>
#include <chrono>
#include <future>
#include <map>
#include <mutex>
#include <thread>
#include <vector>

#include "channel_table.hpp"
#include "plexus/base/clock.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/base/logging.hpp"
#include "plexus/web/ws_transport.hpp"

namespace plexus::foxglove {
namespace {

using web::WsTransport;

/// The bridge's readers: best effort, volatile, a short history (see the header).
rt::QosProfile reader_qos() {
  rt::QosProfile q;
  q.name = "foxglove_bridge";
  q.reliability = rt::QosProfile::Reliability::best_effort;
  q.durability = rt::QosProfile::Durability::volatile_;
  q.history = rt::QosProfile::History::keep_last;
  q.depth = 16;
  return q;
}

}  // namespace

struct FoxgloveServer::Impl {
  struct Client {
    std::map<uint32_t, uint32_t> subscriptions;  // subscription id -> channel id
    uint64_t sent = 0, dropped = 0;
  };
  /// One channel's DDS reader, created on its first subscription.
  struct ChannelReader {
    const msg::TypeSupport* type = nullptr;
    uint32_t channel = 0;
    std::unique_ptr<rt::ReaderBackend> reader;
    void* sample = nullptr;
    std::vector<unsigned char> raw;
    ~ChannelReader() {
      reader.reset();  // no callback after this
      if (sample) type->destroy(sample);
    }
  };

  rt::Participant& participant;
  BridgeOptions o;
  std::string session_id = std::to_string(wall_time_ns());

  // The I/O thread only.
  std::map<uint64_t, Client> clients;
  std::vector<double> latency_us;  // ring of the last kLatencySamples sends
  std::size_t latency_next = 0;
  uint64_t clients_seen = 0;

  mutable std::mutex table_mu;  // the table: discovery (main thread) and the I/O thread
  ChannelTable table;
  std::mutex readers_mu;
  std::map<uint32_t, std::unique_ptr<ChannelReader>> readers;

  /// Samples on their way from the DDS threads to the I/O thread: one wake-up drains them all
  /// (a post per sample cost a wake-up, and most of the bridge's CPU, each).
  struct Pending {
    uint32_t channel;
    int64_t receive_ns;
    std::vector<unsigned char> frame;
  };
  std::mutex out_mu;
  std::vector<Pending> out_queue, out_draining;
  bool drain_posted = false;
  std::atomic<uint64_t> sent{0}, dropped_slow_client{0}, dropped_queue_full{0}, samples{0};
  static constexpr std::size_t kLatencySamples = 100000;

  std::unique_ptr<WsTransport> ws;  // the last member: destroyed first, with its I/O thread

  Impl(rt::Participant& p, BridgeOptions options) : participant(p), o(std::move(options)) {
    latency_us.reserve(kLatencySamples);
    WsTransport::Handlers h;
    h.on_open = [this](uint64_t c) { on_open(c); };
    h.on_close = [this](uint64_t c) { clients.erase(c); };
    h.on_text = [this](uint64_t c, const std::string& text) { on_text(c, text); };
    try {
      ws = std::make_unique<WsTransport>(o.address, o.port, kSubprotocol, std::move(h));
    } catch (const std::runtime_error& e) {
      // "'x' is not an IP address" names the address; everything else the port.
      throw InputError(std::string(e.what()[0] == '\'' ? "--address: " : "--port: ") + e.what());
    }
  }

  ~Impl() {
    {
      std::lock_guard lk(readers_mu);
      readers.clear();  // no DDS callback posts after this
    }
    ws.reset();
  }

  void send_text(uint64_t h, const std::string& text) { ws->send_text(h, text); }

  void on_open(uint64_t h) {
    clients[h] = Client{};
    ++clients_seen;
    send_text(h, server_info(o.name, session_id));
    std::vector<Channel> all;
    {
      std::lock_guard lk(table_mu);
      all = table.all();
    }
    send_text(h, advertise(all));  // at least one advertise, even empty (the spec)
  }

  void on_text(uint64_t h, const std::string& text) {
    auto c = clients.find(h);
    if (c == clients.end()) return;
    const ClientMessage m = parse_client_message(text);
    if (m.op == ClientMessage::Op::unknown) return send_text(h, status(1, m.error));
    if (m.op == ClientMessage::Op::unsubscribe) {
      for (uint32_t id : m.unsubscriptions) c->second.subscriptions.erase(id);
      return;
    }
    for (const auto& [id, channel] : m.subscriptions) {
      const msg::TypeSupport* type = nullptr;
      {
        std::lock_guard lk(table_mu);
        if (const Channel* ch = table.find(channel)) type = ch->type;
      }
      if (!type) {
        send_text(h, status(1, "subscribe: channel " + std::to_string(channel) + " is not advertised"));
        continue;
      }
      if (c->second.subscriptions.count(id)) {
        send_text(h, status(2, "subscribe: subscription id " + std::to_string(id) + " is in use"));
        continue;
      }
      c->second.subscriptions[id] = channel;
      ensure_reader(channel, *type);
    }
  }

  void ensure_reader(uint32_t channel, const msg::TypeSupport& type) {
    std::lock_guard lk(readers_mu);
    if (readers.count(channel)) return;
    std::string topic;
    {
      std::lock_guard tl(table_mu);
      if (const Channel* ch = table.find(channel)) topic = ch->topic;
    }
    if (topic.empty()) return;
    auto r = std::make_unique<ChannelReader>();
    r->type = &type;
    r->channel = channel;
    r->sample = type.create();
    r->raw.reserve(type.max_cdr_size);
    r->reader = participant.make_reader(type, topic, reader_qos());
    ChannelReader* self = r.get();
    r->reader->set_data_callback([this, self] { on_samples(*self); });
    readers.emplace(channel, std::move(r));
  }

  /// On a DDS receive thread: each sample's CDR queued for the I/O thread, unless the queue is full.
  void on_samples(ChannelReader& r) {
    rt::SampleMeta meta;
    while (r.reader->take_raw(r.sample, r.raw, &meta)) {
      samples.fetch_add(1, std::memory_order_relaxed);
      Pending p{r.channel, meta.receive_time_ns, {}};
      message_data(p.frame, 0, static_cast<uint64_t>(meta.receive_time_ns), r.raw.data(), r.raw.size());
      std::lock_guard lk(out_mu);
      if (static_cast<int>(out_queue.size()) >= o.max_queued_frames) {
        dropped_queue_full.fetch_add(1, std::memory_order_relaxed);
        continue;
      }
      out_queue.push_back(std::move(p));
      if (!drain_posted) {
        drain_posted = true;
        ws->post([this] { drain(); });
      }
    }
  }

  /// On the I/O thread: everything queued so far, in order.
  void drain() {
    {
      std::lock_guard lk(out_mu);
      out_draining.swap(out_queue);
      drain_posted = false;
    }
    for (auto& p : out_draining) deliver(p.channel, p.receive_ns, p.frame);
    out_draining.clear();
  }

  /// On the I/O thread: the frame to every subscriber of the channel, with its subscription id.
  void deliver(uint32_t channel, int64_t receive_ns, std::vector<unsigned char>& frame) {
    for (auto& [h, c] : clients)
      for (const auto& [sub, ch] : c.subscriptions) {
        if (ch != channel) continue;
        if (ws->buffered(h) > o.max_client_buffer_bytes) {
          ++c.dropped;
          dropped_slow_client.fetch_add(1, std::memory_order_relaxed);
          continue;
        }
        for (int i = 0; i < 4; ++i) frame[1 + i] = static_cast<unsigned char>(sub >> (8 * i));
        const double lat = static_cast<double>(wall_time_ns() - receive_ns) * 1e-3;
        if (!ws->send_binary(h, frame.data(), frame.size())) continue;
        ++c.sent;
        sent.fetch_add(1, std::memory_order_relaxed);
        if (latency_us.size() < kLatencySamples)
          latency_us.push_back(lat);
        else
          latency_us[latency_next++ % kLatencySamples] = lat;
      }
  }

  void discover() {
    std::map<std::string, const msg::TypeSupport*> topics;
    for (const auto& e : participant.discovered_endpoints()) {
      if (!e.is_writer || e.local) continue;
      if (const msg::TypeSupport* ts = msg::find_type_support(e.type_name)) topics.emplace(e.topic, ts);
    }
    ChannelTable::Diff d;
    {
      std::lock_guard lk(table_mu);
      d = table.update(topics);
    }
    if (d.added.empty() && d.removed.empty()) return;
    ws->post([this, d] {
      for (auto& [h, c] : clients) {
        for (auto it = c.subscriptions.begin(); it != c.subscriptions.end();)
          it = std::count(d.removed.begin(), d.removed.end(), it->second) ? c.subscriptions.erase(it) : std::next(it);
        if (!d.removed.empty()) send_text(h, unadvertise(d.removed));
        if (!d.added.empty()) send_text(h, advertise(d.added));
      }
    });
  }

  void send_time() {
    ws->post([this] {
      const auto frame = time_frame(static_cast<uint64_t>(wall_time_ns()));
      for (auto& [h, c] : clients) ws->send_binary(h, frame.data(), frame.size());
    });
  }

  void close_all() {
    ws->post([this] { ws->close_all("foxglove_bridge stopping"); });
  }
};

FoxgloveServer::FoxgloveServer(rt::Participant& participant, BridgeOptions options)
    : impl_(std::make_unique<Impl>(participant, std::move(options))) {}

FoxgloveServer::~FoxgloveServer() = default;

void FoxgloveServer::run_until(const std::atomic<bool>& stop) {
  const int64_t discovery = static_cast<int64_t>(impl_->o.discovery_period_s * 1e9);
  const int64_t time = static_cast<int64_t>(impl_->o.time_period_s * 1e9);
  int64_t next_discovery = monotonic_ns(), next_time = monotonic_ns();
  while (!stop) {
    const int64_t now = monotonic_ns();
    if (now >= next_discovery) {
      impl_->discover();
      next_discovery += discovery;
    }
    if (now >= next_time) {
      impl_->send_time();
      next_time += time;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  impl_->close_all();
  std::this_thread::sleep_for(std::chrono::milliseconds(200));  // the close frames go out
}

nlohmann::ordered_json FoxgloveServer::stats() const {
  std::vector<double> lat;
  std::promise<void> done;
  // The latency ring and the clients belong to the I/O thread: read there.
  std::size_t clients_now = 0;
  uint64_t seen = 0;
  impl_->ws->post([&] {
    lat = impl_->latency_us;
    clients_now = impl_->clients.size();
    seen = impl_->clients_seen;
    done.set_value();
  });
  if (done.get_future().wait_for(std::chrono::seconds(2)) != std::future_status::ready) lat.clear();
  std::sort(lat.begin(), lat.end());
  const auto q = [&](double p) { return lat.empty() ? 0.0 : lat[static_cast<std::size_t>(p * (lat.size() - 1))]; };
  std::size_t channels = 0;
  {
    std::lock_guard lk(impl_->table_mu);
    channels = impl_->table.all().size();
  }
  return {{"clients", clients_now},
          {"clients_seen", seen},
          {"channels", channels},
          {"samples", impl_->samples.load()},
          {"sent", impl_->sent.load()},
          {"dropped_slow_client", impl_->dropped_slow_client.load()},
          {"dropped_queue_full", impl_->dropped_queue_full.load()},
          {"latency_p50_us", q(0.5)},
          {"latency_p99_us", q(0.99)},
          {"latency_max_us", lat.empty() ? 0.0 : lat.back()}};
}

}  // namespace plexus::foxglove
