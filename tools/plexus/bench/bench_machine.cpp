#include "bench/bench_machine.hpp"

#include <sys/utsname.h>
#include <unistd.h>

#include <fstream>
#include <string>

#include "external_program.hpp"

namespace plexus::cli::bench {
using Json = nlohmann::ordered_json;

namespace {

std::string first_match(const std::string& file, const std::string& key) {
  std::ifstream f(file);
  for (std::string line; std::getline(f, line);)
    if (line.rfind(key, 0) == 0) {
      const auto colon = line.find(':');
      std::string v = colon == std::string::npos ? "" : line.substr(colon + 1);
      v.erase(0, v.find_first_not_of(" \t"));
      return v;
    }
  return "";
}

std::string package_version(const std::string& package) {
  if (find_program("dpkg-query").empty()) return "unknown";
  std::string out;
  if (run_program(find_program("dpkg-query"), {"-W", "-f=${Version}", package}, out) != 0 || out.empty())
    return "unknown";
  return out;
}

}  // namespace

Json load_average() {
  std::ifstream f("/proc/loadavg");
  double a = 0, b = 0, c = 0;
  f >> a >> b >> c;
  return Json::array({a, b, c});
}

Json machine() {
  char host[256] = {};
  gethostname(host, sizeof host - 1);
  utsname u{};
  uname(&u);
  const std::string mem = first_match("/proc/meminfo", "MemTotal");
  return {{"hostname", host},
          {"cpu_model", first_match("/proc/cpuinfo", "model name")},
          {"cpus", sysconf(_SC_NPROCESSORS_ONLN)},
          {"kernel", u.release},
          {"memory_mb", mem.empty() ? 0L : std::stol(mem) / 1024},
          {"load_before", load_average()},
          {"fastdds_version", package_version("libfastrtps2.9")},
          {"cyclonedds_version", package_version("libddsc0debian")},
          {"plexus_version", PLEXUS_VERSION}};
}

}  // namespace plexus::cli::bench
