// raw_fast_pingpong: the Fast DDS baseline of `plexus latency pingpong`, written against the
// plain Fast DDS 2.9 API (no plexus code) with the fastddsgen type of the same IDL
// (LatencyProbe) and the transport plexus uses: UDPv4 on 127.0.0.1 only, unicast discovery
// on the well-known ports, no data sharing, XCDR1; with --shm, Fast DDS's shared-memory
// transport beside UDPv4, as plexus's transport auto/shm (LatencyProbe is not a plain type,
// so plexus does not data-share it either). Same options, same measurement and the same
// JSON line as pingpong_node.
#include <fastdds/rtps/transport/UDPv4TransportDescriptor.h>
#include <fastdds/rtps/transport/shared_mem/SharedMemTransportDescriptor.h>
#include <fastrtps/utils/IPLocator.h>
#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/DataReaderListener.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/topic/Topic.hpp>

#include <atomic>
#include <csignal>
#include <thread>

#include "latency_probePubSubTypes.h"
#include "pingpong_common.hpp"

using namespace eprosima::fastdds::dds;
using eprosima::fastrtps::rtps::IPLocator;
using eprosima::fastrtps::rtps::Locator_t;
using plexus::latency::mono_ns;
using RC = eprosima::fastrtps::types::ReturnCode_t;

namespace {

std::atomic<bool> g_stop{false};
void on_signal(int) { g_stop = true; }

template <class Q>
void set_qos(Q& q, bool reliable, int depth) {
  q.reliability().kind = reliable ? RELIABLE_RELIABILITY_QOS : BEST_EFFORT_RELIABILITY_QOS;
  q.reliability().max_blocking_time = eprosima::fastrtps::Duration_t(0, 100'000'000);
  q.durability().kind = VOLATILE_DURABILITY_QOS;
  q.history().kind = KEEP_LAST_HISTORY_QOS;
  q.history().depth = depth;
  q.resource_limits().max_samples = depth;
  q.resource_limits().max_samples_per_instance = depth;
  q.data_sharing().off();
}

bool take_one(DataReader* r, plexus::msg::LatencyProbe& m) {
  SampleInfo info;
  while (r->take_next_sample(&m, &info) == RC::RETCODE_OK)
    if (info.valid_data) return true;
  return false;
}

// pong answers on Fast DDS's receive thread, from the reader listener, as plexus's pong
// does (Subscriber::on_sample): both measure the same delivery path.
struct Echo final : DataReaderListener {
  DataWriter* writer = nullptr;
  plexus::msg::LatencyProbe in;
  void on_data_available(DataReader* r) override {
    while (take_one(r, in)) writer->write(&in);
  }
};

// ping's pongs, stamped on Fast DDS's receive thread from the reader listener, as plexus's
// ping does (Subscriber::on_sample) and ddsperf's.
struct PongStamp final : DataReaderListener {
  plexus::latency::PongArrivals* pongs = nullptr;
  plexus::msg::LatencyProbe in;
  void on_data_available(DataReader* r) override {
    while (take_one(r, in)) pongs->arrived(in.header().data_time_ns());
  }
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"raw_fast_pingpong: plain Fast DDS ping-pong baseline"};
  app.set_version_flag("--version", std::string("raw_fast_pingpong") + " " + PLEXUS_VERSION);
  plexus::latency::PingPongOptions o;
  bool best_effort = false, shm = false;
  int depth = 16;
  plexus::latency::add_pingpong_options(app, o);
  app.add_flag("--best-effort", best_effort, "best-effort instead of reliable");
  app.add_option("--depth", depth, "keep_last depth")->check(CLI::Range(1, 100000));
  app.add_flag("--shm", shm, "shared-memory transport beside UDPv4 (same-host peers use it)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // the plexus style, without plexus code (a baseline)
    std::fprintf(stderr, "raw_fast_pingpong: error: %s (--help lists the options)\n", e.what());
    return 2;
  }
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  const bool ping = o.role == "ping";

  DomainParticipantQos pq;
  pq.name(ping ? "raw_fast_ping" : "raw_fast_pong");
  pq.transport().use_builtin_transports = false;
  if (shm)
    pq.transport().user_transports.push_back(std::make_shared<eprosima::fastdds::rtps::SharedMemTransportDescriptor>());
  auto udp = std::make_shared<eprosima::fastdds::rtps::UDPv4TransportDescriptor>();
  udp->interfaceWhiteList.push_back("127.0.0.1");
  pq.transport().user_transports.push_back(udp);
  pq.wire_protocol().builtin.metatrafficMulticastLocatorList.clear();
  pq.wire_protocol().builtin.metatrafficUnicastLocatorList.clear();
  pq.wire_protocol().builtin.metatrafficUnicastLocatorList.push_back(Locator_t());
  for (int pid = 0; pid < 32; ++pid) {
    Locator_t loc;
    IPLocator::setIPv4(loc, "127.0.0.1");
    loc.port = static_cast<uint32_t>(7400 + 250 * o.domain + 10 + 2 * pid);
    pq.wire_protocol().builtin.initialPeersList.push_back(loc);
  }
  DomainParticipant* dp = DomainParticipantFactory::get_instance()->create_participant(o.domain, pq);
  if (!dp) {
    std::fprintf(stderr, "raw_fast_pingpong: cannot create participant\n");
    return 1;
  }
  TypeSupport type(new plexus::msg::LatencyProbePubSubType());
  type.register_type(dp);
  Topic* tping = dp->create_topic("latency/ping", type.get_type_name(), TOPIC_QOS_DEFAULT);
  Topic* tpong = dp->create_topic("latency/pong", type.get_type_name(), TOPIC_QOS_DEFAULT);
  Publisher* pub = dp->create_publisher(PUBLISHER_QOS_DEFAULT);
  Subscriber* sub = dp->create_subscriber(SUBSCRIBER_QOS_DEFAULT);
  DataWriterQos wq = pub->get_default_datawriter_qos();
  set_qos(wq, !best_effort, depth);
  wq.representation().m_value = {XCDR_DATA_REPRESENTATION};
  DataReaderQos rq = sub->get_default_datareader_qos();
  set_qos(rq, !best_effort, depth);
  rq.type_consistency().representation.m_value = {XCDR_DATA_REPRESENTATION};
  DataWriter* w = pub->create_datawriter(ping ? tping : tpong, wq);
  Echo echo;
  echo.writer = w;
  echo.in.payload().reserve(plexus::latency::kMaxPayload);
  plexus::latency::PongArrivals pongs;
  PongStamp stamp;
  stamp.pongs = &pongs;
  stamp.in.payload().reserve(plexus::latency::kMaxPayload);
  DataReader* r = ping ? sub->create_datareader(tpong, rq, &stamp, StatusMask::data_available())
                       : sub->create_datareader(tping, rq, &echo, StatusMask::data_available());
  if (!w || !r) {
    std::fprintf(stderr, "raw_fast_pingpong: cannot create endpoints\n");
    return 1;
  }
  int rc = 0;
  plexus::msg::LatencyProbe out;
  if (!ping) {
    const int64_t end = o.duration > 0 ? mono_ns() + static_cast<int64_t>(o.duration * 1e9) : INT64_MAX;
    while (!g_stop && mono_ns() < end) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    r->set_listener(nullptr);  // before echo goes
  } else {
    PublicationMatchedStatus ps;
    SubscriptionMatchedStatus ss;
    const int64_t match_end = mono_ns() + static_cast<int64_t>(o.timeout * 1e9);
    for (;;) {
      w->get_publication_matched_status(ps);
      r->get_subscription_matched_status(ss);
      if ((ps.current_count > 0 && ss.current_count > 0) || g_stop) break;
      if (mono_ns() > match_end) {
        std::fprintf(stderr, "raw_fast_pingpong ping: no pong matched within %.0f s\n", o.timeout);
        return 1;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    out.payload().assign(static_cast<std::size_t>(o.size), 0x5a);
    rc = plexus::latency::run_ping(
        "raw Fast DDS", o,
        [&](int k) {
          if (g_stop) return false;
          out.header().data_time_ns(k);
          return w->write(&out);
        },
        pongs);
    r->set_listener(nullptr);  // before stamp goes
  }
  dp->delete_contained_entities();
  DomainParticipantFactory::get_instance()->delete_participant(dp);
  return rc;
}
