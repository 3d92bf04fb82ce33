// Fast DDS 2.9 back end.
#include "fast_participant.hpp"

#include <optional>

#include <fastdds/rtps/transport/UDPv4TransportDescriptor.h>
#include <fastdds/rtps/transport/shared_mem/SharedMemTransportDescriptor.h>
#include <fastrtps/utils/IPLocator.h>
#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/dds/domain/DomainParticipantListener.hpp>
#include <fastdds/dds/log/Log.hpp>
#include <fastdds/dds/log/StdoutErrConsumer.hpp>
#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/DataWriterListener.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/DataReaderListener.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/topic/Topic.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>

#include <atomic>
#include <functional>
#include <map>
#include <mutex>
#include <sstream>
#include <stdexcept>

#include "../endpoint_listener.hpp"
#include "../policy_names.hpp"
#include "fast_endpoint_qos.hpp"
#include "fast_security.hpp"
#include "plexus/base/clock.hpp"
#include "plexus/msg/checked_fast_type.hpp"
#include "shm_ports.hpp"

namespace plexus::rt {
namespace {

namespace fdds = eprosima::fastdds::dds;
using eprosima::fastrtps::rtps::IPLocator;
using eprosima::fastrtps::rtps::Locator_t;

/// The SHM transport's healthy_check_timeout_ms (where it is set says why).
constexpr uint32_t kShmHealthyCheckMs = 90;

eprosima::fastrtps::Duration_t to_fast_duration(double s) {
  if (s <= 0) return eprosima::fastrtps::c_TimeInfinite;
  const auto sec = static_cast<int32_t>(s);
  return eprosima::fastrtps::Duration_t(sec, static_cast<uint32_t>((s - sec) * 1e9));
}

std::string policy_name(fdds::QosPolicyId_t id) {
  if (id == fdds::DATAREPRESENTATION_QOS_POLICY_ID) return "DATA_REPRESENTATION";
  return detail::standard_policy_name(static_cast<int>(id));
}

// The QoS of a profile, applied to a writer or a reader the same way.
template <class Q>
void apply_common(Q& q, const QosProfile& p) {
  q.reliability().kind = p.reliability == QosProfile::Reliability::reliable ? fdds::RELIABLE_RELIABILITY_QOS
                                                                            : fdds::BEST_EFFORT_RELIABILITY_QOS;
  q.reliability().max_blocking_time = to_fast_duration(p.max_blocking_time_s);
  q.durability().kind = p.durability == QosProfile::Durability::transient_local ? fdds::TRANSIENT_LOCAL_DURABILITY_QOS
                                                                                : fdds::VOLATILE_DURABILITY_QOS;
  q.history().kind =
      p.history == QosProfile::History::keep_all ? fdds::KEEP_ALL_HISTORY_QOS : fdds::KEEP_LAST_HISTORY_QOS;
  q.history().depth = p.depth;
  q.deadline().period = to_fast_duration(p.deadline_s);
  switch (p.liveliness) {
    case QosProfile::Liveliness::automatic: q.liveliness().kind = fdds::AUTOMATIC_LIVELINESS_QOS; break;
    case QosProfile::Liveliness::manual_by_participant:
      q.liveliness().kind = fdds::MANUAL_BY_PARTICIPANT_LIVELINESS_QOS;
      break;
    case QosProfile::Liveliness::manual_by_topic: q.liveliness().kind = fdds::MANUAL_BY_TOPIC_LIVELINESS_QOS; break;
  }
  q.liveliness().lease_duration = to_fast_duration(p.liveliness_lease_s);
  if (p.liveliness_lease_s > 0) q.liveliness().announcement_period = to_fast_duration(p.liveliness_lease_s / 3);
  q.lifespan().duration = to_fast_duration(p.lifespan_s);
  // Latency budget 0 means "no budget" (zero), not infinite as for the other durations.
  q.latency_budget().duration =
      p.latency_budget_s > 0 ? to_fast_duration(p.latency_budget_s) : eprosima::fastrtps::Duration_t(0, 0);
  // Data sharing off: same-host Fast DDS peers use the SHM transport (transport.hpp), RTPS
  // messages as over UDP. Fast DDS 2.9's data sharing gives every reader a listening thread
  // of its own: a 50-robot fleet's controllers' process (100 readers) took p50 240 ms of its
  // 10 ms tick with it, 1.9 ms without; a data-sharing reader misses a transient-local
  // writer's first sample when it matches after the write, and its listening thread locks an
  // interprocess mutex with no recovery from a dead owner (docs/runtime.md, Transports).
  q.data_sharing().off();
  auto& repr = [&q]() -> fdds::DataRepresentationQosPolicy& {
    if constexpr (requires { q.representation(); })
      return q.representation();  // DataWriterQos
    else
      return q.type_consistency().representation;  // DataReaderQos
  }();
  repr.m_value.clear();
  repr.m_value.push_back(fdds::XCDR_DATA_REPRESENTATION);
  // A keep_last writer holds exactly `depth` samples. A reader keeps Fast DDS's default
  // limits: a reliable reader also holds samples received out of order until the gap before
  // them is filled or declared lost, and with max_samples = depth a reader that joins a
  // running writer (a restarted service) refuses every new sample, each then reported lost,
  // for the rest of the run (tests/fault, docs/distributed.md).
  if constexpr (requires { q.representation(); }) {
    if (p.history == QosProfile::History::keep_last) {
      q.resource_limits().max_samples = p.depth;
      q.resource_limits().max_samples_per_instance = p.depth;
    }
  }
}

/// Empties a writer's history before it is deleted. Fast DDS 2.9 (Debian 12's 2.9.1) releases
/// a deleted writer's samples while they are still in its history, without its lock
/// (RTPSWriter::deinit): a periodic heartbeat that fires meanwhile computes the gaps of that
/// history from released samples and loops for good (StatefulWriter::
/// add_gaps_for_holes_in_history_). Seen as a service that spun for 10 s at the end of a
/// launch until its teardown deadline (1 of 300 five-second launches on a loaded machine;
/// the launcher then waited 10 s for its acknowledgement; docs/runtime.md). Fixed upstream by
/// eProsima/Fast-DDS#4076 (December 2023), not in 2.9.1. clear_history() removes each sample
/// under the writer's lock, so the history stays whole, and the deletion has none to release.
void clear_before_delete(fdds::DataWriter* w) {
  std::size_t removed = 0;
  w->clear_history(&removed);
}

class FastWriter final : public WriterBackend, public fdds::DataWriterListener {
 public:
  FastWriter(const FastParticipant& owner, std::string topic, std::string local)
      : owner_(owner), events_(owner, std::move(topic), /*on_writer=*/true, std::move(local)) {}
  ~FastWriter() override {
    if (writer_) {
      writer_->set_listener(nullptr);
      clear_before_delete(writer_);
      owner_.publisher()->delete_datawriter(writer_);
    }
  }
  void attach(fdds::DataWriter* w) { writer_ = w; }

  bool write(const void* sample) override { return writer_->write(const_cast<void*>(sample)); }
  void assert_liveliness() override { writer_->assert_liveliness(); }
  int matched_count() const override { return events_.matched_count(); }
  bool wait_for_acks(int64_t timeout_ns) override {
    const eprosima::fastrtps::Duration_t max_wait(static_cast<int32_t>(timeout_ns / 1'000'000'000),
                                                  static_cast<uint32_t>(timeout_ns % 1'000'000'000));
    return writer_->wait_for_acknowledgments(max_wait) == eprosima::fastrtps::types::ReturnCode_t::RETCODE_OK;
  }

  void on_publication_matched(fdds::DataWriter*, const fdds::PublicationMatchedStatus& s) override {
    events_.matched(s.total_count, s.current_count, s.current_count_change,
                    owner_.describe_remote(s.last_subscription_handle));
  }
  void on_offered_deadline_missed(fdds::DataWriter*, const fdds::OfferedDeadlineMissedStatus& s) override {
    events_.deadline_missed(s.total_count);
  }
  void on_offered_incompatible_qos(fdds::DataWriter*, const fdds::OfferedIncompatibleQosStatus& s) override {
    events_.incompatible_qos(s.total_count, policy_name(s.last_policy_id));
  }
  void on_liveliness_lost(fdds::DataWriter*, const fdds::LivelinessLostStatus& s) override {
    events_.liveliness_lost(s.total_count);
  }

 private:
  const FastParticipant& owner_;
  detail::EndpointEvents events_;
  fdds::DataWriter* writer_ = nullptr;
};

class FastReader final : public ReaderBackend, public fdds::DataReaderListener {
 public:
  FastReader(const FastParticipant& owner, std::string topic, std::string local)
      : owner_(owner), events_(owner, std::move(topic), /*on_writer=*/false, std::move(local)) {}
  ~FastReader() override {
    if (reader_) {
      reader_->set_listener(nullptr);
      owner_.subscriber()->delete_datareader(reader_);
    }
  }
  void attach(fdds::DataReader* r) { reader_ = r; }

  bool take(void* sample, SampleMeta* meta) override { return take_into(sample, meta); }
  bool take_raw(void* sample, std::vector<unsigned char>& cdr, SampleMeta* meta) override {
    // Fast DDS decodes on this thread, inside take_next_sample: the checked type copies the
    // payload it decodes (the CDR as received) into `cdr` (checked_fast_type.hpp).
    const msg::FastRawCapture capture(cdr);
    return take_into(sample, meta);
  }
  bool take_into(void* sample, SampleMeta* meta) {
    fdds::SampleInfo info;
    msg::take_fast_decode_failure();  // a stale flag of this thread is not ours
    while (reader_->take_next_sample(sample, &info) == eprosima::fastrtps::types::ReturnCode_t::RETCODE_OK) {
      // Fast DDS hands over a sample whose decode failed as valid: dropped here, counted.
      if (msg::take_fast_decode_failure()) {
        ++malformed_;
        continue;
      }
      if (!info.valid_data) continue;  // dispose / unregister notifications
      if (meta) {
        meta->source_timestamp_ns = info.source_timestamp.to_ns();
        meta->receive_time_ns = wall_time_ns();
      }
      return true;
    }
    return false;
  }
  bool wait(int64_t timeout_ns) override {
    if (reader_->get_unread_count() > 0) return true;
    return reader_->wait_for_unread_message(
        eprosima::fastrtps::Duration_t(static_cast<long double>(timeout_ns) * 1e-9L));
  }
  int matched_count() const override { return events_.matched_count(); }
  uint64_t malformed_count() const override { return malformed_; }
  void set_data_callback(std::function<void()> fn) override {
    data_cb_.set(std::move(fn), events_.topic());  // before the listener can call it
    if (!reader_->set_listener(this, fdds::StatusMask::all()))
      throw std::runtime_error("Fast DDS: cannot set the data listener on '" + events_.topic() + "'");
    on_data_available(reader_);  // samples that arrived before the listener
  }
  // Fast DDS calls it on the thread that received the data (the transport's receive thread).
  void on_data_available(fdds::DataReader*) override { data_cb_(); }

  void on_subscription_matched(fdds::DataReader*, const fdds::SubscriptionMatchedStatus& s) override {
    events_.matched(s.total_count, s.current_count, s.current_count_change,
                    owner_.describe_remote(s.last_publication_handle));
  }
  void on_requested_deadline_missed(fdds::DataReader*, const fdds::RequestedDeadlineMissedStatus& s) override {
    events_.deadline_missed(s.total_count);
  }
  void on_requested_incompatible_qos(fdds::DataReader*, const fdds::RequestedIncompatibleQosStatus& s) override {
    events_.incompatible_qos(s.total_count, policy_name(s.last_policy_id));
  }
  void on_liveliness_changed(fdds::DataReader*, const fdds::LivelinessChangedStatus& s) override {
    events_.liveliness_changed(s.alive_count, s.not_alive_count, s.alive_count_change, s.not_alive_count_change,
                               owner_.describe_remote(s.last_publication_handle));
  }
  void on_sample_lost(fdds::DataReader*, const fdds::SampleLostStatus& s) override {
    events_.sample_lost(s.total_count);
  }

 private:
  const FastParticipant& owner_;
  detail::EndpointEvents events_;
  fdds::DataReader* reader_ = nullptr;
  std::atomic<uint64_t> malformed_{0};
  detail::DataCallback data_cb_;
};

}  // namespace

// Discovery cache: remote endpoints by GUID, so events can name the other side.
class FastParticipant::Discovery final : public fdds::DomainParticipantListener {
 public:
  struct Remote {
    std::string participant;
    std::string topic;
    bool is_writer = false;
    std::string qos;  // "reliability=..., durability=..., deadline=..."
    fdds::ReliabilityQosPolicyKind reliability{};
    fdds::DurabilityQosPolicyKind durability{};
    eprosima::fastrtps::Duration_t deadline;
    fdds::LivelinessQosPolicyKind liveliness{};
    DiscoveredEndpoint endpoint;  // for discovered_endpoints()
  };

  void on_participant_discovery(fdds::DomainParticipant*,
                                eprosima::fastrtps::rtps::ParticipantDiscoveryInfo&& info) override {
    std::lock_guard lk(mu_);
    std::ostringstream g;
    g << info.info.m_guid.guidPrefix;
    names_[g.str()] = info.info.m_participantName.to_string();
    using PDI = eprosima::fastrtps::rtps::ParticipantDiscoveryInfo;
    if (info.status == PDI::REMOVED_PARTICIPANT || info.status == PDI::DROPPED_PARTICIPANT)
      for (auto it = remotes_.begin(); it != remotes_.end();)
        it = it->first.rfind(g.str(), 0) == 0 ? remotes_.erase(it) : std::next(it);
  }
  void on_subscriber_discovery(fdds::DomainParticipant*,
                               eprosima::fastrtps::rtps::ReaderDiscoveryInfo&& info) override {
    const auto& r = info.info;
    Remote rem;
    rem.is_writer = false;
    rem.topic = r.topicName().to_string();
    rem.reliability = r.m_qos.m_reliability.kind;
    rem.durability = r.m_qos.m_durability.kind;
    rem.deadline = r.m_qos.m_deadline.period;
    rem.liveliness = r.m_qos.m_liveliness.kind;
    rem.endpoint.type_name = r.typeName().to_string();
    rem.endpoint.qos = detail::endpoint_qos_from_fast(r.m_qos);
    store(r.guid(), std::move(rem), info.status == eprosima::fastrtps::rtps::ReaderDiscoveryInfo::REMOVED_READER);
  }
  void on_publisher_discovery(fdds::DomainParticipant*, eprosima::fastrtps::rtps::WriterDiscoveryInfo&& info) override {
    const auto& w = info.info;
    Remote rem;
    rem.is_writer = true;
    rem.topic = w.topicName().to_string();
    rem.reliability = w.m_qos.m_reliability.kind;
    rem.durability = w.m_qos.m_durability.kind;
    rem.deadline = w.m_qos.m_deadline.period;
    rem.liveliness = w.m_qos.m_liveliness.kind;
    rem.endpoint.type_name = w.typeName().to_string();
    rem.endpoint.qos = detail::endpoint_qos_from_fast(w.m_qos);
    store(w.guid(), std::move(rem), info.status == eprosima::fastrtps::rtps::WriterDiscoveryInfo::REMOVED_WRITER);
  }

  std::string describe(const fdds::InstanceHandle_t& h) {
    std::lock_guard lk(mu_);
    std::ostringstream g;
    eprosima::fastrtps::rtps::GUID_t guid = eprosima::fastrtps::rtps::iHandle2GUID(h);
    g << guid;
    auto it = remotes_.find(g.str());
    if (it == remotes_.end()) return g.str();
    return label(it->second);
  }

  std::string incompatible(const std::string& topic, bool remote_is_writer, const std::string& policy) {
    std::lock_guard lk(mu_);
    std::string out;
    for (const auto& [guid, r] : remotes_) {
      if (r.topic != topic || r.is_writer != remote_is_writer) continue;
      out += (out.empty() ? "" : "; ") + label(r) + " " + policy_value(r, policy);
    }
    return out;
  }

 private:
  void store(const eprosima::fastrtps::rtps::GUID_t& guid, Remote rem, bool removed) {
    std::lock_guard lk(mu_);
    std::ostringstream g, p;
    g << guid;
    p << guid.guidPrefix;
    if (removed) {
      remotes_.erase(g.str());
      return;
    }
    auto n = names_.find(p.str());
    rem.participant = n != names_.end() && !n->second.empty() ? n->second : p.str();
    rem.endpoint.topic = rem.topic;
    rem.endpoint.is_writer = rem.is_writer;
    rem.endpoint.participant = rem.participant;
    rem.endpoint.guid = g.str();
    rem.endpoint.local = p.str() == local_prefix;
    remotes_[g.str()] = std::move(rem);
  }

 public:
  std::string local_prefix;  // this participant's GUID prefix, set once it exists
  std::vector<DiscoveredEndpoint> endpoints() {
    std::lock_guard lk(mu_);
    std::vector<DiscoveredEndpoint> out;
    for (const auto& [guid, r] : remotes_) out.push_back(r.endpoint);
    return out;
  }

 private:
  static std::string label(const Remote& r) {
    return std::string(r.is_writer ? "writer" : "reader") + " of participant '" + r.participant + "'";
  }
  static std::string policy_value(const Remote& r, const std::string& policy) {
    if (policy == "RELIABILITY")
      return std::string("offers RELIABILITY=") +
             (r.reliability == fdds::RELIABLE_RELIABILITY_QOS ? "reliable" : "best_effort");
    if (policy == "DURABILITY")
      return std::string("DURABILITY=") +
             (r.durability == fdds::VOLATILE_DURABILITY_QOS ? "volatile" : "transient_local+");
    if (policy == "DEADLINE") return "DEADLINE=" + std::to_string(r.deadline.to_ns() * 1e-9) + "s";
    if (policy == "LIVELINESS") return "LIVELINESS kind=" + std::to_string(static_cast<int>(r.liveliness));
    return "";
  }

  std::mutex mu_;
  std::map<std::string, std::string> names_;
  std::map<std::string, Remote> remotes_;
};

FastParticipant::FastParticipant(const ParticipantOptions& o)
    : Participant(o), discovery_(std::make_unique<Discovery>()) {
  // Fast DDS logs to stdout by default, where tools print their results (`plexus topic list
  // --json`): its own log goes to stderr instead. Security errors (a failed handshake with a
  // participant of another CA, for one) would otherwise break the JSON.
  static std::once_flag log_to_stderr;
  std::call_once(log_to_stderr, [] {
    auto consumer = std::make_unique<fdds::StdoutErrConsumer>();
    consumer->stderr_threshold(fdds::Log::Kind::Info);
    fdds::Log::ClearConsumers();
    fdds::Log::RegisterConsumer(std::move(consumer));
  });
  fdds::DomainParticipantQos pq;
  pq.name(o.name);
  // Transport: UDPv4 on the configured interface only (loopback by default), and unless
  // NetworkOptions::transport is udp, Fast DDS's shared-memory transport beside it. A peer
  // announces both; Fast DDS uses shared memory with a Fast DDS peer of the same host (same
  // host id in the SHM locator) and UDP with any other: a Cyclone DDS peer ignores the SHM
  // locators, another host cannot reach them. RTPS messages are encrypted before either
  // transport carries them, so DDS Security works over both (docs/runtime.md, Transports).
  // With shared memory (the default since 2026-11-30; docs/runtime.md, Transports), plexus keeps the participant off an
  // SHM port that a writer still holds from a killed process (shm_ports.hpp: Fast DDS 2.9 would otherwise let a
  // restarted reader take that port and never hear from such a writer again), under a host-wide lock until the
  // participant exists.
  pq.transport().use_builtin_transports = false;
  std::optional<detail::ShmParticipantLock> shm_lock;
  if (fast_shared_memory(o.network.transport)) {
    // The port health check's period, 1000 ms by default. A process that sends to a port for
    // the first time checks that every listener waiting on it has woken since the last
    // watchdog round, and if one has not, sleeps a third of this period before it checks
    // again (SharedMemGlobal.hpp, Port::healthy_check; eProsima/Fast-DDS issue 6535). An idle
    // listener wakes every third of the period, so the first write to a reader that just
    // joined could block the writing thread for up to 333 ms, in about one case in four
    // (bridges.balancing_contract_serial_fast: a 500 Hz bridge's samples 330 ms late, then in
    // a burst). At 90 ms the wait is at most 30 ms and rarer; idle listeners wake 33 times a
    // second; a listener must still be unscheduled for about 60 ms to be taken for dead (the
    // watchdog's own round stays 1 s). docs/runtime.md, Transports.
    auto shm = std::make_shared<eprosima::fastdds::rtps::SharedMemTransportDescriptor>();
    shm->healthy_check_timeout_ms(kShmHealthyCheckMs);
    pq.transport().user_transports.push_back(shm);
    shm_lock.emplace();
    // The segments of killed or crashed Fast DDS processes (0.5 MiB of memory each) go now,
    // so that a service restarted again and again does not fill /dev/shm (shm_ports.hpp).
    detail::remove_zombie_segments();
    const auto& pp = pq.wire_protocol().port;
    pq.wire_protocol().participant_id =
        detail::pick_shm_participant_id(static_cast<uint32_t>(o.domain_id), o.network.max_participants_per_host,
                                        {pp.portBase, pp.domainIDGain, pp.participantIDGain, pp.offsetd3});
  }
  auto udp = std::make_shared<eprosima::fastdds::rtps::UDPv4TransportDescriptor>();
  udp->interfaceWhiteList.push_back(o.network.interface_address);
  pq.transport().user_transports.push_back(udp);
  // Discovery: unicast only. A null locator means "the interface above, well-known port";
  // no multicast locator is set, so nothing goes to a multicast group.
  pq.wire_protocol().builtin.metatrafficMulticastLocatorList.clear();
  pq.wire_protocol().builtin.metatrafficUnicastLocatorList.clear();
  pq.wire_protocol().builtin.metatrafficUnicastLocatorList.push_back(Locator_t());
  pq.wire_protocol().builtin.initialPeersList.clear();
  // Announce every 0.5 s (Fast DDS's default: 3 s): a participant answers a newcomer only
  // with its next announcement, so a reader started (or restarted) beside a running writer
  // waits up to one period for its first sample (about 0.5 s on Cyclone DDS). Measured on a
  // 100 Hz writer: with 3 s half of the joining readers got nothing within 2 s; with 0.5 s
  // each gets its first samples in about 0.5 s.
  pq.wire_protocol().builtin.discovery_config.leaseDuration_announcementperiod =
      eprosima::fastrtps::Duration_t(0, 500'000'000);
  const auto& ports = pq.wire_protocol().port;
  for (const auto& peer : o.network.peers) {
    for (int pid = 0; pid < o.network.max_participants_per_host; ++pid) {
      Locator_t loc;
      IPLocator::setIPv4(loc, peer);
      loc.port = ports.portBase + ports.domainIDGain * static_cast<uint32_t>(o.domain_id) + ports.offsetd1 +
                 ports.participantIDGain * static_cast<uint32_t>(pid);
      pq.wire_protocol().builtin.initialPeersList.push_back(loc);
    }
  }
  detail::apply_fast_security(pq, o.security);
  auto* factory = fdds::DomainParticipantFactory::get_instance();
  participant_ = factory->create_participant(static_cast<fdds::DomainId_t>(o.domain_id), pq, discovery_.get(),
                                             fdds::StatusMask::none() << fdds::StatusMask::data_on_readers());
  shm_lock.reset();  // its ports are open
  if (!participant_)
    throw std::runtime_error("Fast DDS: cannot create participant on domain " + std::to_string(o.domain_id) +
                             (o.security.enabled ? " with DDS Security (identity '" + o.security.identity + "')" : ""));
  {
    std::ostringstream g;
    g << participant_->guid().guidPrefix;
    discovery_->local_prefix = g.str();
  }
  participant_->set_listener(discovery_.get(), fdds::StatusMask::none());
  publisher_ = participant_->create_publisher(fdds::PUBLISHER_QOS_DEFAULT);
  subscriber_ = participant_->create_subscriber(fdds::SUBSCRIBER_QOS_DEFAULT);
  if (!publisher_ || !subscriber_) throw std::runtime_error("Fast DDS: cannot create publisher/subscriber");
}

FastParticipant::~FastParticipant() {
  if (participant_) {
    participant_->set_listener(nullptr);
    participant_->delete_contained_entities();
    fdds::DomainParticipantFactory::get_instance()->delete_participant(participant_);
  }
}

fdds::Topic* FastParticipant::topic(const msg::TypeSupport& type, const DdsNames& names) {
  const std::string& name = names.topic;
  std::lock_guard lk(mu_);
  if (auto it = topics_.find(name); it != topics_.end()) {
    if (it->second->get_type_name() != names.type)
      throw std::runtime_error("topic '" + name + "' already exists with type " + it->second->get_type_name());
    return it->second;
  }
  fdds::TypeSupport ts(type.make_fast_type());
  ts.register_type(participant_, names.type);  // under its wire name; no-op if already registered
  fdds::Topic* t = participant_->create_topic(name, names.type, fdds::TOPIC_QOS_DEFAULT);
  if (!t) throw std::runtime_error("Fast DDS: cannot create topic '" + name + "'");
  topics_[name] = t;
  return t;
}

std::unique_ptr<WriterBackend> FastParticipant::create_writer(const msg::TypeSupport& type, const DdsNames& names,
                                                              const QosProfile& qos) {
  const std::string& topic_name = names.topic;
  fdds::Topic* t = topic(type, names);
  fdds::DataWriterQos wq = publisher_->get_default_datawriter_qos();
  apply_common(wq, qos);
  // A lost sample is asked for when the next heartbeat arrives, and repaired 1 ms after the
  // request (NetworkOptions::reliable_heartbeat_s; Fast DDS's defaults: 3 s and 5 ms).
  wq.reliable_writer_qos().times.heartbeatPeriod = to_fast_duration(options().network.reliable_heartbeat_s);
  wq.reliable_writer_qos().times.nackResponseDelay = eprosima::fastrtps::Duration_t(0, 1'000'000);
  auto w = std::make_unique<FastWriter>(*this, topic_name, detail::local_endpoint(options().name, true, qos));
  fdds::DataWriter* dw = publisher_->create_datawriter(t, wq, w.get(), fdds::StatusMask::all());
  if (!dw) throw std::runtime_error("Fast DDS: cannot create writer on '" + topic_name + "' with profile " + qos.name);
  w->attach(dw);
  return w;
}

std::unique_ptr<ReaderBackend> FastParticipant::create_reader(const msg::TypeSupport& type, const DdsNames& names,
                                                              const QosProfile& qos) {
  const std::string& topic_name = names.topic;
  fdds::Topic* t = topic(type, names);
  fdds::DataReaderQos rq = subscriber_->get_default_datareader_qos();
  apply_common(rq, qos);
  // Asks for what a heartbeat says it missed 1 ms after it (default 5 ms): NetworkOptions.
  rq.reliable_reader_qos().times.heartbeatResponseDelay = eprosima::fastrtps::Duration_t(0, 1'000'000);
  auto r = std::make_unique<FastReader>(*this, topic_name, detail::local_endpoint(options().name, false, qos));
  // data_available only with a data callback (set_data_callback): otherwise readers are
  // polled or waited on.
  fdds::StatusMask mask = fdds::StatusMask::all();
  mask >> fdds::StatusMask::data_available();
  fdds::DataReader* dr = subscriber_->create_datareader(t, rq, r.get(), mask);
  if (!dr) throw std::runtime_error("Fast DDS: cannot create reader on '" + topic_name + "' with profile " + qos.name);
  r->attach(dr);
  return r;
}

std::vector<DiscoveredEndpoint> FastParticipant::dds_endpoints() const { return discovery_->endpoints(); }

std::string FastParticipant::describe_remote(const fdds::InstanceHandle_t& h) const { return discovery_->describe(h); }

std::string FastParticipant::incompatible_remotes(const std::string& topic, bool remote_is_writer,
                                                  const std::string& policy) const {
  return discovery_->incompatible(topic, remote_is_writer, policy);
}

}  // namespace plexus::rt
