#include "signal_recorder.hpp"

#include "plexus/msg/messages.hpp"
#include "topic_discovery.hpp"

namespace plexus::cli {

SignalRecorder::SignalRecorder(const std::string& path, const rt::QosProfile& qos) : file_(path) {
  rt::EndpointQos q;
  q.reliability = qos.reliability;
  q.durability = qos.durability;
  q.history_known = true;
  q.history = qos.history;
  q.depth = qos.depth;
  qos_json_ = qos_to_json(q).dump();
}

distributed::LockstepClock::SampleTap SignalRecorder::tap(const std::vector<scenario::SignalSpec>& signals) {
  const auto& ts = msg::type_support<msg::Signal>();
  topic_ids_.clear();
  for (const auto& s : signals) topic_ids_.push_back(file_.add_topic(distributed::signal_topic(s.name), ts.type_name, qos_json_));
  return [this, &ts](std::size_t signal, const msg::Signal& m, const rt::SampleMeta& meta) {
    RecordedMessage r;
    r.topic_id = topic_ids_.at(signal);
    r.receive_time_ns = meta.receive_time_ns;
    r.seq_num = static_cast<int64_t>(m.header().seq_num());
    r.data_time_ns = m.header().data_time_ns();
    r.origin_time_ns = m.header().origin_time_ns();
    r.publish_time_ns = m.header().publish_time_ns();
    r.cdr.resize(ts.max_cdr_size);
    r.cdr.resize(ts.serialize(&m, r.cdr.data(), r.cdr.size()));
    taken_.push_back(std::move(r));
  };
}

std::size_t SignalRecorder::write() {
  file_.insert(taken_);
  return taken_.size();
}

}  // namespace plexus::cli
