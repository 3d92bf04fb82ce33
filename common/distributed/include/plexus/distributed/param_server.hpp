// The service side of `plexus param` (docs/parameters.md): a process's tunable parameters
// (Component::add_tunable) read and changed over DDS while it runs.
//
//  - Requests arrive on `param/request` (ParamRequest, idl/plexus/msg/param.idl), each naming
//    its target service; a service answers its own on `param/reply`, one ParamReply per
//    parameter for a list.
//  - They are served on the loop's thread, between two steps (serve(k) before step k runs):
//    a change is validated by the component's own validator (scenario::try_set), applied
//    before step k, and acknowledged with k; a refused one gets the reason, and the running
//    value stays. A set with at_step > k waits for that step; one whose step has run already
//    is refused (PARAM_TOO_LATE).
//  - In lockstep, k is the clock's step: a change made at step k of a run is replayed exactly
//    by the scenario's `parameter_changes: [{step: k, ...}]` (the digest is the same).
//  - A requester repeats its request until the reply comes (discovery takes a while); a
//    repeated set (same request_id) is answered again, not applied twice.
//  - Every change is logged at warn level, visible at the default log level.
// Serving allocates only when a request arrives; a tick with none takes an empty reader.
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "plexus/msg/messages.hpp"
#include "plexus/runtime/participant.hpp"
#include "plexus/scenario/scenario.hpp"

namespace plexus::distributed {

inline const char* const kParamRequestTopic = "param/request";
inline const char* const kParamReplyTopic = "param/reply";

/// The QoS of both topics: reliable, volatile, keep_last 32 (a protocol of plexus's, not a
/// profile of the user's QoS file).
rt::QosProfile param_qos();

class ParamServer {
 public:
  /// Serves the tunable parameters of the components `hosted` says run here, as `service`
  /// (the participant's name, as `plexus service list` shows it).
  ParamServer(scenario::Scenario& sc, std::vector<bool> hosted, rt::Participant& participant, std::string service);

  /// The oldest step component c has still to run when it is behind the host's steps (a
  /// realtime estimator waiting for late samples); nullopt when it is not, and the step it runs
  /// next is the first multiple of its period >= the host's step.
  using PendingStep = std::function<std::optional<int64_t>(std::size_t component)>;
  void set_pending_step(PendingStep pending_step) { pending_step_ = std::move(pending_step); }
  /// Data time of step 0 (a realtime run's start on the wall clock; lockstep: 0, sim time):
  /// a reply's header carries the data time of its step, as the outputs' headers do.
  void set_epoch(int64_t epoch_ns) { epoch_ns_ = epoch_ns; }

  /// Between two steps, before step k runs: answers what has arrived, applies the changes
  /// due at k. A change is acknowledged with the step its component runs next (PendingStep):
  /// every step before it used the old value, every step from it on uses the new one.
  void serve(int64_t k);

 private:
  void handle(const msg::ParamRequest& req, int64_t k);
  void apply(const msg::ParamRequest& req, int64_t k);
  void reply(msg::ParamReply& r);

  scenario::Scenario& sc_;
  std::vector<bool> hosted_;
  std::string service_;
  std::string addressed_as_;  ///< service_ as a request can name it (its first 63 characters)
  rt::Subscriber<msg::ParamRequest> requests_;
  rt::Publisher<msg::ParamReply> replies_;
  msg::ParamRequest scratch_;
  std::vector<msg::ParamRequest> waiting_;  ///< sets for a later step (at_step > k)
  std::deque<msg::ParamReply> answered_;    ///< the last sets' replies, for a repeated request
  /// The step component c runs next when the host is about to run step k.
  int64_t next_step(std::size_t c, int64_t k) const;

  PendingStep pending_step_;
  int64_t epoch_ns_ = 0;
  int64_t step_ns_ = 0;
};

}  // namespace plexus::distributed
