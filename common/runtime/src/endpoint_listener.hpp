// Internal: what the endpoint listeners of both back ends share. A vendor's callback reads
// its status struct and calls EndpointEvents, which turns it into a plexus event
// (events.hpp) the same way for Fast DDS and Cyclone DDS, and a reader's receive-thread
// delivery goes through DataCallback.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>

#include "plexus/runtime/events.hpp"
#include "plexus/runtime/qos.hpp"

namespace plexus::rt::detail {

/// What an endpoint's events need from the participant that owns the endpoint.
class EventOwner {
 public:
  /// Logs the event and calls the participant's handler (Participant::emit).
  virtual void emit_event(const Event& e) const = 0;
  /// Every discovered remote endpoint of the given kind on `topic`, with its value of `policy`.
  virtual std::string incompatible_remotes(const std::string& topic, bool remote_is_writer,
                                           const std::string& policy) const = 0;

 protected:
  ~EventOwner() = default;
};

/// "<participant> writer (<QoS profile>)": the local side of an endpoint's events.
std::string local_endpoint(const std::string& participant, bool writer, const QosProfile& qos);

/// One local endpoint's statuses as events, with the counts as the vendor reports them; also
/// keeps the matched count the endpoint reports (WriterBackend/ReaderBackend::matched_count).
class EndpointEvents {
 public:
  EndpointEvents(const EventOwner& owner, std::string topic, bool on_writer, std::string local);

  const std::string& topic() const { return topic_; }
  int matched_count() const { return matched_; }

  /// Publication or subscription matched: `change` > 0 a remote endpoint matched, else one
  /// went away. `remote`: that endpoint, when the vendor can still name it.
  void matched(int32_t total, int32_t current, int32_t change, const std::string& remote);
  /// Offered (writer) or requested (reader) deadline missed.
  void deadline_missed(int32_t total);
  /// Offered or requested incompatible QoS; `policy`: the vendor's last policy id, named
  /// (policy_names.hpp). The event names every remote endpoint on the topic and its value.
  void incompatible_qos(int32_t total, const std::string& policy);
  /// Writer: it failed to assert its liveliness within its lease.
  void liveliness_lost(int32_t total);
  /// Reader: a matched writer became alive or not alive (`remote`: that writer).
  void liveliness_changed(int32_t alive, int32_t not_alive, int32_t alive_change, int32_t not_alive_change,
                          const std::string& remote);
  /// Reader: samples lost.
  void sample_lost(int32_t total);

 private:
  Event base(EventKind k) const;
  void counted(EventKind k, int32_t total);  // an event that carries only the vendor's count

  const EventOwner& owner_;
  std::string topic_;
  bool on_writer_;
  std::string local_;
  std::atomic<int> matched_{0};
};

/// A reader's receive-thread delivery (ReaderBackend::set_data_callback): set once, before
/// the vendor's listener can call it; never two calls at once (the interface's promise).
class DataCallback {
 public:
  /// Throws std::logic_error naming the reader's `topic` when a callback is already set.
  void set(std::function<void()> fn, const std::string& topic);
  /// Calls the callback (nothing while none is set).
  void operator()();

 private:
  std::mutex mu_;
  std::function<void()> fn_;  // set once; outlives the vendor's reader (deleted in the backend's destructor)
};

}  // namespace plexus::rt::detail
