// plexus param list|get|set SERVICE [KEY [VALUE]]: a running service's tunable parameters,
// read and changed over DDS as `ros2 param` does for a node (docs/parameters.md), no launcher
// needed: a ParamRequest on param/request, answered on param/reply by the service, between
// two of its steps (plexus/distributed/param_server.hpp).
// plexus param changes RECORDING: the changes a recording holds, as the scenario's
// `parameter_changes:` that replays them (same steps, same digest in lockstep).
#include <chrono>
#include <cstdio>
#include <cstring>
#include <map>
#include <random>
#include <set>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "command.hpp"
#include "plexus/base/clock.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/distributed/param_server.hpp"
#include "plexus/msg/fixed_text.hpp"
#include "plexus/msg/messages.hpp"
#include "plexus/runtime/vendor.hpp"
#include "plexus/scenario/format.hpp"
#include "recording.hpp"
#include "topic_discovery.hpp"

namespace plexus::cli {
namespace {

struct ParamOpts {
  DdsOptions dds;
  std::string service, key, recording;
  double value = 0.0;
  int64_t at_step = -1;
  double timeout = 5.0;  ///< s: discovery and the reply
  bool json = false;
};

using msg::text_of;

/// An argument into a request's char array: whole, or InputError naming the argument.
template <std::size_t N>
void copy_text(std::array<char, N>& dst, const std::string& src, const char* what) {
  if (!msg::fits(dst, src))
    throw InputError(std::string(what) + ": '" + src + "' is longer than " + std::to_string(N - 1) + " characters");
  msg::set_text(dst, src);
}

uint64_t new_request_id() {
  std::random_device rd;
  return (static_cast<uint64_t>(rd()) << 32) ^ static_cast<uint64_t>(rd()) ^ static_cast<uint64_t>(wall_time_ns());
}

/// Sends the request until its replies have come (one, or a list's count), or the timeout.
std::vector<msg::ParamReply> exchange(const ParamOpts& o, msg::ParamOperation op) {
  rt::parse_vendor(o.dds.dds);
  msg::ParamRequest req;
  msg::set_text(req.service(), o.service);  // a longer name is addressed by its first 63 characters
  copy_text(req.key(), o.key, "KEY");
  req.operation(op);
  req.value(o.value);
  req.at_step(o.at_step);
  req.request_id(new_request_id());
  auto p = make_participant(o.dds, "plexus_param", "plexus_param");
  auto requests = p->publisher<msg::ParamRequest>(distributed::kParamRequestTopic, distributed::param_qos());
  auto replies = p->subscriber<msg::ParamReply>(distributed::kParamReplyTopic, distributed::param_qos());
  std::map<uint32_t, msg::ParamReply> got;  // by index (a list's)
  uint32_t count = 1;
  msg::ParamReply r;
  const int64_t end = monotonic_ns() + static_cast<int64_t>(o.timeout * 1e9);
  int64_t next_send = 0;
  // A reply can only come once the service's reader has matched our writer; repeated every
  // 0.5 s (the service answers a repeated set again without applying it twice).
  while (!g_stop && monotonic_ns() < end && got.size() < count) {
    if (monotonic_ns() >= next_send && requests.matched_count() > 0) {
      requests.publish(req);
      next_send = monotonic_ns() + 500'000'000;
    }
    while (replies.take(r))
      if (r.request_id() == req.request_id()) {
        count = std::max<uint32_t>(1, r.count());
        got[r.index()] = r;
      }
    if (got.size() < count) replies.wait(50'000'000);
  }
  if (got.size() < count)
    throw std::runtime_error("no " + std::string(got.empty() ? "reply" : "complete reply") + " from '" + o.service +
                             "' within " + scenario::format_number(o.timeout) + " s on domain " +
                             std::to_string(o.dds.domain) + " (plexus service list names the services running)");
  std::vector<msg::ParamReply> out;
  for (auto& [i, reply] : got) out.push_back(reply);
  return out;
}

/// A reply that is not PARAM_OK: its reason, as the command's one error line (exit 2).
void require_ok(const ParamOpts& o, const msg::ParamReply& r, const std::string& what) {
  if (r.status() == msg::PARAM_OK) return;
  throw InputError(o.service + " refused " + what + ": " + text_of(r.reason()) +
                   (r.operation() == msg::PARAM_SET && r.status() != msg::PARAM_UNKNOWN_KEY
                        ? "; " + text_of(r.key()) + " stays " + scenario::format_number(r.value())
                        : std::string()));
}

nlohmann::ordered_json reply_json(const msg::ParamReply& r) {
  nlohmann::ordered_json j;
  j["service"] = text_of(r.service());
  j["key"] = text_of(r.key());
  j["value"] = r.value();
  j["description"] = text_of(r.description());
  return j;
}

int run_list(const ParamOpts& o) {
  const auto replies = exchange(o, msg::PARAM_LIST);
  require_ok(o, replies.front(), "a list");
  if (o.json) {
    nlohmann::ordered_json all = nlohmann::ordered_json::array();
    for (const auto& r : replies) all.push_back(reply_json(r));
    std::printf("%s\n", all.dump().c_str());
    return 0;
  }
  int key_w = 3;
  for (const auto& r : replies) key_w = std::max(key_w, static_cast<int>(text_of(r.key()).size()));
  std::printf("%-*s %12s  %s\n", key_w, "key", "value", "description");
  for (const auto& r : replies)
    std::printf("%-*s %12s  %s\n", key_w, text_of(r.key()).c_str(), scenario::format_number(r.value()).c_str(),
                text_of(r.description()).c_str());
  return 0;
}

int run_get(const ParamOpts& o) {
  const auto r = exchange(o, msg::PARAM_GET).front();
  require_ok(o, r, "'" + o.key + "'");
  if (o.json) {
    auto j = reply_json(r);
    j["step"] = r.applied_step();
    std::printf("%s\n", j.dump().c_str());
  } else {
    std::printf("%s = %s\n", text_of(r.key()).c_str(), scenario::format_number(r.value()).c_str());
  }
  return 0;
}

int run_set(const ParamOpts& o) {
  const auto r = exchange(o, msg::PARAM_SET).front();
  require_ok(o, r, o.key + " = " + scenario::format_number(o.value));
  if (o.json) {
    auto j = reply_json(r);
    j["previous_value"] = r.previous_value();
    j["step"] = r.applied_step();
    std::printf("%s\n", j.dump().c_str());
  } else {
    std::printf("%s: %s %s -> %s at step %lld\n", text_of(r.service()).c_str(), text_of(r.key()).c_str(),
                scenario::format_number(r.previous_value()).c_str(), scenario::format_number(r.value()).c_str(),
                static_cast<long long>(r.applied_step()));
  }
  return 0;
}

/// The accepted sets of a recording's param/reply topic, as `parameter_changes:` YAML.
int run_changes(const ParamOpts& o) {
  const auto rec = open_recording(o.recording);
  int64_t topic = -1;
  for (const auto& t : rec->topics())
    if (t.name == distributed::kParamReplyTopic) topic = t.id;
  const auto& ts = msg::type_support<msg::ParamReply>();
  std::printf("parameter_changes:%s\n", topic < 0 ? " []" : "");
  if (topic < 0) {
    std::fprintf(stderr, "plexus param changes: %s has no %s topic: no parameter changed while it was recorded\n",
                 o.recording.c_str(), distributed::kParamReplyTopic);
    return 0;
  }
  std::set<uint64_t> seen;  // request ids: a repeated reply is one change
  msg::ParamReply r;
  rec->for_each([&](const RecordedMessage& m) {
    if (m.topic_id != topic) return true;
    if (!ts.deserialize(m.cdr.data(), m.cdr.size(), &r))
      throw InputError(o.recording + ": a malformed " + ts.type_name + " sample on " + distributed::kParamReplyTopic);
    if (r.operation() != msg::PARAM_SET || r.status() != msg::PARAM_OK || !seen.insert(r.request_id()).second)
      return true;
    std::printf("  - {step: %lld, key: %s, value: %s}  # %s\n", static_cast<long long>(r.applied_step()),
                text_of(r.key()).c_str(), scenario::format_number(r.value()).c_str(), text_of(r.service()).c_str());
    return true;
  });
  return 0;
}

}  // namespace

Command add_param_command(CLI::App& root) {
  auto o = std::make_shared<ParamOpts>();
  Command c;
  c.app = root.add_subcommand(
      "param", "A running service's parameters that can change while it runs: list, get, set (either DDS vendor)");
  c.app->require_subcommand(1);
  const auto common = [&o](CLI::App* sub) {
    add_dds_options(sub, o->dds);
    sub->add_option("service", o->service,
                    "The service, as plexus service list names it (\"localisation_observer observer\")")
        ->required();
    sub->add_option("--timeout", o->timeout, "seconds to wait for the service's reply (discovery included)")
        ->capture_default_str()
        ->check(positive_seconds());
    sub->add_flag("--json", o->json, "JSON output");
  };
  auto* list = c.app->add_subcommand("list", "Its tunable parameters: key, value, meaning and unit");
  common(list);
  auto* get = c.app->add_subcommand("get", "One parameter's value");
  common(get);
  get->add_option("key", o->key, "<component>.<parameter>, or <parameter> when one component has it")->required();
  auto* set = c.app->add_subcommand(
      "set", "Change one: validated as at start, applied between two steps, acknowledged with that step");
  common(set);
  set->add_option("key", o->key, "<component>.<parameter>, or <parameter> when one component has it")->required();
  set->add_option("value", o->value, "The new value")->required();
  set->add_option("--at-step", o->at_step,
                  "Apply it before this step (lockstep: a step of the clock's; default: the next step)")
      ->check(CLI::NonNegativeNumber);
  auto* changes = c.app->add_subcommand(
      "changes", "The changes a recording holds (its param/reply topic), as a scenario's parameter_changes:");
  changes->add_option("recording", o->recording, "A plexus recording (MCAP or SQLite)")
      ->required()
      ->check(CLI::ExistingFile);
  c.run = [o, list, get, set, changes] {
    install_stop_handler();
    if (list->parsed()) return run_list(*o);
    if (get->parsed()) return run_get(*o);
    if (set->parsed()) return run_set(*o);
    if (changes->parsed()) return run_changes(*o);
    return 2;
  };
  return c;
}

}  // namespace plexus::cli
