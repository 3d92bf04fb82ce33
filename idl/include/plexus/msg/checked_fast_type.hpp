// The Fast DDS type of every message: the fastddsgen PubSubType with a decode that cannot
// throw and whose failure the reader sees.
//
// Fast DDS 2.9 calls TopicDataType::deserialize inside DataReader::take_next_sample and
// ignores what it returns: bytes that do not decode (truncated CDR) were handed over as a
// valid sample, partly decoded. And the generated deserialize catches only Fast CDR's
// NotEnoughMemoryException: another one (BadParamException, for an encapsulation header that
// does not start with a zero byte) went out of take_next_sample into the service. Both found
// by fuzzing the subscriber edge (tests/fuzz/cdr_decode_fuzz.cpp). A failed decode now sets
// a flag of the calling thread, which the Fast DDS reader (common/runtime/src/fastdds)
// checks after each take: the sample is dropped and counted as malformed, as the Cyclone DDS
// reader does.
#pragma once

#include <fastdds/rtps/common/SerializedPayload.h>
#include <fastdds/dds/topic/TopicDataType.hpp>

#include <exception>
#include <vector>

namespace plexus::msg {

namespace detail {
inline thread_local bool fast_decode_failed = false;
inline thread_local std::vector<unsigned char>* fast_raw_capture = nullptr;
}  // namespace detail

/// While one exists, every Fast DDS decode on this thread first copies the serialized
/// payload it decodes (encapsulation header included: the bytes as received) into `into`,
/// so a reader's take can hand over the sample and its CDR (rt::ReaderBackend::take_raw).
class FastRawCapture {
 public:
  explicit FastRawCapture(std::vector<unsigned char>& into) : previous_(detail::fast_raw_capture) {
    detail::fast_raw_capture = &into;
  }
  ~FastRawCapture() { detail::fast_raw_capture = previous_; }
  FastRawCapture(const FastRawCapture&) = delete;
  FastRawCapture& operator=(const FastRawCapture&) = delete;

 private:
  std::vector<unsigned char>* previous_;
};

/// True if a Fast DDS decode in this thread failed since the last call; clears the flag.
inline bool take_fast_decode_failure() {
  const bool failed = detail::fast_decode_failed;
  detail::fast_decode_failed = false;
  return failed;
}

template <class GeneratedPubSubType>
class CheckedPubSubType final : public GeneratedPubSubType {
 public:
  bool deserialize(eprosima::fastrtps::rtps::SerializedPayload_t* payload, void* data) override {
    if (auto* capture = detail::fast_raw_capture) capture->assign(payload->data, payload->data + payload->length);
    bool ok = false;
    try {
      ok = GeneratedPubSubType::deserialize(payload, data);
    } catch (const std::exception&) {
      ok = false;
    }
    if (!ok) detail::fast_decode_failed = true;
    return ok;
  }
};

}  // namespace plexus::msg
