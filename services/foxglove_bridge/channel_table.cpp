#include "channel_table.hpp"

namespace plexus::foxglove {

ChannelTable::Diff ChannelTable::update(const std::map<std::string, const msg::TypeSupport*>& topics) {
  Diff d;
  for (auto it = live_.begin(); it != live_.end();) {
    const auto now = topics.find(it->first);
    if (now == topics.end() || now->second != it->second.type) {
      d.removed.push_back(it->second.id);
      topic_of_id_.erase(it->second.id);
      it = live_.erase(it);
    } else {
      ++it;
    }
  }
  for (const auto& [topic, type] : topics) {
    if (live_.count(topic)) continue;
    const std::string key = topic + '\n' + type->type_name;
    auto id = ids_.find(key);
    if (id == ids_.end()) id = ids_.emplace(key, next_id_++).first;
    Channel c{id->second, topic, type};
    live_.emplace(topic, c);
    topic_of_id_[c.id] = topic;
    d.added.push_back(c);
  }
  return d;
}

const Channel* ChannelTable::find(uint32_t id) const {
  const auto t = topic_of_id_.find(id);
  return t == topic_of_id_.end() ? nullptr : &live_.at(t->second);
}

std::vector<Channel> ChannelTable::all() const {
  std::vector<Channel> out;
  for (const auto& [topic, c] : live_) out.push_back(c);
  return out;
}

}  // namespace plexus::foxglove
