#include "plexus/distributed/lockstep_wait.hpp"

#include "lockstep_text.hpp"

namespace plexus::distributed {

namespace {
constexpr std::string_view kSample = "no sample of '";
constexpr std::string_view kProducer = "' (produced by '";
}  // namespace

std::string lockstep_wait_message(const LockstepWait& wait, int64_t step, double timeout_s) {
  return "lockstep: " + std::string(kSample) + wait.sample + std::string(kProducer) + wait.producer + "') for " +
         lockstep_step(step) + " within " + lockstep_seconds(timeout_s);
}

std::optional<LockstepWait> parse_lockstep_wait(std::string_view line) {
  const auto at = line.find(kSample);
  if (at == std::string_view::npos) return std::nullopt;
  line.remove_prefix(at + kSample.size());
  const auto sample_end = line.find(kProducer);
  if (sample_end == std::string_view::npos) return std::nullopt;
  LockstepWait w{std::string(line.substr(0, sample_end)), {}};
  line.remove_prefix(sample_end + kProducer.size());
  const auto producer_end = line.find("')");
  if (producer_end == std::string_view::npos || w.sample.empty() || producer_end == 0) return std::nullopt;
  w.producer = std::string(line.substr(0, producer_end));
  return w;
}

}  // namespace plexus::distributed
