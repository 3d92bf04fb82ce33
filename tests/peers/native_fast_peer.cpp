// native_fast_peer: a plain Fast DDS 2.9 program using the fastddsgen types generated from
// plexus's IDL (no plexus code), that exchanges Pose2D and JointState samples with plexus
// processes. Values follow simple_values.hpp.
//
//   native_fast_peer pub|sub DOMAIN COUNT
//
// Configured like plexus: UDPv4 on 127.0.0.1 only, unicast discovery, no shared memory.
#include <fastdds/rtps/transport/UDPv4TransportDescriptor.h>
#include <fastrtps/utils/IPLocator.h>
#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/topic/Topic.hpp>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <thread>

#include "jointPubSubTypes.h"
#include "posePubSubTypes.h"
#include "simple_values.hpp"

using namespace eprosima::fastdds::dds;
using eprosima::fastrtps::rtps::IPLocator;
using eprosima::fastrtps::rtps::Locator_t;

int main(int argc, char** argv) {
  if (argc != 4 || (std::strcmp(argv[1], "pub") != 0 && std::strcmp(argv[1], "sub") != 0)) {
    std::fprintf(stderr, "usage: native_fast_peer pub|sub DOMAIN COUNT\n");
    return 2;
  }
  const bool pub = std::strcmp(argv[1], "pub") == 0;
  const int domain = std::atoi(argv[2]);
  const int count = std::atoi(argv[3]);

  DomainParticipantQos pq;
  pq.name(pub ? "native_fast_peer pub" : "native_fast_peer sub");
  pq.transport().use_builtin_transports = false;
  auto udp = std::make_shared<eprosima::fastdds::rtps::UDPv4TransportDescriptor>();
  udp->interfaceWhiteList.push_back("127.0.0.1");
  pq.transport().user_transports.push_back(udp);
  pq.wire_protocol().builtin.metatrafficUnicastLocatorList.push_back(Locator_t());
  for (int pid = 0; pid < 32; ++pid) {
    Locator_t loc;
    IPLocator::setIPv4(loc, "127.0.0.1");
    loc.port = 7400 + 250 * domain + 10 + 2 * pid;
    pq.wire_protocol().builtin.initialPeersList.push_back(loc);
  }
  DomainParticipant* dp = DomainParticipantFactory::get_instance()->create_participant(domain, pq);
  if (!dp) return 1;
  TypeSupport pose_type(new plexus::msg::Pose2DPubSubType());
  TypeSupport joint_type(new plexus::msg::JointStatePubSubType());
  pose_type.register_type(dp);
  joint_type.register_type(dp);
  Topic* tpose = dp->create_topic("native/Pose2D", pose_type.get_type_name(), TOPIC_QOS_DEFAULT);
  Topic* tjoint = dp->create_topic("native/JointState", joint_type.get_type_name(), TOPIC_QOS_DEFAULT);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(40);
  int rc = 0;

  if (pub) {
    Publisher* p = dp->create_publisher(PUBLISHER_QOS_DEFAULT);
    DataWriterQos wq = DATAWRITER_QOS_DEFAULT;
    wq.reliability().kind = RELIABLE_RELIABILITY_QOS;
    wq.history().kind = KEEP_LAST_HISTORY_QOS;
    wq.history().depth = count;
    wq.durability().kind = TRANSIENT_LOCAL_DURABILITY_QOS;  // as plexus_test_peer
    wq.data_sharing().off();
    DataWriter* wpose = p->create_datawriter(tpose, wq);
    DataWriter* wjoint = p->create_datawriter(tjoint, wq);
    PublicationMatchedStatus s1, s2;
    do {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
      wpose->get_publication_matched_status(s1);
      wjoint->get_publication_matched_status(s2);
    } while ((s1.current_count == 0 || s2.current_count == 0) && std::chrono::steady_clock::now() < deadline);
    if (s1.current_count == 0 || s2.current_count == 0) {
      std::fprintf(stderr, "native_fast_peer pub: no reader matched\n");
      return 1;
    }
    for (int k = 1; k <= count; ++k) {
      plexus::msg::Pose2D m;
      plexus::msg::JointState j;
      plexus::test::fill_simple(m, static_cast<uint64_t>(k));
      plexus::test::fill_simple(j, static_cast<uint64_t>(k));
      if (!wpose->write(&m) || !wjoint->write(&j)) rc = 1;
    }
    do {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      wpose->get_publication_matched_status(s1);
      wjoint->get_publication_matched_status(s2);
    } while ((s1.current_count > 0 || s2.current_count > 0) && std::chrono::steady_clock::now() < deadline);
    std::printf("native_fast_peer pub: wrote %d Pose2D and JointState samples\n", count);
  } else {
    Subscriber* s = dp->create_subscriber(SUBSCRIBER_QOS_DEFAULT);
    DataReaderQos rq = DATAREADER_QOS_DEFAULT;
    rq.reliability().kind = RELIABLE_RELIABILITY_QOS;
    rq.history().kind = KEEP_LAST_HISTORY_QOS;
    rq.history().depth = count;
    rq.durability().kind = TRANSIENT_LOCAL_DURABILITY_QOS;
    rq.data_sharing().off();
    DataReader* rpose = s->create_datareader(tpose, rq);
    DataReader* rjoint = s->create_datareader(tjoint, rq);
    int got_pose = 0, got_joint = 0, bad = 0;
    while ((got_pose < count || got_joint < count) && std::chrono::steady_clock::now() < deadline) {
      plexus::msg::Pose2D m;
      plexus::msg::JointState j;
      SampleInfo info;
      while (rpose->take_next_sample(&m, &info) == ReturnCode_t::RETCODE_OK)
        if (info.valid_data) plexus::test::check_simple(m) ? ++got_pose : ++bad;
      while (rjoint->take_next_sample(&j, &info) == ReturnCode_t::RETCODE_OK)
        if (info.valid_data) plexus::test::check_simple(j) ? ++got_joint : ++bad;
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    std::printf("native_fast_peer sub: Pose2D %d/%d, JointState %d/%d, wrong values %d\n", got_pose, count, got_joint,
                count, bad);
    rc = (got_pose == count && got_joint == count && bad == 0) ? 0 : 1;
  }
  dp->delete_contained_entities();
  DomainParticipantFactory::get_instance()->delete_participant(dp);
  return rc;
}
