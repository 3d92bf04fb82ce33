#include "plexus/distributed/param_server.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <tuple>
#include <type_traits>

#include "plexus/msg/fixed_text.hpp"
#include "plexus/scenario/format.hpp"
#include "plexus/scenario/parameter_change.hpp"

namespace plexus::distributed {
namespace {

constexpr std::size_t kRemembered = 16;  ///< sets whose reply a repeated request gets again

using msg::text_of;

}  // namespace

rt::QosProfile param_qos() {
  rt::QosProfile q;
  q.name = "param";
  q.reliability = rt::QosProfile::Reliability::reliable;
  q.durability = rt::QosProfile::Durability::volatile_;
  q.history = rt::QosProfile::History::keep_last;
  q.depth = 32;
  return q;
}

ParamServer::ParamServer(scenario::Scenario& sc, std::vector<bool> hosted, rt::Participant& participant,
                         std::string service)
    : sc_(sc), hosted_(std::move(hosted)), service_(std::move(service)), step_ns_(std::llround(sc.step * 1e9)) {
  // A request names its target in 63 characters at most: a longer name is addressed by its start.
  addressed_as_ = service_.substr(0, std::tuple_size_v<std::remove_reference_t<decltype(scratch_.service())>> - 1);
  requests_ = participant.subscriber<msg::ParamRequest>(kParamRequestTopic, param_qos());
  replies_ = participant.publisher<msg::ParamReply>(kParamReplyTopic, param_qos());
  waiting_.reserve(8);
}

int64_t ParamServer::next_step(std::size_t c, int64_t k) const {
  if (pending_step_)
    if (const auto pending = pending_step_(c)) return *pending;
  const int64_t period = sc_.components[c].period_steps;
  return (k + period - 1) / period * period;
}

void ParamServer::serve(int64_t k) {
  while (requests_.take(scratch_))
    if (text_of(scratch_.service()) == addressed_as_) handle(scratch_, k);
  if (waiting_.empty()) return;
  for (auto it = waiting_.begin(); it != waiting_.end();) {
    if (it->at_step() > k) {
      ++it;
      continue;
    }
    apply(*it, k);
    it = waiting_.erase(it);
  }
}

void ParamServer::reply(msg::ParamReply& r) {
  msg::set_text(r.service(), service_);
  if (r.header().data_time_ns() == 0) r.header().data_time_ns(epoch_ns_ + r.applied_step() * step_ns_);
  r.header().origin_time_ns(0);
  replies_.publish(r);
}

void ParamServer::handle(const msg::ParamRequest& req, int64_t k) {
  for (auto& done : answered_)
    if (done.request_id() == req.request_id()) {  // a repeated set: answered, not applied again
      reply(done);
      return;
    }
  msg::ParamReply r;
  r.request_id(req.request_id());
  r.operation(req.operation());
  r.applied_step(k);
  r.count(1);
  if (req.operation() == msg::PARAM_LIST) {
    std::vector<scenario::TunableRef> all;
    for (std::size_t c = 0; c < sc_.components.size(); ++c)
      if (hosted_[c])
        for (const auto& t : sc_.components[c].component->tunables()) all.push_back({c, &t});
    r.count(static_cast<uint32_t>(all.size()));
    if (all.empty()) {  // one reply, so the requester knows there is nothing
      r.status(msg::PARAM_UNKNOWN_KEY);
      msg::set_text(r.reason(), service_ + " has no parameter that can change while it runs");
      reply(r);
    }
    for (std::size_t i = 0; i < all.size(); ++i) {
      r.index(static_cast<uint32_t>(i));
      r.status(msg::PARAM_OK);
      msg::set_text(r.key(), scenario::tunable_name(sc_, all[i]));
      msg::set_text(r.description(), all[i].parameter->description);
      r.value(all[i].parameter->get());
      r.previous_value(r.value());
      reply(r);
    }
    return;
  }
  std::string why;
  const auto ref = scenario::find_tunable(sc_, hosted_, text_of(req.key()), why);
  if (!ref) {
    msg::set_text(r.key(), text_of(req.key()));
    r.status(msg::PARAM_UNKNOWN_KEY);
    msg::set_text(r.reason(), why);
    reply(r);
    return;
  }
  if (req.operation() == msg::PARAM_SET && req.at_step() > k) {
    if (std::none_of(waiting_.begin(), waiting_.end(),
                     [&](const msg::ParamRequest& w) { return w.request_id() == req.request_id(); }))
      waiting_.push_back(req);
    return;
  }
  if (req.operation() == msg::PARAM_SET && req.at_step() >= 0 && req.at_step() < k) {
    msg::set_text(r.key(), scenario::tunable_name(sc_, *ref));
    r.status(msg::PARAM_TOO_LATE);
    r.value(ref->parameter->get());
    r.previous_value(r.value());
    msg::set_text(r.reason(), "step " + std::to_string(req.at_step()) + " has run already (" + service_ +
                                  " is at step " + std::to_string(k) + ")");
    reply(r);
    return;
  }
  if (req.operation() == msg::PARAM_SET) {
    apply(req, k);
    return;
  }
  msg::set_text(r.key(), scenario::tunable_name(sc_, *ref));
  msg::set_text(r.description(), ref->parameter->description);
  r.status(msg::PARAM_OK);
  r.value(ref->parameter->get());
  r.previous_value(r.value());
  reply(r);
}

void ParamServer::apply(const msg::ParamRequest& req, int64_t k) {
  msg::ParamReply r;
  r.request_id(req.request_id());
  r.operation(msg::PARAM_SET);
  r.applied_step(k);
  r.count(1);
  std::string why;
  const auto ref = scenario::find_tunable(sc_, hosted_, text_of(req.key()), why);  // found when it was handled
  const std::string name = scenario::tunable_name(sc_, *ref);
  msg::set_text(r.key(), name);
  msg::set_text(r.description(), ref->parameter->description);
  const double previous = ref->parameter->get();
  r.previous_value(previous);
  r.applied_step(next_step(ref->component, k));
  r.header().data_time_ns(epoch_ns_ + r.applied_step() * step_ns_);
  why = scenario::try_set(*ref->parameter, req.value());
  r.status(why.empty() ? msg::PARAM_OK : msg::PARAM_REFUSED);
  r.value(ref->parameter->get());
  if (why.empty())
    scenario::parameter_log().warn("{}: {} {} -> {} at step {} (plexus param set)", service_, name,
                                   scenario::format_number(previous), scenario::format_number(r.value()),
                                   r.applied_step());
  else
    scenario::parameter_log().warn("{}: {} stays {}: refused {} ({})", service_, name,
                                   scenario::format_number(previous), scenario::format_number(req.value()), why);
  msg::set_text(r.reason(), why);
  reply(r);
  answered_.push_back(r);
  if (answered_.size() > kRemembered) answered_.pop_front();
}

}  // namespace plexus::distributed
