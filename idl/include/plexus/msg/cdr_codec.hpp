// XCDR1 encoding of the generated C++ types with Fast CDR, shared by both back ends.
// Instantiated for every message type by the generated messages.cpp.
#pragma once

#include <fastcdr/Cdr.h>
#include <fastcdr/FastBuffer.h>
#include <fastcdr/exceptions/Exception.h>

#include <cstddef>
#include <cstring>

namespace plexus::msg {

template <class T>
std::size_t cdr_max_size() {
  return T::getMaxCdrSerializedSize() + 4;  // + encapsulation header
}

template <class T>
std::size_t cdr_serialize(const void* sample, unsigned char* buf, std::size_t capacity) {
  // Fast CDR skips alignment padding without writing it: zero the buffer so padding is
  // deterministic on the wire (and never leaks old memory). Only the bytes this sample
  // uses: for a bounded sequence (LatencyProbe) capacity is 64 KiB, the sample often tiny.
  const std::size_t used = T::getCdrSerializedSize(*static_cast<const T*>(sample)) + 4;
  std::memset(buf, 0, used < capacity ? used : capacity);
  eprosima::fastcdr::FastBuffer fb(reinterpret_cast<char*>(buf), capacity);
  eprosima::fastcdr::Cdr ser(fb, eprosima::fastcdr::Cdr::DEFAULT_ENDIAN, eprosima::fastcdr::Cdr::DDS_CDR);
  try {
    ser.serialize_encapsulation();
    static_cast<const T*>(sample)->serialize(ser);
  } catch (const eprosima::fastcdr::exception::Exception&) {
    return 0;
  }
  return ser.getSerializedDataLength();
}

template <class T>
bool cdr_deserialize(const unsigned char* buf, std::size_t length, void* sample) {
  eprosima::fastcdr::FastBuffer fb(const_cast<char*>(reinterpret_cast<const char*>(buf)), length);
  eprosima::fastcdr::Cdr des(fb, eprosima::fastcdr::Cdr::DEFAULT_ENDIAN, eprosima::fastcdr::Cdr::DDS_CDR);
  try {
    des.read_encapsulation();
    static_cast<T*>(sample)->deserialize(des);
  } catch (const eprosima::fastcdr::exception::Exception&) {
    return false;
  }
  return true;
}

}  // namespace plexus::msg
