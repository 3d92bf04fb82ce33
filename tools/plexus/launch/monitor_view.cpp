#include "monitor_view.hpp"

#include <algorithm>
#include <set>
#include <utility>

#include "service_state.hpp"

namespace plexus::cli {

Health health_of(const ProcessView& v) {
  if (!v.seen) return Health::starting;
  // A process that drained at the end of the run has stopped on purpose.
  if (v.beat.state() == msg::SERVICE_DRAINING) return Health::done;
  if (v.exited || v.age_s > kHeartbeatSilentS) return Health::down;
  return v.beat.state() == msg::SERVICE_DEGRADED ? Health::degraded : Health::ok;
}

const char* health_name(Health h) {
  switch (h) {
    case Health::starting: return "starting";
    case Health::ok: return "ok";
    case Health::degraded: return "degraded";
    case Health::down: return "down";
    case Health::done: return "done";
  }
  return "?";
}

namespace {

/// A bridge's link, or null for a service without one (every counter zero, link down).
nlohmann::json link_json(const msg::LinkStatus& l) {
  if (l.state() != msg::LINK_UP && l.frames_in() == 0 && l.frames_out() == 0 && l.disconnects() == 0) return nullptr;
  return {{"state", l.state() == msg::LINK_UP ? "up" : "down"},
          {"frames_in", l.frames_in()},
          {"frames_out", l.frames_out()},
          {"dropped_frames", l.crc_errors() + l.framing_errors() + l.oversize()},
          {"rejected_frames", l.rejected_frames()},
          {"reconnects", l.reconnects()},
          {"latency_p99_us", l.latency_p99_us()}};
}

nlohmann::json process_json(const ProcessView& v) {
  nlohmann::json j = {{"name", v.name}, {"host", v.host}, {"health", health_name(health_of(v))}};
  if (!v.seen) return j;
  const auto& b = v.beat;
  j["state"] = state_name(b.state());
  j["pid"] = b.pid();
  j["heartbeat_age_s"] = v.age_s;
  j["loop_hz"] = v.rate_hz;
  j["loops"] = b.loop_count();
  j["loop_time_us"] = {{"p50", b.compute_p50_us()}, {"p99", b.compute_p99_us()}, {"max", b.compute_max_us()}};
  j["jitter_us"] = {{"p50", b.jitter_p50_us()}, {"p99", b.jitter_p99_us()}, {"max", b.jitter_max_us()}};
  j["deadline_misses"] = b.overruns();
  j["stale_inputs"] = b.stale_inputs();
  j["refused_inputs"] = b.rejected_inputs();
  j["late_inputs"] = b.late_inputs();
  j["restarts"] = v.restarts;
  j["link"] = link_json(b.link());
  return j;
}

}  // namespace

void PlotFeed::select(std::string signal, std::string field) {
  signal_ = std::move(signal);
  field_ = std::move(field);
  reset();
}

nlohmann::json PlotFeed::next(const scenario::RunLog& log, std::size_t max_points) {
  const scenario::SignalTrace* trace = signal_.empty() ? nullptr : log.find(signal_);
  const int f = trace ? trace->field_index(field_) : -1;
  if (f < 0) return nullptr;
  nlohmann::json points = nlohmann::json::array();
  const std::size_t n = trace->size();
  const std::size_t from = std::min(cursor_, n);
  const std::size_t stride =
      std::max<std::size_t>(1, (n - from + max_points - 1) / std::max<std::size_t>(1, max_points));
  for (std::size_t r = from; r < n; r += stride)
    points.push_back({log.time(trace->steps[r]), trace->at(r, static_cast<std::size_t>(f))});
  cursor_ = n;
  nlohmann::json j = {{"signal", signal_}, {"field", field_}, {"reset", reset_}, {"points", std::move(points)}};
  reset_ = false;
  return j;
}

nlohmann::json status_json(const RunProgress& run, const std::vector<ProcessView>& procs,
                           const std::map<std::string, int64_t>& host_offsets_ns, const nlohmann::json& latency,
                           nlohmann::json plot) {
  nlohmann::json processes = nlohmann::json::array();
  std::set<std::string> hosts;
  for (const auto& p : procs) {
    processes.push_back(process_json(p));
    hosts.insert(p.host);
  }
  nlohmann::json host_list = nlohmann::json::array();
  for (const auto& h : hosts) {
    const auto off = host_offsets_ns.find(h);
    host_list.push_back({{"host", h}, {"clock_offset_ms", off == host_offsets_ns.end() ? 0.0 : off->second * 1e-6}});
  }
  return {{"type", "status"},
          {"phase", run.phase},
          {"t_s", run.t_s},
          {"duration_s", run.duration_s},
          {"processes", std::move(processes)},
          {"hosts", std::move(host_list)},
          {"latency", latency},
          {"plot", std::move(plot)}};
}

}  // namespace plexus::cli
