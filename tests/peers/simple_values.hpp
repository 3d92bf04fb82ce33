// Known sample values shared with the vendor-native peers (native_cyclone_peer.c and
// native_fast_peer.cpp compute the same ones): Pose2D and JointState, as functions of
// the header sequence number.
#pragma once

#include <cstdint>

// fastddsgen types only, so the vendor-native Fast DDS peer can use this too.
#include "joint.h"
#include "pose.h"

namespace plexus::test {

inline void fill_simple(msg::Pose2D& m, uint64_t seq) {
  m.header().seq_num(seq);
  m.x(static_cast<double>(seq));
  m.y(-0.5 * static_cast<double>(seq));
  m.theta(0.01 * static_cast<double>(seq));
}

inline bool check_simple(const msg::Pose2D& m) {
  const auto s = static_cast<double>(m.header().seq_num());
  return s > 0 && m.x() == s && m.y() == -0.5 * s && m.theta() == 0.01 * s;
}

inline void fill_simple(msg::JointState& m, uint64_t seq) {
  m.header().seq_num(seq);
  m.count(7);
  for (int i = 0; i < 16; ++i) {
    m.position()[i] = static_cast<double>(seq) + i;
    m.velocity()[i] = -static_cast<double>(i);
    m.effort()[i] = 0.5 * static_cast<double>(seq) * i;
  }
}

inline bool check_simple(const msg::JointState& m) {
  const auto s = static_cast<double>(m.header().seq_num());
  if (s <= 0 || m.count() != 7) return false;
  for (int i = 0; i < 16; ++i)
    if (m.position()[i] != s + i || m.velocity()[i] != -static_cast<double>(i) || m.effort()[i] != 0.5 * s * i)
      return false;
  return true;
}

}  // namespace plexus::test
