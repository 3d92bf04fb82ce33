#include "bench/bench_report_csv.hpp"

namespace plexus::cli::bench_report_impl {
namespace {

struct Column {
  const char* name;
  bool per_rate;  ///< read from the latency entry of the row, not from the cell
  Path path;
};

const std::vector<Column>& csv_columns() {
  static const std::vector<Column> columns = {
      {"id", false, {"id"}},
      {"pair", false, {"pair"}},
      {"writer_dds", false, {"writer_dds"}},
      {"reader_dds", false, {"reader_dds"}},
      {"transport", false, {"transport"}},
      {"profile", false, {"profile"}},
      {"reliability", false, {"reliability"}},
      {"size", false, {"size"}},
      {"topology", false, {"topology"}},
      {"loss_percent", false, {"loss_percent"}},
      {"status", false, {"status"}},
      {"reason", false, {"reason"}},
      {"rate_hz", true, {"rate_hz"}},
      {"one_way_count", true, {"one_way_us", "count"}},
      {"one_way_p50_us", true, {"one_way_us", "p50"}},
      {"one_way_p90_us", true, {"one_way_us", "p90"}},
      {"one_way_p99_us", true, {"one_way_us", "p99"}},
      {"one_way_p999_us", true, {"one_way_us", "p999"}},
      {"one_way_max_us", true, {"one_way_us", "max"}},
      {"round_trip_count", true, {"round_trip_us", "count"}},
      {"round_trip_p50_us", true, {"round_trip_us", "p50"}},
      {"round_trip_p90_us", true, {"round_trip_us", "p90"}},
      {"round_trip_p99_us", true, {"round_trip_us", "p99"}},
      {"round_trip_p999_us", true, {"round_trip_us", "p999"}},
      {"round_trip_max_us", true, {"round_trip_us", "max"}},
      {"sent", true, {"sent"}},
      {"received", true, {"received"}},
      {"lost", true, {"lost"}},
      {"late", true, {"late"}},
      {"throughput_samples_per_s", false, {"throughput", "samples_per_s"}},
      {"throughput_mb_per_s", false, {"throughput", "mb_per_s"}},
      {"throughput_sent", false, {"throughput", "sent"}},
      {"throughput_received", false, {"throughput", "received"}},
      {"throughput_lost", false, {"throughput", "lost"}},
      {"throughput_seconds", false, {"throughput", "seconds"}},
      {"cpu_writer_percent", false, {"cpu_percent", "writer"}},
      {"cpu_reader_percent", false, {"cpu_percent", "reader"}},
      {"clock_offset_us", false, {"clock_offset_us"}},
      {"recovery_outage_s", false, {"recovery", "outage_s"}},
      {"recovery_s", false, {"recovery", "recovery_s"}},
      {"recovery_repaired", false, {"recovery", "repaired"}},
      {"recovery_lost", false, {"recovery", "lost"}},
      {"deadline_period_s", false, {"events", "deadline", "period_s"}},
      {"deadline_detected_after_s", false, {"events", "deadline", "detected_after_s"}},
      {"liveliness_lease_s", false, {"events", "liveliness", "lease_s"}},
      {"liveliness_detected_after_s", false, {"events", "liveliness", "detected_after_s"}},
      {"spread_one_way_p50_us", false, {"spread", "one_way_p50_us"}},
      {"spread_round_trip_p50_us", false, {"spread", "round_trip_p50_us"}},
      {"spread_throughput_samples_per_s", false, {"spread", "throughput_samples_per_s"}},
      {"vendor_tool", false, {"vendor_tool", "name"}},
      {"vendor_round_trip_p50_us", false, {"vendor_tool", "round_trip_us", "p50"}},
      {"vendor_round_trip_p99_us", false, {"vendor_tool", "round_trip_us", "p99"}},
      {"vendor_samples_per_s", false, {"vendor_tool", "throughput", "samples_per_s"}},
      {"vendor_mb_per_s", false, {"vendor_tool", "throughput", "mb_per_s"}},
      {"ratio_round_trip_p50", false, {"ratio", "round_trip_p50"}},
      {"ratio_round_trip_p99", false, {"ratio", "round_trip_p99"}},
      {"ratio_throughput", false, {"ratio", "throughput"}},
  };
  return columns;
}

std::string csv_field(const std::string& s) {  // RFC 4180: quoted if it has , " or a line break
  if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

void csv_row(std::string& out, const json& cell, const json* entry) {
  bool first = true;
  for (const auto& col : csv_columns()) {
    if (!first) out += ',';
    first = false;
    if (col.per_rate && !entry) continue;
    out += csv_field(text(col.per_rate ? *entry : cell, col.path));
  }
  out += '\n';
}

}  // namespace

std::string csv_of(const json& run) {
  std::string out;
  for (const auto& col : csv_columns()) out += (out.empty() ? "" : ",") + std::string(col.name);
  out += '\n';
  for (const json* cell : cells_of(run)) {
    std::size_t rows = 0;
    if (const json* entries = member(*cell, {"latency"}); entries && entries->is_array())
      for (const auto& e : *entries)
        if (e.is_object()) csv_row(out, *cell, &e), ++rows;
    if (rows == 0) csv_row(out, *cell, nullptr);
  }
  return out;
}

}  // namespace plexus::cli::bench_report_impl
