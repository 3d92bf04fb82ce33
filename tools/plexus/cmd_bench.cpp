// plexus bench: which vendor, transport and QoS profile for a loop, measured in one command
// (docs/qos-bench.md). Runs a matrix of cells (vendor pair x transport x QoS profile x payload
// size x topology, at each rate), with the vendors' own tools beside plexus, and writes
// OUT/run.json, OUT/cells.csv and OUT/report.html. --baseline compares with an earlier run
// and exits 1 on a regression beyond the noise both runs measured.
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "bench/bench_baseline.hpp"
#include "bench/bench_matrix.hpp"
#include "bench/bench_report.hpp"
#include "bench/bench_runner.hpp"
#include "command.hpp"
#include "plexus/base/comma_list.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/runtime/qos.hpp"

namespace plexus::cli {
namespace {

using Json = nlohmann::ordered_json;

struct BenchOpts {
  std::string preset = "quick", matrix, out = "bench_out", baseline, plant;
  std::string pairs, transports, profiles, sizes, rates, topologies, qos_file;
  double loss = -1, delay_ms = -1, seconds = -1, threshold = 0.25, threshold_us = 20, noise_factor = 3;
  int repeats = 0, domain = -1;
  bool no_vendor_tools = false;
  std::string command;
};

template <class T>
std::vector<T> parse_list(const std::string& text, const char* flag) {
  std::vector<T> out;
  for (const auto& s : split_comma_list(text)) {
    try {
      std::size_t used = 0;
      const double v = std::stod(s, &used);
      if (used != s.size()) throw std::invalid_argument(s);
      out.push_back(static_cast<T>(v));
    } catch (const std::exception&) {
      throw InputError(std::string(flag) + ": '" + s + "' is not a number");
    }
  }
  return out;
}

bench::Matrix matrix_of(const BenchOpts& o) {
  bench::Matrix m = bench::preset(o.preset);
  if (!o.qos_file.empty()) m.qos_file = o.qos_file;
  if (!o.matrix.empty()) m = bench::load_matrix(o.matrix, m, o.out);
  // Flags last: they change one dimension of the file's or the preset's matrix.
  if (!o.pairs.empty()) m.pairs = bench::parse_pairs(split_comma_list(o.pairs), "--pairs");
  if (!o.transports.empty()) m.transports = split_comma_list(o.transports);
  if (!o.profiles.empty()) m.profiles = split_comma_list(o.profiles);
  if (!o.sizes.empty()) m.sizes = parse_list<int>(o.sizes, "--sizes");
  if (!o.rates.empty()) m.rates_hz = parse_list<double>(o.rates, "--rates");
  if (!o.topologies.empty()) m.topologies = split_comma_list(o.topologies);
  if (o.loss >= 0) m.loss_percent = o.loss;
  if (o.delay_ms >= 0) m.delay_ms = o.delay_ms;
  if (o.seconds > 0) m.seconds_per_phase = m.throughput_seconds = o.seconds;
  if (o.repeats > 0) m.repeats = o.repeats;
  if (o.no_vendor_tools) m.vendor_tools = false;
  if (o.domain >= 0) m.domain = o.domain;
  bench::validate(m, "plexus bench");
  return m;
}

void print_summary(const Json& run) {
  double rate = 0;
  for (const auto& r : run["matrix"]["rates_hz"])
    if (r.get<double>() > 0) {
      rate = r.get<double>();
      break;
    }
  std::printf("%-44s %9s %9s %9s %11s %8s %6s\n", "cell (pair/transport/profile/size/topology)", "1way p50", "1way p99",
              "rtt p50", "samples/s", "lost %", "vs tool");
  for (const auto& c : run["cells"]) {
    if (c["status"] != "ok") {
      if (c["status"] == "failed")
        std::printf("%-44s failed: %s\n", c["id"].get<std::string>().c_str(), c["reason"].get<std::string>().c_str());
      continue;
    }
    const Json* l = nullptr;
    for (const auto& e : c["latency"])
      if (e["rate_hz"].get<double>() == rate) l = &e;
    if (!l) continue;
    const double sent = (*l)["sent"].get<double>();
    const Json& ratio = c["ratio"];
    const bool has_ratio = ratio.is_object() && ratio["round_trip_p50"].is_number();
    std::printf("%-44s %9.1f %9.1f %9.1f %11.0f %8.2f %6s\n", c["id"].get<std::string>().c_str(),
                (*l)["one_way_us"]["p50"].get<double>(), (*l)["one_way_us"]["p99"].get<double>(),
                (*l)["round_trip_us"]["p50"].get<double>(),
                c["throughput"].is_null() ? 0.0 : c["throughput"]["samples_per_s"].get<double>(),
                sent > 0 ? 100.0 * (*l)["lost"].get<double>() / sent : 0.0,
                has_ratio ? std::to_string(ratio["round_trip_p50"].get<double>()).substr(0, 4).c_str() : "-");
  }
}

int run(const BenchOpts& o) {
  namespace fs = std::filesystem;
  fs::create_directories(o.out);
  const bench::Matrix m = matrix_of(o);
  bench::Thresholds t{o.threshold, o.threshold_us, o.noise_factor};
  if (!(t.relative >= 0) || !(t.absolute_us >= 0) || !(t.noise_factor >= 0))
    throw InputError("--threshold, --threshold-us, --noise-factor: must be >= 0");
  const Json old = o.baseline.empty() ? Json(nullptr) : bench::load_run(o.baseline);  // before the run: fail early
  bench::Plant plant;
  if (!o.plant.empty()) {
    const auto eq = o.plant.rfind('=');
    if (eq == std::string::npos) throw InputError("--plant-delay: expected CELL_ID=MICROSECONDS");
    plant.cell = o.plant.substr(0, eq);
    plant.delay_us = parse_list<double>(o.plant.substr(eq + 1), "--plant-delay").at(0);
    if (!(plant.delay_us > 0 && plant.delay_us <= 100000)) throw InputError("--plant-delay: 0 < us <= 100000");
  }
  Json run = bench::run_bench({m, o.out, o.command, plant});
  int rc = 0;
  if (!old.is_null()) {
    const auto cmp = bench::compare_runs(run, old, t);
    Json regs = Json::array();
    for (const auto& r : cmp.regressions)
      regs.push_back({{"cell", r.cell},
                      {"measure", r.measure},
                      {"old", r.old_value},
                      {"new", r.new_value},
                      {"allowed_change", r.allowed}});
    run["baseline"] = {
        {"run", o.baseline},
        {"compared", cmp.compared},
        {"thresholds", {{"relative", t.relative}, {"absolute_us", t.absolute_us}, {"noise_factor", t.noise_factor}}},
        {"regressions", regs}};
    rc = cmp.regressions.empty() ? 0 : 1;
  }
  std::ofstream(o.out + "/run.json") << run.dump(2) << '\n';
  write_bench_report(run, o.out);
  print_summary(run);
  if (run.contains("baseline")) {
    std::printf("baseline %s: %d measures compared, %zu regressions\n", o.baseline.c_str(),
                run["baseline"]["compared"].get<int>(), run["baseline"]["regressions"].size());
    for (const auto& r : run["baseline"]["regressions"])
      std::printf("REGRESSION %s %s: %.1f -> %.1f (allowed change %.1f)\n", r["cell"].get<std::string>().c_str(),
                  r["measure"].get<std::string>().c_str(), r["old"].get<double>(), r["new"].get<double>(),
                  r["allowed_change"].get<double>());
  }
  std::printf("report: %s/report.html (run.json, cells.csv) in %.0f s\n", o.out.c_str(),
              run["duration_s"].get<double>());
  // A cell that could not be measured (its processes did not start or match) fails the run
  // as a regression does: a user's CI must not read a missing figure as a pass.
  int failed = 0;
  for (const auto& c : run["cells"]) failed += c["status"] == "failed";
  if (failed > 0) {
    std::printf("%d cells failed to run (their reasons above and in the report)\n", failed);
    rc = 1;
  }
  return rc;
}

}  // namespace

Command add_bench_command(CLI::App& root) {
  Command c;
  auto o = std::make_shared<BenchOpts>();
  c.app = root.add_subcommand("bench",
                              "QoS and latency bench: a matrix of vendor pairs, transports, QoS profiles, sizes, "
                              "rates and topologies, with the vendors' tools beside it, into report.html");
  auto* a = c.app;
  a->add_option("--preset", o->preset, "quick (CI: two vendors, two sizes) or full (the whole matrix)")
      ->capture_default_str();
  a->add_option("--matrix", o->matrix, "YAML file of the matrix (its keys replace the preset's; docs/qos-bench.md)");
  a->add_option("--pairs", o->pairs, "WRITER-READER vendor pairs, e.g. fast-fast,cyclone-cyclone,fast-cyclone");
  a->add_option("--transports", o->transports, "udp,shm");
  a->add_option("--profiles", o->profiles, "QoS profile names (deploy/qos.yaml, or --qos-file)");
  a->add_option("--qos-file", o->qos_file, "QoS profiles file");
  a->add_option("--sizes", o->sizes, "payload bytes, e.g. 64,4096,65536,1048576");
  a->add_option("--rates", o->rates, "ping rates in Hz (0: unpaced); the first > 0 is the summary's");
  a->add_option("--topologies", o->topologies, "one_host,two_ns (two network namespaces, root)");
  a->add_option("--loss", o->loss, "percent of packets dropped on the two_ns link");
  a->add_option("--delay-ms", o->delay_ms, "delay each way on the two_ns link, ms (a userspace relay)");
  a->add_option("--seconds", o->seconds, "seconds per latency and throughput phase");
  a->add_option("--repeats", o->repeats, "run every group this many times (the spread between them is the noise)");
  a->add_option("--domain", o->domain, "DDS domain of every cell (default 200)");
  a->add_flag("--no-vendor-tools", o->no_vendor_tools, "skip ddsperf and raw Fast DDS");
  a->add_option("-o,--out", o->out, "output directory")->capture_default_str();
  a->add_option("--baseline", o->baseline, "an earlier run (directory or run.json): exit 1 on a regression");
  a->add_option("--threshold", o->threshold, "--baseline: relative change allowed")->capture_default_str();
  a->add_option("--threshold-us", o->threshold_us, "--baseline: latency change always allowed, us")
      ->capture_default_str();
  a->add_option("--noise-factor", o->noise_factor, "--baseline: change allowed, in multiples of the measured spread")
      ->capture_default_str();
  a->add_option("--plant-delay", o->plant, "CELL_ID=US: delay that cell's pings (to check --baseline)");
  c.run = [o, a] {
    o->command = "plexus bench";
    for (const auto& r : a->get_options())
      if (r->count() > 0 && r->get_name() != "--help") {
        o->command += " " + r->get_name();
        for (const auto& v : r->results()) o->command += " " + v;
      }
    return run(*o);
  };
  return c;
}

}  // namespace plexus::cli
