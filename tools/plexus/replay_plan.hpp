// What `plexus replay` decides from a recording alone, before any DDS entity exists: the
// topics it publishes (type and QoS), the per-topic summary (--summary), and the times it
// publishes at. Apart from cmd_replay.cpp so that it is tested and fuzzed without DDS
// (tests/fuzz/recording_reader_fuzz.cpp).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "plexus/msg/messages.hpp"
#include "plexus/runtime/qos.hpp"
#include "recording.hpp"

namespace plexus::cli {

/// One recorded topic as replay publishes it.
struct ReplayTopic {
  RecordedTopic topic;
  const msg::TypeSupport* ts = nullptr;
  rt::QosProfile qos;
};

/// The topics to publish: `wanted` (every topic if empty; InputError for a name the
/// recording does not have), each with its type (InputError for a type this build does not
/// know) and its QoS: `fixed` if given (--qos), else the recorded writer's (recorded_qos).
/// `restamp`: a live stand-in keeps newest-wins history (depth 1), a plain replay up to 64.
std::vector<ReplayTopic> plan_replay_topics(const RecordingReader& rec, const std::string& file,
                                            const std::vector<std::string>& wanted, const rt::QosProfile* fixed,
                                            bool restamp);

/// The recorded writer's QoS (the topics table's JSON, written by plexus record from
/// discovery) as a writer profile with history depth at least `depth`. Empty JSON (the
/// writer was not discovered): reliable, keep_last `depth`. InputError naming the file, the
/// topic and the key for JSON that is not an object of known values, a keep_last depth
/// outside 1..100000, or a duration that is not 0 or within [1 ns, 1e9 s] (the QoS file's
/// rules, docs/runtime.md).
rt::QosProfile recorded_qos(const RecordedTopic& topic, const std::string& file, int32_t depth);

/// --summary: per topic (in the topics table's order) the sample count, the first and last
/// receive times and the FNV-1a digest of the CDR bytes.
struct TopicSummary {
  const RecordedTopic* topic = nullptr;
  uint64_t count = 0;
  uint64_t digest = 1469598103934665603ull;
  int64_t first_ns = 0, last_ns = 0;
};
std::vector<TopicSummary> summarize_recording(const RecordingReader& rec);

/// Monotonic-clock offset (ns, from the replay's start) at which a sample received at
/// `receive_ns` is due when the recording started at `first_ns` (<= receive_ns, both >= 0,
/// as RecordingReader guarantees) and plays at `rate_scale` (> 0): saturated at INT64_MAX
/// for a span the clock cannot hold.
int64_t replay_due_ns(int64_t receive_ns, int64_t first_ns, double rate_scale);

/// `t` + `shift` into `out`; false (and `out` untouched) when the sum is not an int64.
bool shift_time(int64_t t, int64_t shift, int64_t& out);

}  // namespace plexus::cli
