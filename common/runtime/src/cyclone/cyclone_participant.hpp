// Cyclone DDS 0.10 back end (internal).
#pragma once

#include <dds/dds.h>

#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "../endpoint_listener.hpp"
#include "plexus/runtime/participant.hpp"

namespace plexus::rt {

class CycloneParticipant final : public Participant, public detail::EventOwner {
 public:
  explicit CycloneParticipant(const ParticipantOptions& options);
  ~CycloneParticipant() override;

  Vendor vendor() const override { return Vendor::cyclone; }

  // For the endpoint listeners.
  dds_entity_t handle() const { return participant_; }
  void emit_event(const Event& e) const override { emit(e); }
  /// "writer of participant 'name'" for a matched remote endpoint.
  std::string describe_matched(dds_entity_t local, dds_instance_handle_t remote, bool remote_is_writer) const;
  /// Every discovered remote endpoint of the given kind on `topic`, with its value of `policy`.
  std::string incompatible_remotes(const std::string& topic, bool remote_is_writer,
                                   const std::string& policy) const override;

  /// The configuration XML plexus gives Cyclone for these network options (for tools and tests).
  static std::string config_xml(const NetworkOptions& net);

 protected:
  std::unique_ptr<WriterBackend> create_writer(const msg::TypeSupport& type, const DdsNames& names,
                                               const QosProfile& qos) override;
  std::unique_ptr<ReaderBackend> create_reader(const msg::TypeSupport& type, const DdsNames& names,
                                               const QosProfile& qos) override;
  std::vector<DiscoveredEndpoint> dds_endpoints() const override;

 private:
  struct Topic {
    dds_entity_t entity;
    const struct ddsi_sertype* sertype;
  };
  Topic topic(const msg::TypeSupport& type, const DdsNames& names);
  std::string participant_name(const dds_guid_t& key) const;

  dds_entity_t participant_ = 0;
  dds_entity_t builtin_participants_ = 0;
  dds_entity_t builtin_publications_ = 0;
  dds_entity_t builtin_subscriptions_ = 0;
  std::mutex mu_;
  std::map<std::string, Topic> topics_;
};

}  // namespace plexus::rt
