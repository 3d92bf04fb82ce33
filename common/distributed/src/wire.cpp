#include "plexus/distributed/wire.hpp"

#include <algorithm>
#include <cmath>

#include "plexus/base/clock.hpp"
#include "plexus/base/input_error.hpp"

namespace plexus::distributed {
namespace {

using msg::read_slot;
using msg::write_slot;

std::size_t slot_size(const WireSlot& s) {
  using K = WireSlot::Kind;
  switch (s.kind) {
    case K::f64:
    case K::i64:
    case K::u64: return 8;
    case K::f32:
    case K::i32:
    case K::u32: return 4;
    case K::i16:
    case K::u16: return 2;
    case K::i8:
    case K::u8:
    case K::boolean: return 1;
  }
  return 8;
}

/// The field names a type accepts, for errors ("q1.." stands for q1 to q16).
std::string join_fields(const WireType& t) {
  std::string out;
  for (const auto& s : t.slots) {
    if (s.index > 0 && t.count) continue;
    out += (out.empty() ? "" : ", ") + s.field + (t.count && s.kind == WireSlot::Kind::f64 ? ".." : "");
  }
  return out;
}

}  // namespace

const char* to_string(Rejection r) {
  switch (r) {
    case Rejection::none: return "accepted";
    case Rejection::negative_time: return "negative data time";
    case Rejection::non_finite: return "non-finite field";
    case Rejection::out_of_range: return "field out of its physical range";
    case Rejection::wrong_count: return "wrong joint count";
  }
  return "?";
}

WireSignal::WireSignal(const scenario::SignalSpec& spec, int64_t step_ns) : spec_(&spec), step_ns_(step_ns) {
  const std::string who = "signal '" + spec.name + "' (produced by '" + spec.producer + "')";
  if (spec.message.empty())
    throw InputError(who +
                     " has no IDL message type, so it cannot travel over DDS; run this scenario with "
                     "`plexus sim`");
  type_ = find_wire_type(spec.message);
  if (!type_)
    throw InputError(who + ": '" + spec.message +
                     "' is not a known message type (idl/plexus/msg, or a package of a plugin the scenario loads)");
  if (!type_->support->header)
    throw InputError(who + ": " + type_->name + " has no 'StampHeader header' member, so it cannot carry a signal");
  // Where each field lands in a message, to refuse two fields filling one member (aliases
  // such as z2 and z3, which both name HeadingEstimate.direction[0]).
  const MessagePtr probe = make_message();
  std::vector<const void*> places;
  std::size_t joints = 0;
  for (const auto& f : spec.fields) {
    const auto it =
        std::find_if(type_->slots.begin(), type_->slots.end(), [&](const WireSlot& s) { return s.field == f; });
    if (it == type_->slots.end())
      throw InputError(who + ": field '" + f + "' is not a member of " + type_->name +
                       " (its fields: " + join_fields(*type_) + "; docs/topics.md)");
    const void* place = static_cast<const char*>(it->member(probe.get())) + it->index * slot_size(*it);
    if (std::find(places.begin(), places.end(), place) != places.end())
      throw InputError(who + ": field '" + f + "' fills a member of " + type_->name +
                       " that another of its fields fills");
    places.push_back(place);
    slots_.push_back(&*it);
    if (type_->count && static_cast<const void*>(type_->count(probe.get())) == place) {
      count_field_ = true;  // a typed port carries the count itself
      continue;
    }
    joints = std::max(joints, it->index + 1);
  }
  if (type_->count) count_ = static_cast<uint16_t>(joints);
}

MessagePtr WireSignal::make_message() const { return {support().create(), support().destroy}; }

void WireSignal::encode(const scenario::SignalSample& s, void* message) const {
  if (type_->count && !count_field_) *type_->count(message) = count_;
  for (std::size_t i = 0; i < slots_.size(); ++i) write_slot(*slots_[i], message, s.values[i]);
  support().header(message)->data_time_ns(epoch_ns_ + s.step * step_ns_);
}

namespace {
Rejection check_value(const WireSlot& slot, double v) {
  if (!std::isfinite(v)) return Rejection::non_finite;
  if (v < slot.min || v > slot.max) return Rejection::out_of_range;
  return Rejection::none;
}
}  // namespace

Rejection WireSignal::check(const scenario::SignalSample& s, std::size_t& bad_field) const {
  for (std::size_t i = 0; i < slots_.size(); ++i)
    if (const Rejection r = check_value(*slots_[i], s.values[i]); r != Rejection::none) {
      bad_field = i;
      return r;
    }
  return Rejection::none;
}

Rejection WireSignal::decode(const void* message, scenario::SignalSample& s, std::size_t& bad_field) const {
  void* m = const_cast<void*>(message);  // the accessors are the generated non-const ones; nothing is written
  const int64_t t = support().header(m)->data_time_ns();
  if (t < 0) return Rejection::negative_time;
  if (type_->count && !count_field_ && *type_->count(m) != count_) return Rejection::wrong_count;
  for (std::size_t i = 0; i < slots_.size(); ++i)
    if (const Rejection r = check_value(*slots_[i], read_slot(*slots_[i], m)); r != Rejection::none) {
      bad_field = i;
      return r;
    }
  // The nearest step (floor((t - epoch + step/2) / step)), computed without the sum: a data
  // time near the int64 limit overflowed it (found by fuzzing the subscriber edge). t >= 0 and
  // the epoch >= 0, so their difference cannot overflow.
  const int64_t since = t - epoch_ns_;
  int64_t q = since / step_ns_, r = since % step_ns_;
  if (r < 0) {  // floor for times before the epoch
    --q;
    r += step_ns_;
  }
  s.step = r >= step_ns_ - step_ns_ / 2 ? q + 1 : q;
  for (std::size_t i = 0; i < slots_.size(); ++i) s.values[i] = read_slot(*slots_[i], m);
  std::fill(s.values.begin() + static_cast<std::ptrdiff_t>(slots_.size()), s.values.end(), 0.0);
  return Rejection::none;
}

double WireSignal::value(const void* message, std::size_t field) const {
  return read_slot(*slots_.at(field), const_cast<void*>(message));
}

// --- endpoints ----------------------------------------------------------------

std::string signal_topic(const std::string& signal) { return signal; }

WirePublisher::WirePublisher(rt::Participant& p, const scenario::SignalSpec& spec, int64_t step_ns,
                             const rt::QosProfile& qos)
    : wire_(spec, step_ns),
      writer_(p.make_writer(wire_.support(), signal_topic(spec.name), qos)),
      msg_(wire_.make_message()) {}

bool WirePublisher::publish(const scenario::SignalSample& s, int64_t origin_ns) {
  wire_.encode(s, msg_.get());
  return send(origin_ns);
}

bool WirePublisher::publish_at(const scenario::SignalSample& s, int64_t data_time_ns, int64_t origin_ns) {
  wire_.encode(s, msg_.get());
  wire_.support().header(msg_.get())->data_time_ns(data_time_ns);
  return send(origin_ns);
}

bool WirePublisher::send(int64_t origin_ns) {
  msg::StampHeader& h = *wire_.support().header(msg_.get());
  h.seq_num(++seq_);
  const int64_t now = wall_time_ns();
  h.publish_time_ns(now);
  h.origin_time_ns(origin_ns != 0 ? origin_ns : now);
  last_origin_ = h.origin_time_ns();
  return writer_->write(msg_.get());
}

WireSubscriber::WireSubscriber(rt::Participant& p, const scenario::SignalSpec& spec, int64_t step_ns,
                               const rt::QosProfile& qos)
    : wire_(spec, step_ns),
      reader_(p.make_reader(wire_.support(), signal_topic(spec.name), qos)),
      msg_(wire_.make_message()) {}

const void* WireSubscriber::take(rt::SampleMeta* meta) {
  if (keep_raw_) {
    if (raw_.capacity() < wire_.support().max_cdr_size) raw_.reserve(wire_.support().max_cdr_size);
    return reader_->take_raw(msg_.get(), raw_, meta) ? msg_.get() : nullptr;
  }
  return reader_->take(msg_.get(), meta) ? msg_.get() : nullptr;
}

const msg::StampHeader& WireSubscriber::header() const { return *wire_.support().header(msg_.get()); }

}  // namespace plexus::distributed
