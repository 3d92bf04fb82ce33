// plexus launch --record FILE: every signal sample the lockstep clock takes, written as a
// plexus recording (recording.hpp) of the signals' typed topics, so `plexus replay
// --lockstep` can later stand in for any producer (`plexus launch --external`).
//
// The clock sees every sample of every step, so nothing is lost to a late-joining
// recorder (which a separate `plexus record` could suffer in a fast lockstep run).
// Samples are kept in memory during the run and written when it ends.
#pragma once

#include <string>
#include <vector>

#include "plexus/distributed/lockstep.hpp"
#include "recording.hpp"

namespace plexus::cli {

class SignalRecorder {
 public:
  /// Creates `path` now (InputError if it cannot be created). `qos`: the signals' profile,
  /// stored as the recorded writers' QoS so a replay publishes them the same way.
  SignalRecorder(const std::string& path, const rt::QosProfile& qos);

  /// The clock's tap: serialises each sample with its receive and header times.
  distributed::LockstepClock::SampleTap tap(const std::vector<scenario::SignalSpec>& signals);
  /// Writes everything taken and commits the file (recording.hpp). Returns the number of samples.
  std::size_t write();

 private:
  RecordingWriter file_;
  std::string qos_json_;
  std::vector<int64_t> topic_ids_;  // by signal index
  std::vector<RecordedMessage> taken_;
};

}  // namespace plexus::cli
