// The wire contract: how a scenario signal travels between processes as its typed IDL
// message (docs/topics.md).
//
// Every output port names an IDL message type (SignalSpec::message, "PositionMeasurement").
// Each type is described once, in its IDL file, and generated as a list of slots: the name of a
// signal field and the message member (and array element) it occupies, with the member's
// accepted range (@range) and unit (@unit). A signal binds its fields to slots by name, so one
// description serves every component that produces or reads that type, and a program written
// against idl/ alone sees ordinary named members (x, y; position[i]), never a positional array.
//
// The step a sample belongs to travels in its header: data_time_ns = epoch + step * step_ns,
// where the epoch is 0 in lockstep (sim time) and the run's start on the wall clock in
// realtime (so data time is the wall-clock time of the sample, and a native producer simply
// stamps CLOCK_REALTIME there: its samples land on the nearest step of the run's grid).
// Members the signal does not use are zero.
//
// Decoding is the edge check of every input (docs/architecture.md, "Bad input"): a sample with a
// negative time, a non-finite or out-of-range member or a wrong joint count is refused
// whole and the destination left untouched, so estimator state never sees it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "plexus/msg/messages.hpp"
#include "plexus/msg/registry.hpp"
#include "plexus/runtime/participant.hpp"
#include "plexus/scenario/signal.hpp"

namespace plexus::distributed {

/// The message member one signal field occupies, and a message type as signals see it: both
/// generated from the IDL (plexus/msg/registry.hpp).
using WireSlot = msg::WireSlot;
using WireType = msg::WireType;
/// A type by its scoped ("plexus::msg::Pose2D") or unambiguous short name ("Pose2D"); nullptr if none.
using msg::find_wire_type;

/// Why a received sample was refused.
enum class Rejection { none, negative_time, non_finite, out_of_range, wrong_count };
const char* to_string(Rejection r);

/// Owning pointer to a message object of a type chosen at run time.
using MessagePtr = std::unique_ptr<void, void (*)(void*)>;

/// A signal's fields bound to the members of its message type.
class WireSignal {
 public:
  /// Throws InputError naming the signal and its producer when it has no message type, the
  /// type is unknown, or a field is not a member of it.
  WireSignal(const scenario::SignalSpec& spec, int64_t step_ns);

  const scenario::SignalSpec& spec() const { return *spec_; }
  const WireType& type() const { return *type_; }
  /// Realtime: the wall-clock time (ns) of step 0. Lockstep: 0 (the default).
  void set_epoch(int64_t epoch_ns) { epoch_ns_ = epoch_ns; }
  const msg::TypeSupport& support() const { return *type_->support; }
  MessagePtr make_message() const;

  /// Writes the sample into `message`: fields, joint count, header data time. Leaves the
  /// header's origin, sequence number and publish time alone.
  void encode(const scenario::SignalSample& s, void* message) const;
  /// Reads `message` into `s`, or says why not (then `s` is untouched); `bad_field` is the
  /// index of the offending field for non_finite and out_of_range. The step is the nearest
  /// one to the data time (negative for a sample from before the epoch: not yet valid).
  Rejection decode(const void* message, scenario::SignalSample& s, std::size_t& bad_field) const;
  /// The edge check of decode() on values the caller holds (a bridge's frame payload): the
  /// first non-finite or out-of-range field, else Rejection::none.
  Rejection check(const scenario::SignalSample& s, std::size_t& bad_field) const;
  /// The value of field i in `message` (for error messages).
  double value(const void* message, std::size_t field) const;

 private:
  const scenario::SignalSpec* spec_;
  const WireType* type_;
  std::vector<const WireSlot*> slots_;  // by field
  uint16_t count_ = 0;                  // joint messages: entries used
  bool count_field_ = false;            // the signal carries the [count] member as a field (typed ports)
  int64_t step_ns_;
  int64_t epoch_ns_ = 0;
};

/// DDS topic carrying a scenario signal: the signal's name, `<robot>/<topic>` (docs/topics.md).
std::string signal_topic(const std::string& signal);

/// Publishes one signal as its message type on its topic. publish() stamps the header as
/// rt::Publisher<T> does (sequence number, publish time, origin if 0).
class WirePublisher {
 public:
  /// Binds `spec` (throws InputError as WireSignal does) and creates the writer.
  WirePublisher(rt::Participant& p, const scenario::SignalSpec& spec, int64_t step_ns, const rt::QosProfile& qos);
  WireSignal& wire() { return wire_; }
  /// `origin_ns`: the header's origin time (0: this sample starts a chain, stamped now).
  /// False if the vendor refused the sample.
  bool publish(const scenario::SignalSample& s, int64_t origin_ns);
  /// As publish(), with the header's data time given (ns, wall clock) instead of taken from
  /// the step: a sample that is not on a run's grid (a bridge stamps a frame's arrival).
  bool publish_at(const scenario::SignalSample& s, int64_t data_time_ns, int64_t origin_ns);
  /// The origin time written into the last published sample.
  int64_t last_origin() const { return last_origin_; }
  int matched_count() const { return writer_->matched_count(); }
  /// Reliable writers: waits until every matched reader acknowledged what was written
  /// (rt::WriterBackend::wait_for_acks); false on timeout.
  bool wait_for_acks(int64_t timeout_ns) { return writer_->wait_for_acks(timeout_ns); }

 private:
  bool send(int64_t origin_ns);  // stamps sequence, publish and origin times; writes

  WireSignal wire_;
  std::unique_ptr<rt::WriterBackend> writer_;
  MessagePtr msg_;
  uint64_t seq_ = 0;
  int64_t last_origin_ = 0;
};

/// Takes one signal's messages from its topic. take() returns the raw message; the caller
/// decodes it through an InputGuard (counted refusals) or wire().decode.
class WireSubscriber {
 public:
  /// Binds `spec` (throws InputError as WireSignal does) and creates the reader.
  WireSubscriber(rt::Participant& p, const scenario::SignalSpec& spec, int64_t step_ns, const rt::QosProfile& qos);
  /// Oldest unread message, or nullptr. Valid until the next take().
  const void* take(rt::SampleMeta* meta = nullptr);
  /// From now on take() also keeps the message's CDR as received (rt::ReaderBackend::take_raw),
  /// for a recorder: raw() holds it until the next take().
  void keep_raw() { keep_raw_ = true; }
  const std::vector<unsigned char>& raw() const { return raw_; }
  bool wait(int64_t timeout_ns) { return reader_->wait(timeout_ns); }
  /// `fn` is called on the DDS receive thread when a message may be there to take
  /// (rt::ReaderBackend::set_data_callback; take() stays the caller's). Once.
  void on_data(std::function<void()> fn) { reader_->set_data_callback(std::move(fn)); }
  int matched_count() const { return reader_->matched_count(); }
  const WireSignal& wire() const { return wire_; }
  WireSignal& wire() { return wire_; }
  /// The header of the message take() returned.
  const msg::StampHeader& header() const;

 private:
  WireSignal wire_;
  std::unique_ptr<rt::ReaderBackend> reader_;
  MessagePtr msg_;
  bool keep_raw_ = false;
  std::vector<unsigned char> raw_;
};

}  // namespace plexus::distributed
