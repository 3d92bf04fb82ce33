// Which typed topics the bridge advertises: every topic with a writer on the domain whose type
// this process knows (the message registry), one channel each. update() says what appeared
// and what went; a topic that comes back with the same type gets its old channel id back (the
// protocol allows reuse only for the identical channel).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "ws_protocol.hpp"

namespace plexus::foxglove {

class ChannelTable {
 public:
  struct Diff {
    std::vector<Channel> added;
    std::vector<uint32_t> removed;
  };
  /// `topics`: every topic with a writer now, and its type.
  Diff update(const std::map<std::string, const msg::TypeSupport*>& topics);
  /// The channel of an id, or nullptr (never advertised, or gone).
  const Channel* find(uint32_t id) const;
  std::vector<Channel> all() const;

 private:
  std::map<std::string, Channel> live_;          // by topic
  std::map<std::string, uint32_t> ids_;          // topic + '\n' + type -> id, ever given
  std::map<uint32_t, std::string> topic_of_id_;  // live ids
  uint32_t next_id_ = 1;
};

}  // namespace plexus::foxglove
