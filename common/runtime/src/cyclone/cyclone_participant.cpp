// Cyclone DDS 0.10 back end.
#include "cyclone_participant.hpp"

#include <dds/ddsi/ddsi_serdata.h>
#include <dds/ddsi/ddsi_sertype.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <mutex>
#include <stdexcept>

#include "../endpoint_listener.hpp"
#include "../policy_names.hpp"
#include "cdr_sertype.hpp"
#include "cyclone_security.hpp"
#include "domain_ports.hpp"
#include "plexus/base/clock.hpp"

namespace plexus::rt {
namespace {

dds_duration_t to_cyclone_duration(double s) { return s <= 0 ? DDS_INFINITY : static_cast<dds_duration_t>(s * 1e9); }

std::string policy_name(dds_qos_policy_id_t id) {
  if (id == DDS_DATA_REPRESENTATION_QOS_POLICY_ID) return "DATA_REPRESENTATION";
  if (id == DDS_TYPE_CONSISTENCY_ENFORCEMENT_QOS_POLICY_ID) return "TYPE_CONSISTENCY_ENFORCEMENT";
  return detail::standard_policy_name(static_cast<int>(id));
}

std::string cyc_error(const char* what, dds_return_t rc) {
  return std::string("Cyclone DDS: ") + what + ": " + dds_strretcode(rc);
}

dds_qos_t* make_qos(const QosProfile& p) {
  dds_qos_t* q = dds_create_qos();
  dds_qset_reliability(
      q, p.reliability == QosProfile::Reliability::reliable ? DDS_RELIABILITY_RELIABLE : DDS_RELIABILITY_BEST_EFFORT,
      p.max_blocking_time_s > 0 ? to_cyclone_duration(p.max_blocking_time_s) : DDS_INFINITY);
  dds_qset_durability(q, p.durability == QosProfile::Durability::transient_local ? DDS_DURABILITY_TRANSIENT_LOCAL
                                                                                 : DDS_DURABILITY_VOLATILE);
  dds_qset_history(q, p.history == QosProfile::History::keep_all ? DDS_HISTORY_KEEP_ALL : DDS_HISTORY_KEEP_LAST,
                   p.depth);
  if (p.durability == QosProfile::Durability::transient_local)
    dds_qset_durability_service(
        q, 0, p.history == QosProfile::History::keep_all ? DDS_HISTORY_KEEP_ALL : DDS_HISTORY_KEEP_LAST, p.depth,
        DDS_LENGTH_UNLIMITED, DDS_LENGTH_UNLIMITED, DDS_LENGTH_UNLIMITED);
  dds_qset_deadline(q, to_cyclone_duration(p.deadline_s));
  dds_liveliness_kind_t lk = DDS_LIVELINESS_AUTOMATIC;
  if (p.liveliness == QosProfile::Liveliness::manual_by_participant) lk = DDS_LIVELINESS_MANUAL_BY_PARTICIPANT;
  if (p.liveliness == QosProfile::Liveliness::manual_by_topic) lk = DDS_LIVELINESS_MANUAL_BY_TOPIC;
  dds_qset_liveliness(q, lk, to_cyclone_duration(p.liveliness_lease_s));
  dds_qset_lifespan(q, to_cyclone_duration(p.lifespan_s));
  dds_qset_latency_budget(q, p.latency_budget_s > 0 ? to_cyclone_duration(p.latency_budget_s) : 0);
  const dds_data_representation_id_t xcdr1 = DDS_DATA_REPRESENTATION_XCDR1;
  dds_qset_data_representation(q, 1, &xcdr1);
  return q;
}

std::string guid_text(const dds_guid_t& g) {
  static const char* hex = "0123456789abcdef";
  std::string s;
  for (int i = 0; i < 16; ++i) {
    if (i == 12) s += '.';
    s += hex[g.v[i] >> 4];
    s += hex[g.v[i] & 15];
  }
  return s;
}

std::string policy_value(const dds_qos_t* q, const std::string& policy) {
  if (policy == "RELIABILITY") {
    dds_reliability_kind_t k;
    if (dds_qget_reliability(q, &k, nullptr))
      return std::string("RELIABILITY=") + (k == DDS_RELIABILITY_RELIABLE ? "reliable" : "best_effort");
  } else if (policy == "DURABILITY") {
    dds_durability_kind_t k;
    if (dds_qget_durability(q, &k)) return "DURABILITY=" + std::to_string(static_cast<int>(k));
  } else if (policy == "DEADLINE") {
    dds_duration_t d;
    if (dds_qget_deadline(q, &d))
      return d == DDS_INFINITY ? "DEADLINE=infinite" : "DEADLINE=" + std::to_string(d * 1e-9) + "s";
  }
  return "";
}

class CycloneWriter final : public WriterBackend {
 public:
  CycloneWriter(const CycloneParticipant& owner, std::string topic, std::string local, const struct ddsi_sertype* st)
      : owner_(owner), events_(owner, std::move(topic), /*on_writer=*/true, std::move(local)), sertype_(st) {}
  ~CycloneWriter() override {
    if (writer_ > 0) dds_delete(writer_);
  }
  void attach(dds_entity_t w) { writer_ = w; }

  bool write(const void* sample) override {
    struct ddsi_serdata* sd = detail::serdata_from_sample(sertype_, sample);
    if (!sd) return false;
    return dds_writecdr(writer_, sd) >= 0;  // takes ownership of sd
  }
  void assert_liveliness() override { dds_assert_liveliness(writer_); }
  int matched_count() const override { return events_.matched_count(); }
  bool wait_for_acks(int64_t timeout_ns) override { return dds_wait_for_acks(writer_, timeout_ns) == DDS_RETCODE_OK; }

  /// The writer's listener: every status plexus reports as an event.
  static dds_listener_t* listener(CycloneWriter* self) {
    dds_listener_t* l = dds_create_listener(self);
    dds_lset_publication_matched(l, &CycloneWriter::on_matched);
    dds_lset_offered_deadline_missed(l, &CycloneWriter::on_deadline);
    dds_lset_offered_incompatible_qos(l, &CycloneWriter::on_incompatible);
    dds_lset_liveliness_lost(l, &CycloneWriter::on_liveliness_lost);
    return l;
  }
  static void on_matched(dds_entity_t w, const dds_publication_matched_status_t s, void* arg) {
    auto* self = static_cast<CycloneWriter*>(arg);
    const bool added = s.current_count_change > 0;
    self->events_.matched(static_cast<int32_t>(s.total_count), static_cast<int32_t>(s.current_count),
                          s.current_count_change,
                          added ? self->owner_.describe_matched(w, s.last_subscription_handle, false) : std::string());
  }
  static void on_deadline(dds_entity_t, const dds_offered_deadline_missed_status_t s, void* arg) {
    static_cast<CycloneWriter*>(arg)->events_.deadline_missed(static_cast<int32_t>(s.total_count));
  }
  static void on_incompatible(dds_entity_t, const dds_offered_incompatible_qos_status_t s, void* arg) {
    static_cast<CycloneWriter*>(arg)->events_.incompatible_qos(
        static_cast<int32_t>(s.total_count), policy_name(static_cast<dds_qos_policy_id_t>(s.last_policy_id)));
  }
  static void on_liveliness_lost(dds_entity_t, const dds_liveliness_lost_status_t s, void* arg) {
    static_cast<CycloneWriter*>(arg)->events_.liveliness_lost(static_cast<int32_t>(s.total_count));
  }

 private:
  const CycloneParticipant& owner_;
  detail::EndpointEvents events_;
  const struct ddsi_sertype* sertype_;  // owned by the topic, which outlives the writer
  dds_entity_t writer_ = 0;
};

class CycloneReader final : public ReaderBackend {
 public:
  CycloneReader(const CycloneParticipant& owner, std::string topic, std::string local)
      : owner_(owner), events_(owner, std::move(topic), /*on_writer=*/false, std::move(local)) {}
  ~CycloneReader() override {
    if (waitset_ > 0) dds_delete(waitset_);
    if (reader_ > 0) dds_delete(reader_);
  }
  void attach(dds_entity_t r) {
    reader_ = r;
    waitset_ = dds_create_waitset(owner_.handle());
    readcond_ = dds_create_readcondition(reader_, DDS_ANY_STATE);
    dds_waitset_attach(waitset_, readcond_, 0);
  }

  bool take(void* sample, SampleMeta* meta) override { return take_into(sample, nullptr, meta); }
  bool take_raw(void* sample, std::vector<unsigned char>& cdr, SampleMeta* meta) override {
    return take_into(sample, &cdr, meta);
  }
  // The serdata taken is the CDR as received (cdr_sertype.cpp): `cdr` gets a copy of it.
  bool take_into(void* sample, std::vector<unsigned char>* cdr, SampleMeta* meta) {
    for (;;) {
      struct ddsi_serdata* sd = nullptr;
      dds_sample_info_t info;
      if (dds_takecdr(reader_, &sd, 1, &info, DDS_ANY_STATE) <= 0) return false;
      const bool ok = info.valid_data && detail::serdata_to_sample(sd, sample);
      if (ok && cdr) {
        cdr->resize(ddsi_serdata_size(sd));
        ddsi_serdata_to_ser(sd, 0, cdr->size(), cdr->data());
      }
      ddsi_serdata_unref(sd);
      if (!info.valid_data) continue;  // dispose / unregister notifications
      if (!ok) {
        ++malformed_;
        continue;
      }
      if (meta) {
        meta->source_timestamp_ns = info.source_timestamp;
        meta->receive_time_ns = wall_time_ns();
      }
      return true;
    }
  }
  bool wait(int64_t timeout_ns) override {
    return dds_waitset_wait(waitset_, nullptr, 0, static_cast<dds_duration_t>(timeout_ns)) > 0;
  }
  int matched_count() const override { return events_.matched_count(); }
  uint64_t malformed_count() const override { return malformed_; }
  void set_data_callback(std::function<void()> fn) override {
    data_cb_.set(std::move(fn), events_.topic());  // before the listener can call it
    // dds_set_listener replaces the whole listener: the status callbacks again, plus data.
    dds_listener_t* l = listener(this, true);
    const dds_return_t rc = dds_set_listener(reader_, l);
    dds_delete_listener(l);
    if (rc < 0)
      throw std::runtime_error(cyc_error(("cannot set the data listener on '" + events_.topic() + "'").c_str(), rc));
    on_data_available(reader_, this);  // samples that arrived before the listener
  }

  /// The reader's listener: every status plexus reports as an event, and with `data` the
  /// receive-thread delivery (set_data_callback).
  static dds_listener_t* listener(CycloneReader* self, bool data) {
    dds_listener_t* l = dds_create_listener(self);
    dds_lset_subscription_matched(l, &CycloneReader::on_matched);
    dds_lset_requested_deadline_missed(l, &CycloneReader::on_deadline);
    dds_lset_requested_incompatible_qos(l, &CycloneReader::on_incompatible);
    dds_lset_liveliness_changed(l, &CycloneReader::on_liveliness);
    dds_lset_sample_lost(l, &CycloneReader::on_sample_lost);
    if (data) dds_lset_data_available(l, &CycloneReader::on_data_available);
    return l;
  }
  // Cyclone calls it on the thread that delivered the data: with the default
  // Internal/SynchronousDeliveryLatencyBound, the receive thread itself, as ddsperf's pong.
  static void on_data_available(dds_entity_t, void* arg) { static_cast<CycloneReader*>(arg)->data_cb_(); }

  static void on_matched(dds_entity_t r, const dds_subscription_matched_status_t s, void* arg) {
    auto* self = static_cast<CycloneReader*>(arg);
    const bool added = s.current_count_change > 0;
    self->events_.matched(static_cast<int32_t>(s.total_count), static_cast<int32_t>(s.current_count),
                          s.current_count_change,
                          added ? self->owner_.describe_matched(r, s.last_publication_handle, true) : std::string());
  }
  static void on_deadline(dds_entity_t, const dds_requested_deadline_missed_status_t s, void* arg) {
    static_cast<CycloneReader*>(arg)->events_.deadline_missed(static_cast<int32_t>(s.total_count));
  }
  static void on_incompatible(dds_entity_t, const dds_requested_incompatible_qos_status_t s, void* arg) {
    static_cast<CycloneReader*>(arg)->events_.incompatible_qos(
        static_cast<int32_t>(s.total_count), policy_name(static_cast<dds_qos_policy_id_t>(s.last_policy_id)));
  }
  static void on_liveliness(dds_entity_t r, const dds_liveliness_changed_status_t s, void* arg) {
    auto* self = static_cast<CycloneReader*>(arg);
    self->events_.liveliness_changed(static_cast<int32_t>(s.alive_count), static_cast<int32_t>(s.not_alive_count),
                                     s.alive_count_change, s.not_alive_count_change,
                                     self->owner_.describe_matched(r, s.last_publication_handle, true));
  }
  static void on_sample_lost(dds_entity_t, const dds_sample_lost_status_t s, void* arg) {
    static_cast<CycloneReader*>(arg)->events_.sample_lost(static_cast<int32_t>(s.total_count));
  }

 private:
  const CycloneParticipant& owner_;
  detail::EndpointEvents events_;
  dds_entity_t reader_ = 0;
  dds_entity_t waitset_ = 0;
  dds_entity_t readcond_ = 0;
  std::atomic<uint64_t> malformed_{0};
  detail::DataCallback data_cb_;  // outlives the reader entity (deleted in ~CycloneReader)
};

// The domains this process created (dds_create_domain), with the participants on each: one
// configuration per domain and process, made by the first participant and deleted with the
// last. An explicitly created domain would otherwise outlive main(), and its receive threads
// run on while exit handlers have already cleaned up OpenSSL: with DDS Security on, a packet
// decrypted at that moment crashes the process (SIGSEGV in EVP_CipherInit_ex, about one exit
// in seven under load).
struct DomainUse {
  dds_entity_t handle = 0;  // 0: created by someone else in this process, not ours to delete
  int participants = 0;
};
std::mutex g_domains_mu;
std::map<dds_domainid_t, DomainUse>& domains() {
  static auto* d = new std::map<dds_domainid_t, DomainUse>;  // never destroyed: used from destructors
  return *d;
}

void acquire_domain(dds_domainid_t domain, const std::string& config) {
  std::lock_guard lk(g_domains_mu);
  auto& use = domains()[domain];
  if (use.participants++ > 0) return;
  const dds_entity_t d = detail::create_domain_off_foreign_ports(domain, config);
  if (d < 0 && d != DDS_RETCODE_PRECONDITION_NOT_MET) {
    domains().erase(domain);
    throw std::runtime_error(cyc_error("cannot create domain", d));
  }
  use.handle = d > 0 ? d : 0;
}

void release_domain(dds_domainid_t domain) {
  std::lock_guard lk(g_domains_mu);
  auto it = domains().find(domain);
  if (it == domains().end() || --it->second.participants > 0) return;
  if (it->second.handle > 0) dds_delete(it->second.handle);
  domains().erase(it);
}

}  // namespace

std::string CycloneParticipant::config_xml(const NetworkOptions& net) {
  std::string peers;
  for (const auto& p : net.peers) peers += "<Peer address=\"" + p + "\"/>";
  // Reliable repair as on Fast DDS (NetworkOptions::reliable_heartbeat_s): heartbeats every
  // period while samples are unacknowledged, a request for repair 1 ms after one.
  const std::string hb = std::to_string(std::max<long long>(1, std::llround(net.reliable_heartbeat_s * 1e3))) + " ms";
  return "<CycloneDDS><Domain Id=\"any\">"
         "<General><Interfaces><NetworkInterface address=\"" +
         net.interface_address +
         "\"/></Interfaces>"
         "<AllowMulticast>false</AllowMulticast></General>"
         "<Discovery><ParticipantIndex>auto</ParticipantIndex>"
         "<MaxAutoParticipantIndex>" +
         std::to_string(net.max_participants_per_host - 1) +
         "</MaxAutoParticipantIndex>"
         "<Peers>" +
         peers +
         "</Peers></Discovery>"
         "<Internal><HeartbeatInterval min=\"" +
         hb + "\" minsched=\"" + hb + "\">" + hb +
         "</HeartbeatInterval>"
         "<NackDelay>1 ms</NackDelay></Internal>"
         // Receive buffers of 128 KiB, not 1 MiB (docs/runtime.md, "Memory: Cyclone DDS's receive buffers"): each
         // receive thread fills a buffer front to back and allocates the next when it is full, so the process's
         // resident memory climbs by the pages of its buffers until two of them have been written once, 1.5-2.5 MB over
         // 10-20 minutes at the main job's rates. 64 KiB chunks still hold any UDP datagram (Cyclone reads at most 64
         // KiB into one).
         "<Sizing><ReceiveBufferChunkSize>64 KiB</ReceiveBufferChunkSize>"
         "<ReceiveBufferSize>128 KiB</ReceiveBufferSize></Sizing>"
         "</Domain></CycloneDDS>";
}

// Shared memory (iceoryx) stays off: Cyclone DDS 0.10 gives a writer an iceoryx publisher
// when its type can be serialised into a chunk (plexus's sertype can) and its QoS allows it,
// but only dds_write / dds_write_loan put a sample into a chunk. plexus writes serdata with
// dds_writecdr, which has no chunk: the sample then goes to the network path, which leaves
// out every reader reached over iceoryx (its SHM locator), and to no iceoryx subscriber, so
// a Cyclone DDS reader of the same host would silently get nothing (dds_write.c,
// dds_writecdr_impl_common / deliver_data_any; ddsi_wraddrset.c). docs/runtime.md, Transports.
static void warn_no_cyclone_shm(Transport t) {
  if (t != Transport::shm) return;
  static std::once_flag once;
  std::call_once(once, [] {
    std::fprintf(stderr,
                 "plexus: transport shm: Cyclone DDS stays on UDP (iceoryx cannot carry samples written with "
                 "dds_writecdr in Cyclone DDS 0.10; docs/runtime.md, Transports)\n");
  });
}

CycloneParticipant::CycloneParticipant(const ParticipantOptions& o) : Participant(o) {
  warn_no_cyclone_shm(o.network.transport);
  const auto domain = static_cast<dds_domainid_t>(o.domain_id);
  acquire_domain(domain, config_xml(o.network));
  struct Release {  // the domain goes again if the participant cannot be created
    dds_domainid_t domain;
    bool armed = true;
    ~Release() {
      if (armed) release_domain(domain);
    }
  } release{domain};
  dds_qos_t* pq = dds_create_qos();
  dds_qset_entity_name(pq, o.name.c_str());
  detail::apply_cyclone_security(pq, o.security);
  participant_ = dds_create_participant(domain, pq, nullptr);
  dds_delete_qos(pq);
  if (participant_ < 0)
    throw std::runtime_error(
        cyc_error(o.security.enabled
                      ? ("cannot create participant with DDS Security (identity '" + o.security.identity + "')").c_str()
                      : "cannot create participant",
                  participant_));
  builtin_participants_ = dds_create_reader(participant_, DDS_BUILTIN_TOPIC_DCPSPARTICIPANT, nullptr, nullptr);
  builtin_publications_ = dds_create_reader(participant_, DDS_BUILTIN_TOPIC_DCPSPUBLICATION, nullptr, nullptr);
  builtin_subscriptions_ = dds_create_reader(participant_, DDS_BUILTIN_TOPIC_DCPSSUBSCRIPTION, nullptr, nullptr);
  release.armed = false;
}

CycloneParticipant::~CycloneParticipant() {
  if (participant_ > 0) dds_delete(participant_);
  release_domain(static_cast<dds_domainid_t>(options().domain_id));
}

CycloneParticipant::Topic CycloneParticipant::topic(const msg::TypeSupport& type, const DdsNames& names) {
  const std::string& name = names.topic;
  std::lock_guard lk(mu_);
  if (auto it = topics_.find(name); it != topics_.end()) {
    if (names.type != it->second.sertype->type_name)
      throw std::runtime_error("topic '" + name + "' already exists with type " + it->second.sertype->type_name);
    return it->second;
  }
  struct ddsi_sertype* st = detail::make_cdr_sertype(type, names.type);
  // Consumes st; on return it points at the sertype Cyclone actually uses for the topic.
  const dds_entity_t t = dds_create_topic_sertype(participant_, name.c_str(), &st, nullptr, nullptr, nullptr);
  if (t < 0) throw std::runtime_error(cyc_error(("cannot create topic '" + name + "'").c_str(), t));
  return topics_[name] = Topic{t, st};
}

std::unique_ptr<WriterBackend> CycloneParticipant::create_writer(const msg::TypeSupport& type, const DdsNames& names,
                                                                 const QosProfile& qos) {
  const std::string& topic_name = names.topic;
  const Topic t = topic(type, names);
  auto w =
      std::make_unique<CycloneWriter>(*this, topic_name, detail::local_endpoint(options().name, true, qos), t.sertype);
  dds_listener_t* l = CycloneWriter::listener(w.get());
  dds_qos_t* q = make_qos(qos);
  const dds_entity_t dw = dds_create_writer(participant_, t.entity, q, l);
  dds_delete_qos(q);
  dds_delete_listener(l);
  if (dw < 0) throw std::runtime_error(cyc_error(("cannot create writer on '" + topic_name + "'").c_str(), dw));
  w->attach(dw);
  return w;
}

std::unique_ptr<ReaderBackend> CycloneParticipant::create_reader(const msg::TypeSupport& type, const DdsNames& names,
                                                                 const QosProfile& qos) {
  const std::string& topic_name = names.topic;
  const Topic t = topic(type, names);
  auto r = std::make_unique<CycloneReader>(*this, topic_name, detail::local_endpoint(options().name, false, qos));
  dds_listener_t* l = CycloneReader::listener(r.get(), false);
  dds_qos_t* q = make_qos(qos);
  const dds_entity_t dr = dds_create_reader(participant_, t.entity, q, l);
  dds_delete_qos(q);
  dds_delete_listener(l);
  if (dr < 0) throw std::runtime_error(cyc_error(("cannot create reader on '" + topic_name + "'").c_str(), dr));
  r->attach(dr);
  return r;
}

std::string CycloneParticipant::participant_name(const dds_guid_t& key) const {
  void* samples[64] = {};
  dds_sample_info_t infos[64];
  const int n = dds_read(builtin_participants_, samples, infos, 64, 64);
  std::string name;
  for (int i = 0; i < n; ++i) {
    const auto* p = static_cast<const dds_builtintopic_participant_t*>(samples[i]);
    if (!infos[i].valid_data || std::memcmp(p->key.v, key.v, 16) != 0) continue;
    char* en = nullptr;
    if (p->qos && dds_qget_entity_name(p->qos, &en) && en) {
      name = en;
      dds_free(en);
    }
  }
  if (n > 0) dds_return_loan(builtin_participants_, samples, n);
  return name.empty() ? guid_text(key) : name;
}

std::string CycloneParticipant::describe_matched(dds_entity_t local, dds_instance_handle_t remote,
                                                 bool remote_is_writer) const {
  dds_builtintopic_endpoint_t* ep = remote_is_writer ? dds_get_matched_publication_data(local, remote)
                                                     : dds_get_matched_subscription_data(local, remote);
  if (!ep) return "";
  std::string s = std::string(remote_is_writer ? "writer" : "reader") + " of participant '" +
                  participant_name(ep->participant_key) + "'";
  dds_builtintopic_free_endpoint(ep);
  return s;
}

std::string CycloneParticipant::incompatible_remotes(const std::string& topic_name, bool remote_is_writer,
                                                     const std::string& policy) const {
  const dds_entity_t rd = remote_is_writer ? builtin_publications_ : builtin_subscriptions_;
  void* samples[64] = {};
  dds_sample_info_t infos[64];
  const int n = dds_read(rd, samples, infos, 64, 64);
  std::string out;
  for (int i = 0; i < n; ++i) {
    const auto* ep = static_cast<const dds_builtintopic_endpoint_t*>(samples[i]);
    if (!infos[i].valid_data || !ep->topic_name || topic_name != ep->topic_name) continue;
    out += (out.empty() ? "" : "; ") + std::string(remote_is_writer ? "writer" : "reader") + " of participant '" +
           participant_name(ep->participant_key) + "' " + (ep->qos ? policy_value(ep->qos, policy) : "");
  }
  if (n > 0) dds_return_loan(rd, samples, n);
  return out;
}

}  // namespace plexus::rt
