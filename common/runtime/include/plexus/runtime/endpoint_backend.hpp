// The vendor-neutral interface the typed Publisher<T> / Subscriber<T> sit on.
// Back ends (src/fastdds, src/cyclone) implement it once for every message type,
// through plexus::msg::TypeSupport; service code never sees it.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

namespace plexus::rt {

class WriterBackend {
 public:
  virtual ~WriterBackend() = default;
  /// Writes one sample (a T). False if the vendor refused it (e.g. reliable queue full past
  /// max_blocking_time).
  virtual bool write(const void* sample) = 0;
  /// Asserts liveliness (needed for manual liveliness kinds).
  virtual void assert_liveliness() = 0;
  /// Number of matched remote readers.
  virtual int matched_count() const = 0;
  /// Blocks until every matched reliable reader acknowledged every sample written, or
  /// `timeout_ns` passes. True if all were acknowledged. Call it before deleting a writer
  /// whose last sample must arrive (an end-of-run mark): deleting the writer drops samples
  /// still unacknowledged.
  virtual bool wait_for_acks(int64_t timeout_ns) = 0;
};

/// Per-sample metadata a reader gets besides the data.
struct SampleMeta {
  int64_t source_timestamp_ns = 0;  ///< writer's source timestamp (vendor clock)
  int64_t receive_time_ns = 0;      ///< wall clock when plexus took the sample
};

class ReaderBackend {
 public:
  virtual ~ReaderBackend() = default;
  /// Takes the oldest unread valid sample into `sample` (a T). False if there is none.
  /// Malformed data is dropped and counted, never returned; after false, `sample` may hold
  /// part of a dropped one (it is decoded in place): read it only after true.
  virtual bool take(void* sample, SampleMeta* meta) = 0;
  /// As take(), and copies the sample's serialized form as it arrived into `cdr`: XCDR1
  /// with its 4-byte encapsulation header, the bytes that were on the wire, nothing
  /// re-encoded (recorders keep exactly these). `cdr` is resized to fit; it does not
  /// allocate once its capacity reached the type's size.
  virtual bool take_raw(void* sample, std::vector<unsigned char>& cdr, SampleMeta* meta) = 0;
  /// Blocks until data is available or `timeout_ns` passes. True if data is available.
  virtual bool wait(int64_t timeout_ns) = 0;
  /// Receive-thread delivery (opt-in): `fn` is called on the vendor's own thread as data
  /// arrives (Cyclone DDS: the reader listener's on_data_available, on the receive thread;
  /// Fast DDS: DataReaderListener::on_data_available), and takes the samples itself, so no
  /// loop thread is woken per sample. A writer of the same vendor in the same process
  /// delivers locally: `fn` then runs on the writing thread, inside its write(), so it must
  /// not take a lock that thread holds while publishing. Calls for one reader never overlap.
  /// Set it at most once, right after creating the reader (samples already queued are
  /// delivered at once, on the caller's thread); it stays until the reader is destroyed,
  /// whose destructor waits for a call in progress. `fn` must not block: it holds up the
  /// receive thread and every reader behind it. wait() and take() stay valid.
  virtual void set_data_callback(std::function<void()> fn) = 0;
  /// Number of matched remote writers.
  virtual int matched_count() const = 0;
  /// Samples dropped because they could not be decoded.
  virtual uint64_t malformed_count() const = 0;
};

}  // namespace plexus::rt
