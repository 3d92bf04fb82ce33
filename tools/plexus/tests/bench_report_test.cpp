// The report of `plexus bench` (bench/bench_report.hpp): cells.csv's rows and values, the best
// marks of the summary table (per payload size), the cells that did not run, and a run whose
// measures are missing or null.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <string>
#include <vector>

#include "bench/bench_report.hpp"
#include "external_program.hpp"

namespace plexus::cli::bench_report_test {  // its own: a unity build batches test files together
namespace {

using json = nlohmann::ordered_json;

json distribution(double p50) {
  return {{"count", 100},
          {"p50", p50},
          {"p90", p50 * 1.5},
          {"p99", p50 * 2},
          {"p999", p50 * 3},
          {"max", p50 * 4},
          {"cdf", json::array({json::array({p50 / 2, 0.01}), json::array({p50, 0.5}), json::array({p50 * 4, 1.0})})}};
}

json ok_cell(const std::string& pair, double size, const std::string& topology, double p50, double samples_per_s) {
  const std::string id = pair + "/udp/sensor/" + std::to_string(static_cast<int>(size)) + "/" + topology;
  json cell = {{"id", id},
               {"pair", pair},
               {"writer_dds", pair.substr(0, pair.find('-'))},
               {"reader_dds", pair.substr(pair.find('-') + 1)},
               {"transport", "udp"},
               {"profile", "sensor"},
               {"reliability", "best_effort"},
               {"size", size},
               {"topology", topology},
               {"loss_percent", 0},
               {"status", "ok"},
               {"reason", ""}};
  for (double rate : {100.0, 0.0})
    cell["latency"].push_back({{"rate_hz", rate},
                               {"one_way_us", distribution(p50 * (rate > 0 ? 1 : 1.5))},
                               {"round_trip_us", distribution(2.5 * p50)},
                               {"sent", 1000},
                               {"received", 990},
                               {"lost", 10},
                               {"late", 0}});
  cell["throughput"] = {{"samples_per_s", samples_per_s},
                        {"mb_per_s", samples_per_s * size / 1e6},
                        {"sent", 5000},
                        {"received", 5000},
                        {"lost", 0},
                        {"seconds", 1.0}};
  cell["cpu_percent"] = {{"writer", 30.5}, {"reader", 20.25}};
  cell["clock_offset_us"] = 0.4;
  cell["recovery"] = nullptr;
  cell["events"] = {{"deadline", nullptr}, {"liveliness", nullptr}};
  cell["vendor_tool"] = nullptr;
  cell["ratio"] = nullptr;
  return cell;
}

/// A: the fastest at 64 B; B: the highest throughput at 64 B; C: alone at 4096 B (lower
/// latency than A, but another size); D: not applicable, with only the certain members.
json small_run() {
  json run = {{"plexus_bench", 1},
              {"started_utc", "2026-11-30T00:10:00Z"},
              {"duration_s", 12.5},
              {"command", "plexus bench -o out"},
              {"machine", {{"hostname", "h"}, {"cpus", 2}, {"load_before", {0.5, 0.4, 0.3}}}},
              {"matrix",
               {{"pairs", {"fast-fast", "cyclone-cyclone"}},
                {"transports", {"udp", "shm"}},
                {"profiles", {"sensor"}},
                {"sizes", {64, 4096}},
                {"rates_hz", {0, 100}},  // the first paced rate is 100, not the first rate
                {"topologies", {"one_host", "two_ns"}}}}};
  run["cells"].push_back(ok_cell("fast-fast", 64, "one_host", 60.1, 1000));        // A
  run["cells"].push_back(ok_cell("cyclone-cyclone", 64, "one_host", 80.7, 2000));  // B
  run["cells"].push_back(ok_cell("fast-fast", 4096, "one_host", 5.5, 500));        // C
  run["cells"].push_back({{"id", "fast-fast/shm/sensor/64/two_ns"},                // D
                          {"pair", "fast-fast"},
                          {"transport", "shm"},
                          {"profile", "sensor"},
                          {"size", 64},
                          {"topology", "two_ns"},
                          {"status", "not_applicable"},
                          {"reason", "shm needs one host, \"two_ns\" has <two>"},
                          {"latency", nullptr}});
  return run;
}

/// RFC 4180 rows: quoted fields with "" for a quote.
std::vector<std::vector<std::string>> parse_csv(const std::string& text) {
  std::vector<std::vector<std::string>> rows(1, std::vector<std::string>(1));
  bool quoted = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted && c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
      rows.back().back() += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (!quoted && c == ',') {
      rows.back().emplace_back();
    } else if (!quoted && c == '\n') {
      rows.emplace_back(1);
    } else {
      rows.back().back() += c;
    }
  }
  if (rows.back() == std::vector<std::string>(1)) rows.pop_back();  // after the last newline
  return rows;
}

std::size_t column(const std::vector<std::string>& header, const std::string& name) {
  const auto it = std::find(header.begin(), header.end(), name);
  EXPECT_NE(it, header.end()) << name;
  return static_cast<std::size_t>(it - header.begin());
}

TEST(BenchCsv, OneRowPerCellAndRateAndOneForASkippedCell) {
  const json run = small_run();
  const auto rows = parse_csv(bench_csv(run));
  ASSERT_EQ(rows.size(), 1u + 3 * 2 + 1);  // header, 3 ok cells x 2 rates, the not applicable one
  const auto& header = rows[0];
  for (const auto& row : rows) EXPECT_EQ(row.size(), header.size());
  const auto id = column(header, "id"), rate = column(header, "rate_hz"), p50 = column(header, "one_way_p50_us"),
             rt_p999 = column(header, "round_trip_p999_us"), lost = column(header, "lost"),
             status = column(header, "status"), reason = column(header, "reason"),
             mb = column(header, "throughput_mb_per_s"), cpu = column(header, "cpu_reader_percent"),
             vendor = column(header, "vendor_tool");
  // The values read back as run.json has them, for each cell and rate.
  for (std::size_t c = 0; c < 3; ++c) {
    const json& cell = run["cells"][c];
    for (std::size_t r = 0; r < 2; ++r) {
      const auto& row = rows[1 + 2 * c + r];
      const json& entry = cell["latency"][r];
      EXPECT_EQ(row[id], cell["id"].get<std::string>());
      EXPECT_EQ(row[status], "ok");
      EXPECT_EQ(std::stod(row[rate]), entry["rate_hz"].get<double>());
      EXPECT_EQ(std::stod(row[p50]), entry["one_way_us"]["p50"].get<double>());
      EXPECT_EQ(std::stod(row[rt_p999]), entry["round_trip_us"]["p999"].get<double>());
      EXPECT_EQ(row[lost], "10");
      EXPECT_EQ(std::stod(row[mb]), cell["throughput"]["mb_per_s"].get<double>());
      EXPECT_EQ(row[cpu], "20.25");
      EXPECT_EQ(row[vendor], "");  // null
    }
  }
  EXPECT_EQ(rows[1][p50], "60.1");  // the shortest text of the double, not 60.100000000000001
  const auto& skipped = rows.back();
  EXPECT_EQ(skipped[id], "fast-fast/shm/sensor/64/two_ns");
  EXPECT_EQ(skipped[status], "not_applicable");
  EXPECT_EQ(skipped[reason], "shm needs one host, \"two_ns\" has <two>");  // quoted, and read back
  EXPECT_EQ(skipped[rate], "");
  EXPECT_EQ(skipped[p50], "");
  EXPECT_EQ(skipped[mb], "");
}

/// The table with id `id`, or "".
std::string table_of(const std::string& html, const std::string& id) {
  const auto at = html.find("<table class=\"bench\" id=\"" + id + "\"");
  return at == std::string::npos ? "" : html.substr(at, html.find("</table>", at) - at);
}

/// The <td> elements of the summary row of `cell`.
std::vector<std::string> summary_row(const std::string& html, const std::string& cell) {
  const std::string table = table_of(html, "summary");
  const auto start = table.find("<tr data-cell=\"" + cell + "\"");
  if (start == std::string::npos) return {};
  const std::string row = table.substr(start, table.find("</tr>", start) - start);
  std::vector<std::string> tds;
  for (auto at = row.find("<td"); at != std::string::npos; at = row.find("<td", at + 1))
    tds.push_back(row.substr(at, row.find("</td>", at) - at));
  return tds;
}

bool best(const std::string& td) { return td.rfind("<td class=\"best\">", 0) == 0; }

// The cell-id columns come first: pair, transport, profile, size, topology; then the measures.
constexpr std::size_t kOneWayP50 = 5, kRoundTripP50 = 8, kLost = 10, kLate = 11, kSamplesPerS = 12, kCpuWriter = 14;

TEST(BenchReportHtml, MarksTheBestCellOfEachSize) {
  const std::string html = bench_report_html(small_run());
  const auto a = summary_row(html, "fast-fast/udp/sensor/64/one_host");
  const auto b = summary_row(html, "cyclone-cyclone/udp/sensor/64/one_host");
  const auto c = summary_row(html, "fast-fast/udp/sensor/4096/one_host");
  ASSERT_EQ(a.size(), 17u);  // 5 keys, 12 measures
  ASSERT_EQ(b.size(), a.size());
  ASSERT_EQ(c.size(), a.size());
  EXPECT_NE(a[kOneWayP50].find(">60.1"), std::string::npos) << a[kOneWayP50];  // at 100 Hz, not unpaced
  // Latency: the lowest wins; throughput: the highest.
  EXPECT_TRUE(best(a[kOneWayP50]));
  EXPECT_FALSE(best(b[kOneWayP50]));
  EXPECT_TRUE(best(a[kRoundTripP50]));
  EXPECT_FALSE(best(a[kSamplesPerS]));
  EXPECT_TRUE(best(b[kSamplesPerS]));
  // Equal everywhere (loss, late, CPU): nothing stands out, no mark.
  for (std::size_t m : {kLost, kLate, kCpuWriter}) EXPECT_FALSE(best(a[m]) || best(b[m])) << m;
  // C is alone at 4096 B: lower latency than A, but not compared with it.
  for (const auto& td : c) EXPECT_FALSE(best(td)) << td;
  EXPECT_NE(html.find("<span class=\"best\">"), std::string::npos);  // the page says what the mark means
  EXPECT_NE(html.find("latency at 100 Hz"), std::string::npos);      // and at which rate
}

TEST(BenchReportHtml, ListsTheCellsThatDidNotRunEscaped) {
  const std::string html = bench_report_html(small_run());
  EXPECT_EQ(table_of(html, "summary").find("shm/sensor/64/two_ns"), std::string::npos);  // not in the summary
  const std::string skipped = table_of(html, "skipped");
  const auto row = skipped.find("<tr data-cell=\"fast-fast/shm/sensor/64/two_ns\"");
  ASSERT_NE(row, std::string::npos) << skipped;
  EXPECT_NE(skipped.find(">not_applicable<", row), std::string::npos);
  EXPECT_NE(skipped.find("shm needs one host, &quot;two_ns&quot; has &lt;two&gt;", row), std::string::npos);
  EXPECT_EQ(html.find("<two>"), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_NE(html.find("href=\"run.json\""), std::string::npos);
  EXPECT_NE(html.find("href=\"cells.csv\""), std::string::npos);
  // The figures it plans: a CDF of the 64 B and of the 4096 B cells, throughput, latency/rate.
  for (const char* png : {"cdf_64_one_host", "cdf_4096_one_host", "throughput_one_host", "latency_rate_one_host"})
    EXPECT_NE(html.find(std::string("<img src=\"plots/") + png + ".png\" alt=\""), std::string::npos) << png;
  EXPECT_EQ(html.find("two_ns.png"), std::string::npos);  // no cell of two_ns ran: no figure of it
}

TEST(BenchReport, MissingAndNullMeasuresAreNotAnError) {
  json run = small_run();
  run["cells"][1]["latency"] = json::array({{{"rate_hz", 100}, {"one_way_us", nullptr}, {"sent", 0}}});
  run["cells"][1]["throughput"] = nullptr;
  run["cells"][1].erase("cpu_percent");
  run["cells"][2]["status"] = "failed";
  run["cells"][2]["reason"] = "reader exited 1";
  run["cells"][2]["latency"] = "garbage";
  run["matrix"].erase("rates_hz");
  for (const json& r : {run, json::object(), json{{"cells", nullptr}}, json{{"cells", {1, "x", nullptr}}}}) {
    EXPECT_NO_THROW(bench_csv(r));
    EXPECT_NO_THROW(bench_report_html(r));
  }
  EXPECT_EQ(parse_csv(bench_csv(json::object())).size(), 1u);  // the header alone
  const std::string html = bench_report_html(run);
  EXPECT_NE(html.find("reader exited 1"), std::string::npos);
  EXPECT_FALSE(summary_row(html, "cyclone-cyclone/udp/sensor/64/one_host").empty());
}

TEST(BenchReport, WritesEveryFigureThePageShows) {
  if (find_program("gnuplot").empty()) GTEST_SKIP() << "gnuplot is not installed";
  const auto dir = std::filesystem::temp_directory_path() / ("plexus_bench_report_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  write_bench_report(small_run(), dir.string());
  std::ifstream f(dir / "report.html");
  const std::string html((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  const std::regex img("<img src=\"(plots/[^\"]+\\.png)\"");
  int images = 0;
  for (auto it = std::sregex_iterator(html.begin(), html.end(), img); it != std::sregex_iterator(); ++it, ++images)
    EXPECT_GT(std::filesystem::file_size(dir / (*it)[1].str()), 1000u) << (*it)[1];
  EXPECT_EQ(images, 4);
  EXPECT_TRUE(std::filesystem::exists(dir / "cells.csv"));
  EXPECT_TRUE(std::filesystem::exists(dir / "run.json"));  // written: the page links to it
  EXPECT_TRUE(std::filesystem::exists(dir / "plots" / "bench.gp"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace plexus::cli::bench_report_test
