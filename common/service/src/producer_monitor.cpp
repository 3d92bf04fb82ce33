#include "plexus/service/producer_monitor.hpp"

#include <chrono>
#include <exception>

#include <spdlog/spdlog.h>

#include "plexus/distributed/wire.hpp"
#include "plexus/runtime/producer_watch.hpp"

namespace plexus::service {

ProducerMonitor::ProducerMonitor(const rt::Participant& participant, const scenario::Scenario& sc, std::string self) {
  std::vector<std::string> topics;
  for (const auto& s : sc.signals)
    if (!s.message.empty()) topics.push_back(distributed::signal_topic(s.name));
  thread_ = std::thread([this, &participant, topics = std::move(topics), self = std::move(self)]() mutable {
    rt::ProducerWatch watch(std::move(topics), std::move(self));
    try {
      while (!stop_.load()) {
        watch.check(participant);
        for (int i = 0; i < 10 && !stop_.load(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(100));
      }
    } catch (const std::exception& e) {  // discovery is a diagnosis: the service runs on without it
      spdlog::warn("producer watch stopped: {}", e.what());
    }
  });
}

ProducerMonitor::~ProducerMonitor() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
}

}  // namespace plexus::service
