// Fast DDS 2.9 back end (internal).
#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "../endpoint_listener.hpp"
#include "plexus/runtime/participant.hpp"

namespace eprosima::fastdds::dds {
class DomainParticipant;
class Publisher;
class Subscriber;
class Topic;
}  // namespace eprosima::fastdds::dds
namespace eprosima::fastrtps::rtps {
struct InstanceHandle_t;
}

namespace plexus::rt {

class FastParticipant final : public Participant, public detail::EventOwner {
 public:
  explicit FastParticipant(const ParticipantOptions& options);
  ~FastParticipant() override;

  Vendor vendor() const override { return Vendor::fast; }

  // For the endpoint listeners.
  eprosima::fastdds::dds::Publisher* publisher() const { return publisher_; }
  eprosima::fastdds::dds::Subscriber* subscriber() const { return subscriber_; }
  void emit_event(const Event& e) const override { emit(e); }
  std::string describe_remote(const eprosima::fastrtps::rtps::InstanceHandle_t& h) const;
  std::string incompatible_remotes(const std::string& topic, bool remote_is_writer,
                                   const std::string& policy) const override;

 protected:
  std::unique_ptr<WriterBackend> create_writer(const msg::TypeSupport& type, const DdsNames& names,
                                               const QosProfile& qos) override;
  std::unique_ptr<ReaderBackend> create_reader(const msg::TypeSupport& type, const DdsNames& names,
                                               const QosProfile& qos) override;
  std::vector<DiscoveredEndpoint> dds_endpoints() const override;

 private:
  class Discovery;
  eprosima::fastdds::dds::Topic* topic(const msg::TypeSupport& type, const DdsNames& names);

  std::unique_ptr<Discovery> discovery_;
  eprosima::fastdds::dds::DomainParticipant* participant_ = nullptr;
  eprosima::fastdds::dds::Publisher* publisher_ = nullptr;
  eprosima::fastdds::dds::Subscriber* subscriber_ = nullptr;
  mutable std::mutex mu_;
  std::map<std::string, eprosima::fastdds::dds::Topic*> topics_;
};

}  // namespace plexus::rt
