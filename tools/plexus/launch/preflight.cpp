#include "preflight.hpp"

#include <arpa/inet.h>
#include <ifaddrs.h>
#include <netinet/in.h>
#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "plexus/base/input_error.hpp"
#include "plexus/scenario/digest.hpp"

namespace plexus::cli {

bool uses_ssh(const scenario::Scenario& sc) {
  for (const auto& [host, access] : sc.host_access)
    if (!access.ssh.empty()) return true;
  return false;
}

std::vector<std::string> ssh_hosts(const scenario::Scenario& sc) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < sc.hosts.size(); ++i) {
    const std::string& h = sc.hosts[i];
    if (sc.host_address.at(h).empty())
      throw InputError(sc.file + ": hosts." + h + ".address: needed to start the hosts from one command (DDS peers)");
    if (i == 0) continue;
    if (sc.host_access.at(h).ssh.empty())
      throw InputError(sc.file + ": hosts." + h + ".ssh: needed: plexus launch starts every host but the first (" +
                       sc.hosts.front() + ", where it runs) over ssh; or start each host by hand with --host");
    out.push_back(h);
  }
  return out;
}

std::string scenario_digest(const scenario::Scenario& sc, const std::string& qos_file) {
  YAML::Emitter yaml;
  yaml << sc.resolved;
  uint64_t h = scenario::fnv1a64(yaml.c_str(), yaml.size());
  std::ifstream in(qos_file, std::ios::binary);
  std::ostringstream qos;
  qos << in.rdbuf();
  const std::string bytes = qos.str();
  const char sep = 0;
  h = scenario::fnv1a64(&sep, 1, h);
  return scenario::hex16(scenario::fnv1a64(bytes.data(), bytes.size(), h));
}

bool address_on_interface(const std::string& address) {
  in_addr v4{};
  in6_addr v6{};
  const bool is4 = inet_pton(AF_INET, address.c_str(), &v4) == 1;
  const bool is6 = !is4 && inet_pton(AF_INET6, address.c_str(), &v6) == 1;
  if (!is4 && !is6) return false;
  ifaddrs* list = nullptr;
  if (getifaddrs(&list) != 0) return false;
  bool found = false;
  for (ifaddrs* a = list; a && !found; a = a->ifa_next) {
    if (!a->ifa_addr) continue;
    if (is4 && a->ifa_addr->sa_family == AF_INET)
      found = std::memcmp(&reinterpret_cast<sockaddr_in*>(a->ifa_addr)->sin_addr, &v4, sizeof v4) == 0;
    if (is6 && a->ifa_addr->sa_family == AF_INET6)
      found = std::memcmp(&reinterpret_cast<sockaddr_in6*>(a->ifa_addr)->sin6_addr, &v6, sizeof v6) == 0;
  }
  freeifaddrs(list);
  return found;
}

int running_children(const std::vector<pid_t>& except) {
  const pid_t self = getpid();
  int n = 0;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator("/proc", ec)) {
    const std::string name = e.path().filename().string();
    if (name.empty() || name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream stat(e.path() / "stat");
    std::string line;
    if (!std::getline(stat, line)) continue;
    // pid (comm) state ppid ...: comm may hold spaces and parentheses, so read after the last ')'.
    const auto close = line.rfind(')');
    if (close == std::string::npos) continue;
    std::istringstream rest(line.substr(close + 1));
    std::string state;
    long ppid = 0;
    rest >> state >> ppid;
    if (ppid == self && state != "Z" && std::find(except.begin(), except.end(), std::stol(name)) == except.end()) ++n;
  }
  return n;
}

}  // namespace plexus::cli
