#include "plexus/runtime/producer_watch.hpp"

#include <spdlog/spdlog.h>

namespace plexus::rt {

std::set<std::string> topic_producers(const std::vector<DiscoveredEndpoint>& endpoints, const std::string& topic,
                                      const std::string& self) {
  std::set<std::string> producers;
  for (const auto& e : endpoints) {
    if (!e.is_writer || e.topic != topic) continue;
    if (!e.local)
      producers.insert(e.participant);
    else if (!self.empty())
      producers.insert(self);
  }
  return producers;
}

ProducerWatch::ProducerWatch(std::vector<std::string> topics, std::string self)
    : topics_(std::move(topics)), self_(std::move(self)) {}

std::vector<std::string> ProducerWatch::check(const Participant& p) {
  std::vector<std::string> now;
  if (warned_.size() == topics_.size()) return now;
  const auto endpoints = p.discovered_endpoints();
  for (const auto& topic : topics_) {
    if (warned_.count(topic)) continue;
    const auto producers = topic_producers(endpoints, topic, self_);
    if (producers.size() < 2) continue;
    std::string list;
    for (const auto& w : producers) list += (list.empty() ? "" : ", ") + w;
    spdlog::warn("{} has writers in {} processes ({}): their samples interleave", topic, producers.size(), list);
    warned_.insert(topic);
    now.push_back(topic);
  }
  return now;
}

}  // namespace plexus::rt
