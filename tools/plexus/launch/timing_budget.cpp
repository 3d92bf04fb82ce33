#include "timing_budget.hpp"

#include <spdlog/spdlog.h>
#include <algorithm>

#include <fmt/format.h>
#include "plexus/distributed/realtime.hpp"

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

BudgetCheck::BudgetCheck(std::vector<LoopBudget> loops, bool strict) : loops_(std::move(loops)), strict_(strict) {
  for (auto& loop : loops_)
    for (auto& hop : loop.hops) hop.latency_ns.reserve(4096);
}

void BudgetCheck::bind(const std::vector<scenario::SignalSpec>& signals) {
  by_signal_.assign(signals.size(), {});
  for (std::size_t s = 0; s < signals.size(); ++s)
    for (std::size_t l = 0; l < loops_.size(); ++l)
      for (std::size_t h = 0; h < loops_[l].hops.size(); ++h)
        if (loops_[l].hops[h].name == signals[s].name) by_signal_[s].emplace_back(l, h);
}

void BudgetCheck::sample(std::size_t signal, int64_t latency_ns, int64_t since_start_ns) {
  if (concluded_ || signal >= by_signal_.size() || since_start_ns < kFromNs || since_start_ns > kUntilNs) return;
  for (const auto& [l, h] : by_signal_[signal]) {
    auto& v = loops_[l].hops[h].latency_ns;
    if (v.size() < v.capacity()) v.push_back(latency_ns);
  }
}

void BudgetCheck::conclude(int64_t since_start_ns) {
  if (concluded_ || since_start_ns <= kUntilNs) return;
  concluded_ = true;
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
