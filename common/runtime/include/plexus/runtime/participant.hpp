// A DDS participant on the vendor chosen at run time, and typed publishers and
// subscribers over the generated message types.
//
//   auto p = plexus::rt::Participant::create({.vendor = Vendor::cyclone, .domain_id = 7, .name = "observer"});
//   auto pub = p->publisher<plexus::msg::Pose2D>("robot1/pose", qos.get("state"));
//   plexus::msg::Pose2D msg; msg.x(1.0); pub.publish(msg);
//
// Traffic stays on the loopback interface with unicast discovery unless the options say
// otherwise (see NetworkOptions): no packet leaves the machine by default.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "plexus/base/clock.hpp"
#include "plexus/base/participants_per_host.hpp"
#include "plexus/msg/messages.hpp"
#include "plexus/runtime/discovery.hpp"
#include "plexus/runtime/endpoint_backend.hpp"
#include "plexus/runtime/events.hpp"
#include "plexus/runtime/naming.hpp"
#include "plexus/runtime/qos.hpp"
#include "plexus/runtime/security.hpp"
#include "plexus/runtime/transport.hpp"
#include "plexus/runtime/vendor.hpp"

namespace plexus::rt {

/// Where DDS traffic goes. The default keeps everything on 127.0.0.1 with unicast discovery.
struct NetworkOptions {
  /// Address of the one interface DDS may use (loopback by default).
  std::string interface_address = "127.0.0.1";
  /// Unicast discovery peers (addresses). Default: the interface itself.
  std::vector<std::string> peers = {"127.0.0.1"};
  /// Participants of the domain one host may hold: this participant takes a free RTPS
  /// participant id (index) in 0..n-1, and discovery probes those n on each peer. Every
  /// process of a deployment should have the same value (--max-participants).
  int max_participants_per_host = kDefaultParticipantsPerHost;
  /// Period of a reliable writer's heartbeat while a reader has not acknowledged a sample.
  /// A reader asks for a lost sample only when a heartbeat tells it what it missed, and it
  /// delivers in order, so a loss holds a reliable stream up for about this long: a lockstep
  /// step, or a realtime input (at 100 Hz, a repair within half a period arrives before the
  /// reader's next tick). Fast DDS applies it to every reliable writer (its default is 3 s),
  /// Cyclone DDS to the domain (Internal/HeartbeatInterval, default 100 ms); both then answer
  /// a heartbeat and a request for repair within 1 ms (Fast DDS: 5 ms each; Cyclone's
  /// NackDelay: 100 ms). The cost is a heartbeat and its answer per reader every period, only
  /// while samples are unacknowledged. docs/runtime.md, docs/distributed.md (Faults).
  double reliable_heartbeat_s = 0.005;
  /// Shared memory between the participants of one host, or UDP only (transport.hpp).
  Transport transport = Transport::automatic;
};

struct ParticipantOptions {
  Vendor vendor = Vendor::fast;
  int domain_id = 0;            ///< 0..232
  std::string name = "plexus";  ///< service name: appears in logs and in remote endpoints' events
  NetworkOptions network;
  /// DDS Security (off by default): identity, permissions, governance (security.hpp).
  SecurityOptions security;
  /// Topic and type names on the wire: plexus's, or ROS 2's mapping (naming.hpp, docs/ros2.md).
  Naming naming = Naming::plexus;
};

template <class T>
class Publisher;
template <class T>
class Subscriber;

class Participant {
 public:
  /// Creates the participant; throws InputError for bad options (security files included,
  /// checked by check_security_files) and std::runtime_error if the vendor cannot create it.
  static std::unique_ptr<Participant> create(const ParticipantOptions& options);

  virtual ~Participant() = default;
  Participant(const Participant&) = delete;
  Participant& operator=(const Participant&) = delete;

  virtual Vendor vendor() const = 0;
  const ParticipantOptions& options() const { return options_; }

  /// Registers a handler for every endpoint event of this participant (also logged).
  /// Set it before creating endpoints.
  void on_event(EventHandler handler) { handler_ = std::move(handler); }

  template <class T>
  Publisher<T> publisher(const std::string& topic, const QosProfile& qos) {
    return Publisher<T>(make_writer(msg::type_support<T>(), topic, qos));
  }
  template <class T>
  Subscriber<T> subscriber(const std::string& topic, const QosProfile& qos) {
    return Subscriber<T>(make_reader(msg::type_support<T>(), topic, qos));
  }

  /// Untyped endpoints (tools that pick the type at run time). `topic` as plexus names it;
  /// on the wire under the participant's naming (naming.hpp).
  std::unique_ptr<WriterBackend> make_writer(const msg::TypeSupport& type, const std::string& topic,
                                             const QosProfile& qos) {
    return create_writer(type, wire_names(type, topic), qos);
  }
  std::unique_ptr<ReaderBackend> make_reader(const msg::TypeSupport& type, const std::string& topic,
                                             const QosProfile& qos) {
    return create_reader(type, wire_names(type, topic), qos);
  }

  /// The longest participant, topic or type name discovery carries between the vendors:
  /// Fast DDS 2.9 drops a discovery announcement with a longer one (docs/runtime.md, Known
  /// limits). A participant's name is cut to it (bounded_name); a topic or type name over it
  /// is refused.
  static constexpr std::size_t kMaxDiscoveryName = 251;

  /// Every endpoint discovered so far on this domain, local and remote, with its type name
  /// and QoS (see discovery.hpp), its topic and type named as plexus names them (naming.hpp).
  /// Discovery takes time: tools wait a period first.
  std::vector<DiscoveredEndpoint> discovered_endpoints() const;

 protected:
  explicit Participant(ParticipantOptions options) : options_(std::move(options)) {}
  /// dds_names(), refused (InputError) when a name is longer than kMaxDiscoveryName or a topic
  /// name holds a character one vendor refuses (letters, digits, '_' and '/' pass).
  DdsNames wire_names(const msg::TypeSupport& type, const std::string& topic) const;
  /// The vendor's endpoints, under the names they have on the wire.
  virtual std::unique_ptr<WriterBackend> create_writer(const msg::TypeSupport& type, const DdsNames& names,
                                                       const QosProfile& qos) = 0;
  virtual std::unique_ptr<ReaderBackend> create_reader(const msg::TypeSupport& type, const DdsNames& names,
                                                       const QosProfile& qos) = 0;
  /// What the vendor's discovery reports, names as on the wire.
  virtual std::vector<DiscoveredEndpoint> dds_endpoints() const = 0;
  /// Back ends call this for every event: logs it, then calls the handler.
  void emit(const Event& e) const;

 private:
  ParticipantOptions options_;
  EventHandler handler_;
};

/// Typed publisher. publish() fills the header's sequence number and publish time, and the
/// origin time if the caller left it 0 (this sample starts a chain).
template <class T>
class Publisher {
 public:
  Publisher() = default;
  explicit Publisher(std::unique_ptr<WriterBackend> w) : w_(std::move(w)) {}

  bool publish(T& msg) {
    auto& h = msg.header();
    h.seq_num(++seq_);
    const int64_t now = wall_time_ns();
    h.publish_time_ns(now);
    if (h.origin_time_ns() == 0) h.origin_time_ns(now);
    return w_->write(&msg);
  }
  void assert_liveliness() { w_->assert_liveliness(); }
  int matched_count() const { return w_->matched_count(); }
  /// See WriterBackend::wait_for_acks.
  bool wait_for_acks(int64_t timeout_ns) { return w_->wait_for_acks(timeout_ns); }
  uint64_t published() const { return seq_; }
  explicit operator bool() const { return static_cast<bool>(w_); }

 private:
  std::unique_ptr<WriterBackend> w_;
  uint64_t seq_ = 0;
};

/// Typed subscriber with take-based reading, suited to a loop thread, or receive-thread
/// delivery (on_sample) for event-driven readers.
template <class T>
class Subscriber {
 public:
  Subscriber() = default;
  explicit Subscriber(std::unique_ptr<ReaderBackend> r) : r_(std::move(r)) {}

  /// Oldest unread sample; false if none.
  bool take(T& out, SampleMeta* meta = nullptr) { return r_->take(&out, meta); }
  /// Drains the reader and keeps the newest sample; false if there was none. A malformed
  /// sample after the newest valid one leaves `out` as that valid one.
  bool take_latest(T& out, SampleMeta* meta = nullptr) {
    bool any = false;
    T next;
    while (r_->take(&next, meta)) {
      out = next;
      any = true;
    }
    return any;
  }
  /// Blocks until data is available or the timeout passes.
  bool wait(int64_t timeout_ns) { return r_->wait(timeout_ns); }
  /// Event-driven delivery on the DDS receive thread (ReaderBackend::set_data_callback):
  /// fn(T& sample, const SampleMeta& meta) is called once per valid sample, oldest first,
  /// from a vendor thread (a local writer's own thread for a same-vendor writer in this
  /// process), never two at once; no loop thread is woken. `buffer` is the one
  /// sample it decodes into, reused for every sample (reserve its sequences to keep the
  /// steady state free of allocation); fn may change it (e.g. publish it onwards). For
  /// readers whose reaction is short (a reply, a forward); a periodic loop that reads the
  /// newest value keeps take_latest. Once per subscriber; do not take() from it besides.
  template <class Fn>
  void on_sample(Fn fn, T buffer = T{}) {
    struct Delivery {
      ReaderBackend* reader;
      Fn fn;
      T sample;
      SampleMeta meta;
    };
    // One allocation at set-up; the callback owns it for the reader's life.
    auto d = std::make_shared<Delivery>(Delivery{r_.get(), std::move(fn), std::move(buffer), {}});
    r_->set_data_callback([d] {
      while (d->reader->take(&d->sample, &d->meta)) d->fn(d->sample, static_cast<const SampleMeta&>(d->meta));
    });
  }
  int matched_count() const { return r_->matched_count(); }
  uint64_t malformed_count() const { return r_->malformed_count(); }
  explicit operator bool() const { return static_cast<bool>(r_); }

 private:
  std::unique_ptr<ReaderBackend> r_;
};

}  // namespace plexus::rt
