// plexus replay FILE: publishes a recording (plexus record) again, at the recorded speed
// (--rate-scale), at a fixed rate, as fast as possible, or one step per clock tick
// (--lockstep). Replayed data stands in for the simulator: same topics, same types
// (`plexus launch SCENARIO --record FILE`, then `plexus launch SCENARIO --external
// plant_simulator` with `plexus replay --lockstep FILE --topics <the plant's topics>`, e.g.
// r1/truth/state,r1/position).
//
// Header times: by default seq_num and data_time_ns are kept and origin/publish times are
// shifted by (replay start - recording start), so hop latencies downstream stay
// meaningful; --restamp shifts data times as well, so a realtime run reads the replay as
// live samples on its own clock (a robot's `source: {type: replay}` under plexus launch);
// --verbatim publishes the recorded samples byte for byte.
//
// --service NAME: publish a heartbeat on health/NAME once a second (plexus launch waits for
// one from every process it starts).
#include <time.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <map>
#include <thread>

#include "command.hpp"
#include "plexus/base/clock.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/distributed/lockstep.hpp"
#include "plexus/distributed/realtime.hpp"
#include "plexus/evaluation/evaluation.hpp"
#include "plexus/msg/messages.hpp"
#include "recording.hpp"
#include "replay_plan.hpp"
#include "topic_discovery.hpp"

namespace plexus::cli {
namespace {

struct ReplayOpts {
  DdsOptions dds;
  std::string file, topics, qos_file, profile, clock_topic = "lockstep/clock";
  double rate_scale = 1.0, rate = 0, wait = 2.0, linger = 1.0, timeout = 10.0;
  bool fast = false, lockstep = false, verbatim = false, restamp = false, summary = false, json = false;
  std::string service;
};

void sleep_until(int64_t t) {
  timespec ts{static_cast<time_t>(t / 1'000'000'000), static_cast<long>(t % 1'000'000'000)};
  while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) == EINTR && !g_stop) {}
}

int run_summary(const RecordingReader& rec, bool json) {
  nlohmann::ordered_json j = nlohmann::ordered_json::array();
  for (const auto& a : summarize_recording(rec)) {
    const RecordedTopic& t = *a.topic;
    char digest[17];
    std::snprintf(digest, sizeof digest, "%016llx", static_cast<unsigned long long>(a.digest));
    const double span_s = static_cast<double>(a.last_ns - a.first_ns) * 1e-9;
    if (json)
      j.push_back({{"topic", t.name}, {"type", t.type}, {"count", a.count}, {"digest", digest}, {"span_s", span_s}});
    else
      std::printf("%-40s %-36s %8llu samples  %.3f s  digest %s\n", t.name.c_str(), t.type.c_str(),
                  static_cast<unsigned long long>(a.count), span_s, digest);
  }
  if (json) std::printf("%s\n", j.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace).c_str());
  return 0;
}

int run_replay(const ReplayOpts& o) {
  rt::parse_vendor(o.dds.dds);
  const int modes = (o.fast ? 1 : 0) + (o.lockstep ? 1 : 0) + (o.rate > 0 ? 1 : 0);
  if (modes > 1) throw InputError("--fast, --rate and --lockstep: choose one");
  if (!(o.rate_scale > 0 && o.rate_scale <= 1000)) throw InputError("--rate-scale: must be in (0, 1000]");
  if (!(o.rate >= 0 && o.rate <= 1e6)) throw InputError("--rate: must be in (0, 1e6] Hz");
  if (o.restamp && (o.verbatim || o.lockstep)) throw InputError("--restamp: not with --verbatim or --lockstep");
  if (!o.profile.empty())
    rt::QosProfiles::load(o.qos_file.empty() ? rt::default_qos_file() : o.qos_file).get(o.profile);
  const auto opened = open_recording(o.file);
  const RecordingReader& rec = *opened;
  if (!rec.cut_short().empty())  // a recorder that was killed: what is there replays
    std::fprintf(stderr, "plexus replay: warning: %s: %s; replaying the %lld samples before the cut\n", o.file.c_str(),
                 rec.cut_short().c_str(), static_cast<long long>(rec.message_count()));
  if (o.summary) return run_summary(rec, o.json);
  install_stop_handler();

  const auto profiles = rt::QosProfiles::load(o.qos_file.empty() ? rt::default_qos_file() : o.qos_file);
  const rt::QosProfile* fixed = o.profile.empty() ? nullptr : &profiles.get(o.profile);
  const auto plan = plan_replay_topics(rec, o.file, split_comma_list(o.topics), fixed, o.restamp);
  auto p = make_participant(o.dds, "plexus_replay", "plexus_replay");
  struct Out {
    const msg::TypeSupport* ts = nullptr;
    std::unique_ptr<rt::WriterBackend> writer;
    void* sample = nullptr;
  };
  std::map<int64_t, Out> outs;
  rt::Publisher<msg::Heartbeat> heartbeat;
  msg::Heartbeat hb;
  int64_t next_beat = 0;
  uint64_t published = 0, failed = 0;
  const auto beat = [&](msg::ServiceState state) {
    if (!heartbeat || (state == msg::SERVICE_RUNNING && monotonic_ns() < next_beat)) return;
    next_beat = monotonic_ns() + 1'000'000'000;
    hb.state(state);
    hb.loop_count(published);
    hb.uptime_s(distributed::heartbeat_uptime_s());
    hb.header().origin_time_ns(0);
    heartbeat.publish(hb);
  };
  if (!o.service.empty()) {
    heartbeat = p->publisher<msg::Heartbeat>(distributed::health_topic(o.service), profiles.get("health"));
    hb = distributed::heartbeat_of(o.service);
    beat(msg::SERVICE_WAITING);
  }
  for (const auto& t : plan) {
    Out out;
    out.ts = t.ts;
    out.writer = p->make_writer(*t.ts, t.topic.name, t.qos);
    out.sample = t.ts->create();
    outs[t.topic.id] = std::move(out);
  }
  std::vector<RecordedMessage> msgs;
  rec.for_each([&](const RecordedMessage& m) {
    if (outs.count(m.topic_id)) msgs.push_back(m);
    return true;
  });
  if (msgs.empty()) throw std::runtime_error(o.file + ": no samples to replay");

  // Wait (bounded) for subscribers, so the first samples are not published to nobody.
  const int64_t wait_end = monotonic_ns() + static_cast<int64_t>(o.wait * 1e9);
  for (;;) {
    bool all = true;
    for (const auto& [id, out] : outs) all = all && out.writer->matched_count() > 0;
    if (all || g_stop || monotonic_ns() >= wait_end) break;
    beat(msg::SERVICE_RUNNING);
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(100));  // let matching settle both ways

  std::unique_ptr<rt::ReaderBackend> clock;
  void* tick = nullptr;
  const auto& clock_ts = msg::type_support<msg::ClockStep>();
  if (o.lockstep) {
    // The profile every lockstep host follows the clock with (transient-local: the first
    // tick is not lost to a reader that matched a moment after the clock saw it).
    clock =
        p->make_reader(clock_ts, o.clock_topic,
                       rt::QosProfiles::load(o.qos_file.empty() ? rt::default_qos_file() : o.qos_file).get("lockstep"));
    tick = clock_ts.create();
  }

  const int64_t start_mono = monotonic_ns();
  const int64_t shift = wall_time_ns() - msgs.front().receive_time_ns;
  const int64_t t0 = msgs.front().receive_time_ns;
  std::size_t i = 0;
  uint64_t ticks = 0;  // lockstep ticks received
  while (i < msgs.size() && !g_stop) {
    beat(msg::SERVICE_RUNNING);
    // The group published now: one sample, or (lockstep) every sample whose data time is
    // due at the clock's step (header data time <= the step's simulated time).
    std::size_t group_end = i + 1;
    if (o.lockstep) {
      // A bounded wait for the next tick: a clock that never came or went silent is an error.
      bool got = false;
      const int64_t give_up = monotonic_ns() + static_cast<int64_t>(o.timeout * 1e9);
      while (!got && !g_stop) {
        if (clock->wait(50'000'000)) got = clock->take(tick, nullptr);
        if (!got && monotonic_ns() > give_up)
          throw std::runtime_error(
              ticks == 0 ? "no lockstep clock on '" + o.clock_topic + "' within " + scenario::format_number(o.timeout) +
                               " s: nothing runs the clock (`plexus launch SCENARIO --external PROCESS` does)"
                         : "the lockstep clock on '" + o.clock_topic + "' stopped: no tick for " +
                               scenario::format_number(o.timeout) + " s after " + std::to_string(ticks) + " ticks");
      }
      if (!got) break;
      ++ticks;
      const auto& t = *static_cast<const msg::ClockStep*>(tick);
      if (t.step_index() == distributed::kEndOfRun) break;
      // ClockStep k lets a host run up to k + lead_steps (the clock ticks only every
      // clock_stride-th step, lockstep.hpp): the replay, standing in for a host, publishes
      // as far. Consumers wait for exactly the sample due, so an early one changes nothing.
      const int64_t horizon =
          t.sim_time_ns() +
          std::clamp<int64_t>(distributed::LockstepOptions{}.lead_steps, 0, distributed::kMaxLeadSteps) * t.step_ns();
      group_end = i;
      while (group_end < msgs.size() && msgs[group_end].data_time_ns <= horizon) ++group_end;
    } else if (o.rate > 0) {
      sleep_until(start_mono + static_cast<int64_t>(static_cast<double>(i) * 1e9 / o.rate));
    } else if (!o.fast) {
      const int64_t due = replay_due_ns(msgs[i].receive_time_ns, t0, o.rate_scale);
      sleep_until(due > INT64_MAX - start_mono ? INT64_MAX : start_mono + due);
    }
    for (; i < group_end; ++i) {
      const auto& m = msgs[i];
      Out& out = outs[m.topic_id];
      if (!out.ts->deserialize(m.cdr.data(), m.cdr.size(), out.sample)) {
        ++failed;
        continue;
      }
      if (!o.verbatim && out.ts->header) {
        // A header time the shift would carry beyond an int64 (a sample from a writer with a
        // broken clock) cannot be replayed: counted as failed.
        msg::StampHeader& h = *out.ts->header(out.sample);
        int64_t origin = h.origin_time_ns(), data = h.data_time_ns();
        if ((origin != 0 && !shift_time(origin, shift, origin)) || (o.restamp && !shift_time(data, shift, data))) {
          ++failed;
          continue;
        }
        h.origin_time_ns(origin);
        h.data_time_ns(data);
        h.publish_time_ns(wall_time_ns());
      }
      out.writer->write(out.sample) ? ++published : ++failed;
    }
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(static_cast<int64_t>(o.linger * 1000)));
  beat(msg::SERVICE_DRAINING);
  if (tick) clock_ts.destroy(tick);
  clock.reset();
  for (auto& [id, out] : outs) {
    out.writer.reset();
    out.ts->destroy(out.sample);
  }
  std::printf("replayed %llu of %zu samples from %s in %.3f s%s\n", static_cast<unsigned long long>(published),
              msgs.size(), o.file.c_str(), static_cast<double>(monotonic_ns() - start_mono) * 1e-9,
              failed ? (" (" + std::to_string(failed) + " failed)").c_str() : "");
  // Stopped by SIGINT/SIGTERM before the end: a requested stop, not a failure.
  return failed == 0 && (published == msgs.size() || g_stop) ? 0 : 1;
}

}  // namespace

Command add_replay_command(CLI::App& root) {
  auto o = std::make_shared<ReplayOpts>();
  Command c;
  c.app = root.add_subcommand("replay", "Publish a recording again (recorded speed, fixed rate, fast, or lockstep)");
  add_dds_options(c.app, o->dds);
  c.app->add_option("file", o->file, "recording written by plexus record")->required();
  c.app->add_option("--topics", o->topics, "comma-separated topics (default: all recorded)");
  c.app->add_option("--rate-scale", o->rate_scale, "speed relative to the recording (1: recorded speed)")
      ->capture_default_str();
  c.app->add_option("--rate", o->rate, "publish one sample every 1/HZ seconds instead")->check(plexus::positive("Hz"));
  c.app->add_flag("--fast", o->fast, "as fast as possible");
  c.app->add_flag("--lockstep", o->lockstep,
                  "follow the lockstep clock on --clock-topic: at each ClockStep, the samples whose header data time "
                  "is due up to the steps it allows (the step's time + the hosts' lead); stops at the end of the run");
  c.app->add_option("--clock-topic", o->clock_topic, "clock topic for --lockstep")->capture_default_str();
  c.app->add_option("--timeout", o->timeout, "--lockstep: seconds without a clock tick before giving up")
      ->capture_default_str()
      ->check(positive_seconds());
  c.app->add_flag("--verbatim", o->verbatim, "keep the recorded header times (byte-identical samples)");
  c.app->add_flag("--restamp", o->restamp,
                  "shift data times too, to now (a realtime run reads the replay as live samples)");
  c.app->add_option("--service", o->service, "publish a heartbeat on health/<service> (for plexus launch)");
  c.app->add_option("--wait", o->wait, "seconds to wait for subscribers before starting")
      ->capture_default_str()
      ->check(positive_seconds());
  c.app->add_option("--linger", o->linger, "seconds to keep the writers after the last sample")->capture_default_str();
  c.app->add_option("--profile", o->profile, "publish with this QoS profile (default: the recorded writers' QoS)");
  c.app->add_option("--qos-file", o->qos_file, "QoS profiles file (default: deploy/qos.yaml)");
  c.app->add_flag("--summary", o->summary, "print the recording's topics, counts and CDR digests; publish nothing");
  c.app->add_flag("--json", o->json, "--summary as JSON");
  c.run = [o] { return run_replay(*o); };
  return c;
}

}  // namespace plexus::cli
