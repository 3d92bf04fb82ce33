// `plexus bench`'s computations: the distributions (nearest-rank percentiles, the CDF, the
// spread between chunks), the baseline comparison (what is a regression and what is noise),
// and the matrix file's validation (one line naming the key).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "bench/bench_baseline.hpp"
#include "bench/bench_matrix.hpp"
#include "bench/bench_stats.hpp"
#include "input_error_of.hpp"
#include "plexus/runtime/qos.hpp"

namespace plexus::cli::bench_test {  // its own: a unity build batches test files together
namespace {

using Json = nlohmann::ordered_json;
using test_support::error_of;

TEST(BenchStats, PercentilesAreNearestRankAndTheCdfEndsAtTheMax) {
  std::vector<double> us;
  for (int i = 1000; i >= 1; --i) us.push_back(i);  // any order
  const Json d = bench::distribution(us);
  EXPECT_EQ(d["count"], 1000);
  EXPECT_EQ(d["p50"], 500.0);
  EXPECT_EQ(d["p90"], 900.0);
  EXPECT_EQ(d["p99"], 990.0);
  EXPECT_EQ(d["p999"], 999.0);
  EXPECT_EQ(d["max"], 1000.0);
  const Json& cdf = d["cdf"];
  ASSERT_GE(cdf.size(), 50u);
  for (std::size_t i = 1; i < cdf.size(); ++i) {
    EXPECT_GE(cdf[i][0].get<double>(), cdf[i - 1][0].get<double>());
    EXPECT_GT(cdf[i][1].get<double>(), cdf[i - 1][1].get<double>());
  }
  EXPECT_EQ(cdf.back()[0], 1000.0);
  EXPECT_EQ(cdf.back()[1], 1.0);
  EXPECT_EQ(bench::distribution({})["count"], 0);
  EXPECT_TRUE(bench::distribution({})["cdf"].empty());
}

TEST(BenchStats, MedianSpreadIsBetweenConsecutiveChunks) {
  std::vector<double> us;
  for (double level : {10.0, 20.0, 15.0})
    for (int i = 0; i < 20; ++i) us.push_back(level);
  EXPECT_DOUBLE_EQ(bench::median_spread(us), 10.0);
  EXPECT_DOUBLE_EQ(bench::median_spread(std::vector<double>(25, 1.0)), 0.0);  // under 10 per chunk
}

Json run_with(double oneway_p50, double rtt_p50, double samples_per_s, double spread = 0) {
  auto dist = [](double p50) { return Json{{"count", 100}, {"p50", p50}, {"p99", 2 * p50}}; };
  Json cell = {
      {"id", "fast-fast/udp/sensor/64/one_host"},
      {"status", "ok"},
      {"latency",
       Json::array({{{"rate_hz", 1000.0}, {"one_way_us", dist(oneway_p50)}, {"round_trip_us", dist(rtt_p50)}}})},
      {"throughput", {{"samples_per_s", samples_per_s}}},
      {"spread", {{"one_way_p50_us", spread}, {"round_trip_p50_us", spread}, {"throughput_samples_per_s", spread}}}};
  Json other = {{"id", "cyclone-cyclone/udp/sensor/64/one_host"}, {"status", "not_applicable"}};
  return {{"plexus_bench", 1}, {"matrix", {{"rates_hz", {1000.0, 0.0}}}}, {"cells", {cell, other}}};
}

TEST(BenchBaseline, ARegressionIsBeyondTheThresholdsAndTheNoise) {
  const bench::Thresholds t;  // 25 %, 20 us, 3 x spread
  const Json old = run_with(100, 200, 50000);
  // Within 25 %: none; three measures compared (one-way, round trip, throughput).
  auto same = bench::compare_runs(run_with(120, 240, 40000), old, t);
  EXPECT_EQ(same.compared, 3);
  EXPECT_TRUE(same.regressions.empty());
  // One-way 100 -> 200 us, throughput halved: two regressions, the round trip's +20 % not.
  auto worse = bench::compare_runs(run_with(200, 240, 25000), old, t);
  ASSERT_EQ(worse.regressions.size(), 2u);
  EXPECT_EQ(worse.regressions[0].measure, "one_way_us p50");
  EXPECT_DOUBLE_EQ(worse.regressions[0].allowed, 25.0);
  EXPECT_EQ(worse.regressions[1].measure, "throughput samples/s");
  // The same change inside the noise the old run measured of itself (3 x 40 us) is no
  // regression; noise in the new run alone does not excuse it.
  EXPECT_TRUE(bench::compare_runs(run_with(200, 240, 50000), run_with(100, 200, 50000, 40), t).regressions.empty());
  EXPECT_EQ(bench::compare_runs(run_with(200, 240, 50000, 40), old, t).regressions.size(), 1u);
  // A small absolute change is noise even when it is large in relative terms (10 -> 25 us).
  EXPECT_TRUE(bench::compare_runs(run_with(25, 25, 50000), run_with(10, 10, 50000), t).regressions.empty());
  // Better is never a regression.
  EXPECT_TRUE(bench::compare_runs(run_with(10, 20, 90000), old, t).regressions.empty());
}

class BenchMatrixFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() / ("plexus_bench_test_" + std::to_string(getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string write(const std::string& text) {
    const std::string p = (dir_ / "matrix.yaml").string();
    std::ofstream(p) << text;
    return p;
  }
  std::string load_error(const std::string& text) {
    const std::string p = write(text);
    return error_of([&] { bench::load_matrix(p, bench::preset("quick"), dir_.string()); });
  }
  std::filesystem::path dir_;
};

TEST_F(BenchMatrixFile, BadEntriesAreRefusedNamingTheKey) {
  EXPECT_NE(load_error("sizez: [64]\n").find("sizez"), std::string::npos);
  EXPECT_NE(load_error("sizes: [64, 2000000]\n").find("sizes: each must be in 0..1048576 bytes"), std::string::npos);
  EXPECT_NE(load_error("pairs: [fast-opensplice]\n").find("opensplice"), std::string::npos);
  EXPECT_NE(load_error("pairs: [fast]\n").find("is not WRITER-READER"), std::string::npos);
  EXPECT_NE(load_error("transports: [tcp]\n").find("unknown value 'tcp'"), std::string::npos);
  EXPECT_NE(load_error("profiles: [nope]\n").find("nope"), std::string::npos);
  EXPECT_NE(load_error("rates_hz: [1000, 1000]\n").find("listed twice"), std::string::npos);
  EXPECT_NE(load_error("loss_percent: 80\n").find("loss_percent: must be in 0..50"), std::string::npos);
  EXPECT_NE(load_error("sizes: [a]\n").find("expected a list of numbers"), std::string::npos);
}

TEST_F(BenchMatrixFile, InlineProfilesJoinTheNamedOnes) {
  const std::string p = write(
      "pairs: [cyclone-fast]\nprofiles:\n  - sensor\n  - {name: loop_1khz, reliability: reliable, depth: 4, "
      "deadline_s: "
      "0.002}\nsizes: [64]\n");
  const bench::Matrix m = bench::load_matrix(p, bench::preset("quick"), dir_.string());
  EXPECT_EQ(m.pairs.at(0).name(), "cyclone-fast");
  ASSERT_EQ(m.profiles, (std::vector<std::string>{"sensor", "loop_1khz"}));
  EXPECT_EQ(m.qos_file, (dir_ / "qos.yaml").string());
  const auto profiles = rt::QosProfiles::load(m.qos_file);
  EXPECT_EQ(profiles.get("loop_1khz").depth, 4);
  EXPECT_DOUBLE_EQ(profiles.get("loop_1khz").deadline_s, 0.002);
  EXPECT_EQ(profiles.get("sensor").reliability, rt::QosProfile::Reliability::best_effort);
  // A bad inline profile is refused by the profiles' own validation, naming it.
  EXPECT_NE(load_error("profiles:\n  - {name: bad, depth: 0}\n").find("depth"), std::string::npos);
}

}  // namespace
}  // namespace plexus::cli::bench_test
