#include "timing_budget.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <algorithm>
#include <atomic>
#include <thread>

#include "plexus/base/clock.hpp"
#include "plexus/distributed/realtime.hpp"
#include "plexus/distributed/wire.hpp"

namespace plexus::cli {

double percentile_us(std::vector<int64_t> v, double q) {
  if (v.empty()) return 0.0;
  const auto k = static_cast<std::size_t>(q * static_cast<double>(v.size() - 1) + 0.5);
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return static_cast<double>(v[k]) * 1e-3;
}

std::vector<LoopBudget> loop_budgets(const scenario::Scenario& sc, const std::vector<Process>& procs) {
  const std::size_t n = sc.components.size();
  std::vector<int> process_of(n, -1);
  for (std::size_t p = 0; p < procs.size(); ++p)
    for (std::size_t c : procs[p].components) process_of[c] = static_cast<int>(p);
  std::vector<double> phase(procs.size(), 0.0);
  for (std::size_t p = 0; p < procs.size(); ++p) {
    std::vector<bool> hosted(n, false);
    for (std::size_t c : procs[p].components) hosted[c] = true;
    phase[p] = distributed::stage_phase(sc, hosted);
  }
  std::vector<LoopBudget> out;
  for (const auto& loop : sc.loops) {
    LoopBudget b{loop.name, loop.deadline_s, {}};
    for (std::size_t reader : loop.members) {
      for (const auto& in : sc.components[reader].component->inputs()) {
        const auto spec = std::find_if(sc.signals.begin(), sc.signals.end(),
                                       [&](const scenario::SignalSpec& s) { return s.name == in->signal(); });
        if (spec == sc.signals.end()) continue;
        const auto producer = std::find_if(loop.members.begin(), loop.members.end(), [&](std::size_t m) {
          return sc.components[m].component->name() == spec->producer;
        });
        if (producer == loop.members.end()) continue;  // from outside the loop
        const int from = process_of[*producer], to = process_of[reader];
        if (from < 0 || to < 0 || from == to) continue;  // in memory
        double gap = phase[static_cast<std::size_t>(to)] - phase[static_cast<std::size_t>(from)];
        if (gap <= 0.0) gap += 1.0;
        LoopHop hop;
        hop.name = spec->name;
        hop.from = procs[static_cast<std::size_t>(from)].name;
        hop.to = procs[static_cast<std::size_t>(to)].name;
        hop.slot_s = gap * sc.step;
        const bool known = std::any_of(b.hops.begin(), b.hops.end(),
                                       [&](const LoopHop& h) { return h.name == hop.name && h.to == hop.to; });
        if (!known) b.hops.push_back(std::move(hop));
      }
    }
    out.push_back(std::move(b));
  }
  return out;
}

std::string budget_shortfall(const LoopBudget& loop) {
  std::string hops;
  double sum_us = 0.0;
  bool late = false;
  for (const auto& h : loop.hops) {
    const double p50 = percentile_us(h.latency_ns, 0.5), p99 = percentile_us(h.latency_ns, 0.99);
    const double slot_us = h.slot_s * 1e6;
    sum_us += p99;
    const bool over = h.latency_ns.empty() || p99 > slot_us;
    late = late || over;
    hops +=
        (hops.empty() ? "" : "; ") + h.name + " " + h.from + " -> " + h.to + ": " +
        (h.latency_ns.empty() ? std::string("no sample measured")
                              : "p50/p99 " + fmt::format("{:.0f}", p50) + "/" + fmt::format("{:.0f}", p99) + " us") +
        (over ? " > " : " <= ") + "slot " + fmt::format("{:.0f}", slot_us) + " us";
  }
  const double deadline_us = loop.deadline_s * 1e6;
  if (!late && sum_us <= deadline_us) return "";
  return "loop '" + loop.name + "' does not fit its budget under this placement (" + std::to_string(loop.hops.size()) +
         " hops between processes, p99 sum " + fmt::format("{:.0f}", sum_us) + " us, deadline " +
         fmt::format("{:.0f}", deadline_us) + " us): " + hops + " (run its members in one process: loops." + loop.name +
         ".process, docs/distributed.md)";
}

/// A hop signal's reader and the thread that waits on it.
struct BudgetCheck::Probe {
  std::string signal;
  int64_t offset_ns = 0;  // the producer host's clock offset
  std::unique_ptr<distributed::WireSubscriber> sub;
  std::vector<int64_t> latency_ns;  // written by the thread only, read after it joined
  std::thread thread;
  std::atomic<bool> stop{false};
};

BudgetCheck::BudgetCheck(std::vector<LoopBudget> loops, bool strict) : loops_(std::move(loops)), strict_(strict) {}

BudgetCheck::~BudgetCheck() { stop(); }

void BudgetCheck::bind(rt::Participant& participant, const std::vector<scenario::SignalSpec>& signals, int64_t step_ns,
                       const rt::QosProfile& qos, const std::map<std::string, int64_t>& publish_offset_ns) {
  for (const auto& loop : loops_)
    for (const auto& hop : loop.hops) {
      if (std::any_of(probes_.begin(), probes_.end(), [&](const auto& p) { return p->signal == hop.name; })) continue;
      const auto spec = std::find_if(signals.begin(), signals.end(), [&](const auto& s) { return s.name == hop.name; });
      if (spec == signals.end()) continue;
      auto p = std::make_unique<Probe>();
      p->signal = hop.name;
      if (const auto off = publish_offset_ns.find(hop.name); off != publish_offset_ns.end()) p->offset_ns = off->second;
      p->sub = std::make_unique<distributed::WireSubscriber>(participant, *spec, step_ns, qos);
      p->latency_ns.reserve(8192);
      probes_.push_back(std::move(p));
    }
}

void BudgetCheck::start(int64_t t0_ns) {
  t0_ns_ = t0_ns;
  for (auto& probe : probes_) {
    Probe* p = probe.get();
    p->thread = std::thread([p, t0_ns] {
      while (!p->stop.load()) {
        if (!p->sub->wait(5'000'000)) continue;
        const int64_t arrived = wall_time_ns(), since = monotonic_ns() - t0_ns;
        while (p->sub->take()) {
          if (since >= kFromNs && since <= kUntilNs && p->latency_ns.size() < p->latency_ns.capacity())
            p->latency_ns.push_back(arrived - p->sub->header().publish_time_ns() + p->offset_ns);
        }
        if (since > kUntilNs) break;
      }
    });
  }
}

void BudgetCheck::stop() {
  for (auto& p : probes_) {
    p->stop = true;
    if (p->thread.joinable()) p->thread.join();
  }
}

void BudgetCheck::conclude(int64_t now_ns) {
  if (concluded_ || t0_ns_ == 0 || now_ns - t0_ns_ <= kUntilNs + 10'000'000) return;
  concluded_ = true;
  stop();
  for (auto& loop : loops_)
    for (auto& hop : loop.hops)
      for (const auto& p : probes_)
        if (p->signal == hop.name) hop.latency_ns = p->latency_ns;
  std::string first;
  for (const auto& loop : loops_) {
    const std::string why = budget_shortfall(loop);
    if (why.empty()) {
      spdlog::info("timing budget: loop '{}' fits ({} hops between processes)", loop.name, loop.hops.size());
      continue;
    }
    if (first.empty()) first = why;
    if (!strict_) spdlog::warn("timing budget: {}", why);
  }
  if (strict_ && !first.empty()) throw BudgetError("--strict: " + first);
}

nlohmann::ordered_json BudgetCheck::record() const {
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (const auto& loop : loops_) {
    nlohmann::ordered_json hops = nlohmann::ordered_json::array();
    for (const auto& h : loop.hops)
      hops.push_back({{"signal", h.name},
                      {"from", h.from},
                      {"to", h.to},
                      {"slot_us", h.slot_s * 1e6},
                      {"samples", h.latency_ns.size()},
                      {"p50_us", percentile_us(h.latency_ns, 0.5)},
                      {"p99_us", percentile_us(h.latency_ns, 0.99)}});
    out[loop.name] = {{"deadline_us", loop.deadline_s * 1e6},
                      {"fits", concluded_ ? nlohmann::ordered_json(budget_shortfall(loop).empty()) : nullptr},
                      {"hops", hops}};
  }
  return out;
}

}  // namespace plexus::cli
