// plexus launch --record FILE: every signal sample the lockstep clock takes, written as a
// plexus recording (recording.hpp; MCAP unless the file is named *.sqlite) of the signals'
// typed topics, so `plexus replay --lockstep` can later stand in for any producer
// (`plexus launch --external`), and Foxglove or any MCAP reader can open the run.
//
// The clock sees every sample of every step, so nothing is lost to a late-joining
// recorder (which a separate `plexus record` could suffer in a fast lockstep run). The
// clock's thread only copies each sample's CDR as received into a queue (sample_queue.hpp);
// a thread of the recorder writes the queue to the file every 50 ms and ends an MCAP chunk
// every second, so a launcher killed mid-run leaves a recording readable up to then.
#pragma once

#include <atomic>
#include <exception>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "plexus/distributed/lockstep.hpp"
#include "recording.hpp"
#include "sample_queue.hpp"

namespace plexus::cli {

class SignalRecorder {
 public:
  /// Checks now that `path` can be created (InputError if not). `qos`: the signals'
  /// profile, stored as the recorded writers' QoS so a replay publishes them the same way.
  SignalRecorder(const std::string& path, const rt::QosProfile& qos);
  /// A run that failed: what was recorded is written and the file closed as far as it got.
  ~SignalRecorder();

  /// The clock's tap: adds the signals' topics to the file and starts the writing thread.
  distributed::LockstepClock::SampleTap tap(const std::vector<scenario::SignalSpec>& signals);
  /// Records the services' replies on param/reply as well (plexus param: a change made while
  /// the run goes on, with the step it took effect at), so `plexus param changes` can turn them
  /// into the scenario's parameter_changes that replay them. Before tap(). The reader records
  /// while the caller keeps it, and must go before `participant` (as the clock does).
  [[nodiscard]] rt::Subscriber<msg::ParamReply> record_param_replies(rt::Participant& participant);
  /// Writes everything taken and completes the file (recording.hpp). Returns the number of
  /// samples; rethrows a write error of the writing thread.
  std::size_t write();

 private:
  void stop_thread();

  std::string path_;
  std::unique_ptr<RecordingWriter> file_;
  std::string qos_json_;
  std::vector<int64_t> topic_ids_;  // by signal index
  SampleQueue queue_;
  SampleBatch batch_;
  std::atomic<bool> stop_{false};
  std::atomic<bool> failed_{false};
  std::exception_ptr error_;
  std::thread thread_;
  std::vector<unsigned char> param_cdr_;  // one reply's CDR, on the DDS receive thread
};

}  // namespace plexus::cli
