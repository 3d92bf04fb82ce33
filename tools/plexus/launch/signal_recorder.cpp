#include "signal_recorder.hpp"

#include <chrono>

#include "plexus/base/clock.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/distributed/param_server.hpp"
#include "plexus/distributed/wire.hpp"
#include "plexus/msg/messages.hpp"
#include "topic_discovery.hpp"

namespace plexus::cli {
namespace {

/// A topic's QoS as the recording stores it (the writers' offer, read back by replay).
std::string recorded_qos(const rt::QosProfile& qos) {
  rt::EndpointQos q;
  q.reliability = qos.reliability;
  q.durability = qos.durability;
  q.history_known = true;
  q.history = qos.history;
  q.depth = qos.depth;
  return qos_to_json(q).dump();
}

}  // namespace

SignalRecorder::SignalRecorder(const std::string& path, const rt::QosProfile& qos) : path_(path) {
  RecordingOptions o;
  o.format = recording_format(path, "");
  o.library = std::string("plexus ") + PLEXUS_VERSION;
  o.metadata = {{"recorder", "plexus launch --record"}, {"version", PLEXUS_VERSION}};
  file_ = make_recording_writer(path, o);
  qos_json_ = recorded_qos(qos);
}

SignalRecorder::~SignalRecorder() {
  stop_thread();
  try {
    if (!failed_) {
      queue_.take(batch_);
      file_->insert(batch_);
    }
  } catch (const std::exception&) {}
  // file_'s destructor: MCAP closes the file as it is; SQLite leaves none.
}

void SignalRecorder::stop_thread() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
}

distributed::LockstepClock::SampleTap SignalRecorder::tap(const std::vector<scenario::SignalSpec>& signals) {
  topic_ids_.clear();
  for (const auto& s : signals) {
    const distributed::WireType* type = distributed::find_wire_type(s.message);
    if (!type) throw InputError("--record: signal '" + s.name + "' has no IDL message type");
    topic_ids_.push_back(file_->add_topic(distributed::signal_topic(s.name), *type->support, qos_json_));
  }
  thread_ = std::thread([this] {
    int64_t next_flush = monotonic_ns() + 1'000'000'000;
    SampleBatch batch;
    try {
      while (!stop_) {
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        queue_.take(batch);
        file_->insert(batch);
        if (monotonic_ns() >= next_flush) {
          file_->flush();  // at most a second of the run is lost if the launcher is killed
          next_flush += 1'000'000'000;
        }
      }
    } catch (...) {
      error_ = std::current_exception();
      failed_ = true;
    }
  });
  return [this](std::size_t signal, const msg::TypeSupport& ts, const void* m, const rt::SampleMeta& meta,
                const std::vector<unsigned char>& cdr) {
    if (failed_.load(std::memory_order_relaxed)) return;  // write() reports the error
    queue_.push(topic_ids_.at(signal), meta.receive_time_ns, ts.header(const_cast<void*>(m)), cdr.data(), cdr.size());
  };
}

rt::Subscriber<msg::ParamReply> SignalRecorder::record_param_replies(rt::Participant& participant) {
  const auto& ts = msg::type_support<msg::ParamReply>();
  const rt::QosProfile param = distributed::param_qos();
  const int64_t topic = file_->add_topic(distributed::kParamReplyTopic, ts, recorded_qos(param));
  param_cdr_.resize(ts.max_cdr_size);
  auto replies = participant.subscriber<msg::ParamReply>(distributed::kParamReplyTopic, param);
  replies.on_sample([this, topic, &ts](msg::ParamReply& r, const rt::SampleMeta& meta) {
    if (failed_.load(std::memory_order_relaxed)) return;
    const std::size_t n = ts.serialize(&r, param_cdr_.data(), param_cdr_.size());
    if (n > 0) queue_.push(topic, meta.receive_time_ns, &r.header(), param_cdr_.data(), n);
  });
  return replies;
}

std::size_t SignalRecorder::write() {
  stop_thread();
  if (error_) std::rethrow_exception(error_);
  queue_.take(batch_);
  file_->insert(batch_);
  file_->commit();  // the run ended: the recording is complete
  return queue_.pushed();
}

}  // namespace plexus::cli
