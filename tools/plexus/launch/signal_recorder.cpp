#include "signal_recorder.hpp"

#include "plexus/base/input_error.hpp"
#include "plexus/distributed/wire.hpp"
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
  topic_ids_.clear();
  for (const auto& s : signals) {
    const distributed::WireType* type = distributed::find_wire_type(s.message);
    if (!type) throw InputError("--record: signal '" + s.name + "' has no IDL message type");
    topic_ids_.push_back(file_.add_topic(distributed::signal_topic(s.name), type->support->type_name, qos_json_));
  }
  return [this](std::size_t signal, const msg::TypeSupport& ts, const void* m, const rt::SampleMeta& meta) {
    const msg::StampHeader& h = *ts.header(const_cast<void*>(m));
    RecordedMessage r;
    r.topic_id = topic_ids_.at(signal);
    r.receive_time_ns = meta.receive_time_ns;
    r.seq_num = static_cast<int64_t>(h.seq_num());
    r.data_time_ns = h.data_time_ns();
    r.origin_time_ns = h.origin_time_ns();
    r.publish_time_ns = h.publish_time_ns();
    r.cdr.resize(ts.max_cdr_size);
    r.cdr.resize(ts.serialize(m, r.cdr.data(), r.cdr.size()));
    taken_.push_back(std::move(r));
  };
}

std::size_t SignalRecorder::write() {
  file_.insert(taken_);
  file_.commit();  // the run ended: the recording replaces any file at its path
  return taken_.size();
}

}  // namespace plexus::cli
