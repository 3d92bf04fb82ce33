#include "endpoint_listener.hpp"

#include <stdexcept>

namespace plexus::rt::detail {

std::string local_endpoint(const std::string& participant, bool writer, const QosProfile& qos) {
  return participant + (writer ? " writer (" : " reader (") + describe(qos) + ")";
}

EndpointEvents::EndpointEvents(const EventOwner& owner, std::string topic, bool on_writer, std::string local)
    : owner_(owner), topic_(std::move(topic)), on_writer_(on_writer), local_(std::move(local)) {}

Event EndpointEvents::base(EventKind k) const {
  Event e;
  e.kind = k;
  e.on_writer = on_writer_;
  e.topic = topic_;
  e.local = local_;
  return e;
}

void EndpointEvents::counted(EventKind k, int32_t total) {
  Event e = base(k);
  e.total_count = total;
  owner_.emit_event(e);
}

void EndpointEvents::matched(int32_t total, int32_t current, int32_t change, const std::string& remote) {
  matched_ = current;
  Event e = base(change > 0 ? EventKind::matched : EventKind::unmatched);
  e.total_count = total;
  e.current_count = current;
  e.remote = remote;
  owner_.emit_event(e);
}

void EndpointEvents::deadline_missed(int32_t total) { counted(EventKind::deadline_missed, total); }

void EndpointEvents::incompatible_qos(int32_t total, const std::string& policy) {
  Event e = base(EventKind::incompatible_qos);
  e.total_count = total;
  e.policy = policy;
  e.remote = owner_.incompatible_remotes(topic_, /*remote_is_writer=*/!on_writer_, policy);
  owner_.emit_event(e);
}

void EndpointEvents::liveliness_lost(int32_t total) { counted(EventKind::liveliness_lost, total); }

void EndpointEvents::liveliness_changed(int32_t alive, int32_t not_alive, int32_t alive_change,
                                        int32_t not_alive_change, const std::string& remote) {
  Event e = base(EventKind::liveliness_changed);
  e.alive = alive_change > 0;
  // Alive count down without a not-alive count up: the writer was removed (its lease did
  // not expire), as every writer is when a run ends.
  e.writer_left = alive_change < 0 && not_alive_change <= 0;
  e.current_count = alive;
  e.total_count = alive + not_alive;
  e.remote = remote;
  owner_.emit_event(e);
}

void EndpointEvents::sample_lost(int32_t total) { counted(EventKind::sample_lost, total); }

void DataCallback::set(std::function<void()> fn, const std::string& topic) {
  if (fn_) throw std::logic_error("reader on '" + topic + "': data callback set twice");
  fn_ = std::move(fn);
}

void DataCallback::operator()() {
  std::lock_guard lk(mu_);
  if (fn_) fn_();
}

}  // namespace plexus::rt::detail
