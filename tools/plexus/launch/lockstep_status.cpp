#include "lockstep_status.hpp"

#include <algorithm>
#include <cstdio>

#include "plexus/base/clock.hpp"

namespace plexus::cli {

LockstepStatus::LockstepStatus(const scenario::Scenario& sc, distributed::LockstepClock& clock, StatusConsole& console,
                               int64_t start_ns, std::map<std::string, double> producer_offset_us)
    : sc_(sc),
      clock_(clock),
      console_(console),
      producer_offset_us_(std::move(producer_offset_us)),
      status_at_(start_ns) {}

void LockstepStatus::observe(int64_t k, int64_t n) {
  const int64_t now = monotonic_ns();
  if (now - status_at_ < 1'000'000'000 && k != n) return;
  clock_.producer_status(status_);
  const double dt = static_cast<double>(now - status_at_) * 1e-9;
  const double rate = dt > 0 ? static_cast<double>(k - steps_at_) / dt : 0.0;
  status_at_ = now;
  steps_at_ = k;
  accumulate();
  show(k, n, rate);
}

void LockstepStatus::accumulate() {
  for (const auto& p : status_) {
    auto& acc = responses_[p.producer];
    if (p.samples == 0) continue;
    const auto off = producer_offset_us_.find(p.producer);
    const double correction = off == producer_offset_us_.end() ? 0.0 : off->second;
    acc.windows += 1;
    acc.p50_sum += p.response_p50_us - correction;
    acc.worst_p99 = std::max(acc.worst_p99, p.response_p99_us - correction);
    acc.samples += p.samples;
  }
}

void LockstepStatus::show(int64_t k, int64_t n, double rate) {
  const auto slow = std::max_element(status_.begin(), status_.end(), [](const auto& a, const auto& b) {
    return a.response_p99_us < b.response_p99_us;
  });
  char line[512];
  const double done_pct = 100.0 * static_cast<double>(k) / static_cast<double>(n);
  std::snprintf(line, sizeof line, "t %.1f/%.0f s (%3.0f%%) | %.0f steps/s, %.2fx realtime | slowest: %s p99 %.0f us",
                static_cast<double>(k) * sc_.step, sc_.duration, done_pct, rate, rate * sc_.step,
                slow == status_.end() ? "-" : slow->producer.c_str(),
                slow == status_.end() ? 0.0 : slow->response_p99_us);
  console_.status(line);
}

nlohmann::ordered_json LockstepStatus::response() const {
  nlohmann::ordered_json resp = nlohmann::ordered_json::object();
  for (const auto& [producer, acc] : responses_) {
    resp[producer] = {{"samples", acc.samples},
                      {"response_p50_us", acc.windows ? acc.p50_sum / acc.windows : 0.0},
                      {"response_p99_us_worst_second", acc.worst_p99}};
    if (producer_offset_us_.count(producer))  // on another host: corrected by its clock offset
      resp[producer]["clock_offset_corrected_us"] = producer_offset_us_.at(producer);
  }
  return resp;
}

}  // namespace plexus::cli
