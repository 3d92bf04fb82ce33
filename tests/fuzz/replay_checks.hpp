// What `plexus replay` does with a recording up to its first DDS call, with the checks
// the recording fuzz targets (recording_reader, mcap_reader) make on what it accepts: every
// topic's type known, its QoS within what both vendors apply, every sample's due time and
// shifted header times representable, samples in receive-time order.
#pragma once

#include <cmath>
#include <map>
#include <string>

#include "fuzz_support.hpp"
#include "plexus/msg/messages.hpp"
#include "recording.hpp"
#include "replay_plan.hpp"

namespace plexus::fuzz {

inline void check_duration(double s) { CHECK(std::isfinite(s) && (s == 0.0 || (s >= 1e-9 && s <= 1e9))); }

inline void read_as_replay(const cli::RecordingReader& rec, const std::string& path) {
  CHECK(rec.message_count() >= 0);
  const auto summary = cli::summarize_recording(rec);
  CHECK(summary.size() == rec.topics().size());
  for (const auto& s : summary) CHECK(s.count == 0 || s.first_ns <= s.last_ns);

  for (const bool restamp : {false, true}) {
    const auto plan = cli::plan_replay_topics(rec, path, {}, nullptr, restamp);
    CHECK(plan.size() == rec.topics().size());
    std::map<int64_t, const cli::ReplayTopic*> by_id;
    for (const auto& t : plan) {
      CHECK(t.ts != nullptr);
      CHECK(t.qos.depth >= 1 && t.qos.depth <= 100000);
      for (double d : {t.qos.max_blocking_time_s, t.qos.deadline_s, t.qos.liveliness_lease_s, t.qos.lifespan_s,
                       t.qos.latency_budget_s})
        check_duration(d);
      by_id[t.topic.id] = &t;
    }
    bool first = true;
    int64_t t0 = 0, shift = 0, last = 0;
    rec.for_each([&](const cli::RecordedMessage& m) {
      CHECK(m.receive_time_ns >= 0);
      if (first) {
        first = false;
        t0 = last = m.receive_time_ns;
        shift = 1'763'000'000'000'000'000 - t0;  // a replay in November 2025
      }
      CHECK(m.receive_time_ns >= last);
      last = m.receive_time_ns;
      for (const double scale : {1e-3, 1.0, 1000.0}) CHECK(cli::replay_due_ns(m.receive_time_ns, t0, scale) >= 0);
      const auto it = by_id.find(m.topic_id);
      CHECK(it != by_id.end());
      const msg::TypeSupport& ts = *it->second->ts;
      void* sample = ts.create();
      if (ts.deserialize(m.cdr.data(), m.cdr.size(), sample) && ts.header) {
        int64_t out = 0;
        const msg::StampHeader& h = *ts.header(sample);
        (void)cli::shift_time(h.origin_time_ns(), shift, out);
        (void)cli::shift_time(h.data_time_ns(), shift, out);
      }
      ts.destroy(sample);
      return true;
    });
  }
  // Replaying one topic (--topics NAME) plans that topic alone.
  if (!rec.topics().empty()) {
    const auto one = cli::plan_replay_topics(rec, path, {rec.topics().front().name}, nullptr, false);
    CHECK(one.size() == 1 && one.front().topic.id == rec.topics().front().id);
  }
}

}  // namespace plexus::fuzz
