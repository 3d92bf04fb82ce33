#include "bench/bench_netns.hpp"

#include <signal.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>

#include "child_process.hpp"
#include "external_program.hpp"

namespace plexus::cli::bench {
namespace {

constexpr const char* kPrefix = "plxb";

std::string run(const std::vector<std::string>& args, bool must = true) {
  std::string out;
  const int rc = run_program(find_program(args.front()), {args.begin() + 1, args.end()}, out, {}, true);
  if (rc != 0 && must) {
    std::string cmd;
    for (const auto& a : args) cmd += (cmd.empty() ? "" : " ") + a;
    throw std::runtime_error("two_ns: '" + cmd + "' failed: " + out);
  }
  return out;
}

/// Pair names of an earlier bench whose process is gone: plxb1_<pid>, plxb2_<pid>.
void remove_stale() {
  std::istringstream list(run({"ip", "netns", "list"}, false));
  for (std::string line; std::getline(list, line);) {
    const std::string name = line.substr(0, line.find(' '));
    if (name.rfind(kPrefix, 0) != 0 || name.size() < 7 || name[5] != '_') continue;  // plxb1_, plxb2_, plxbm_
    const long pid = std::strtol(name.c_str() + 6, nullptr, 10);
    if (pid > 0 && kill(static_cast<pid_t>(pid), 0) != 0) run({"ip", "netns", "delete", name}, false);
  }
}

long counter(const std::string& listing) {
  static const std::regex re(R"(counter packets (\d+))");
  std::smatch m;
  return std::regex_search(listing, m, re) ? std::stol(m[1]) : 0;
}

}  // namespace

bool NetnsPair::possible(std::string& why) {
  if (geteuid() != 0) {
    why = "needs root (network namespaces, nftables)";
    return false;
  }
  for (const char* p : {"ip", "nft"})
    if (find_program(p).empty()) {
      why = std::string("needs the '") + p + "' program (iproute2, nftables)";
      return false;
    }
  return true;
}

NetnsPair::NetnsPair(double delay_ms) {
  try {
    build(delay_ms);
  } catch (...) {
    remove();  // a half-built pair: no destructor runs for it
    throw;
  }
}

void NetnsPair::build(double delay_ms) {
  remove_stale();
  const std::string tag = std::to_string(getpid());
  ns1_ = std::string(kPrefix) + "1_" + tag;
  ns2_ = std::string(kPrefix) + "2_" + tag;
  veth1_ = std::string(kPrefix) + "a" + tag;
  veth2_ = std::string(kPrefix) + "b" + tag;
  run({"ip", "netns", "add", ns1_});
  created_ = true;
  run({"ip", "netns", "add", ns2_});
  if (delay_ms > 0) {
    // ns1 -- veth -- middle -- veth -- ns2; the middle has no address: link_delay relays
    // every frame (ARP too) from one of its ends to the other.
    mid_ = std::string(kPrefix) + "m_" + tag;
    const std::string m1 = std::string(kPrefix) + "c" + tag, m2 = std::string(kPrefix) + "d" + tag;
    run({"ip", "netns", "add", mid_});
    run({"ip", "link", "add", veth1_, "type", "veth", "peer", "name", m1});
    run({"ip", "link", "add", veth2_, "type", "veth", "peer", "name", m2});
    run({"ip", "link", "set", m1, "netns", mid_});
    run({"ip", "link", "set", m2, "netns", mid_});
    for (const auto& m : {m1, m2}) run({"ip", "-n", mid_, "link", "set", m, "promisc", "on", "up"});
    relay_ = spawn_program(find_program("ip"),
                           {"netns", "exec", mid_, program_path("link_delay"), "--a", m1, "--b", m2, "--delay-ms",
                            std::to_string(delay_ms)},
                           {}, {.file = "/dev/null", .fd = -1});
  } else {
    run({"ip", "link", "add", veth1_, "type", "veth", "peer", "name", veth2_});
  }
  run({"ip", "link", "set", veth1_, "netns", ns1_});
  run({"ip", "link", "set", veth2_, "netns", ns2_});
  run({"ip", "-n", ns1_, "addr", "add", std::string(address(1)) + "/24", "dev", veth1_});
  run({"ip", "-n", ns2_, "addr", "add", std::string(address(2)) + "/24", "dev", veth2_});
  for (const auto* ns : {&ns1_, &ns2_}) run({"ip", "-n", *ns, "link", "set", "lo", "up"});
  run({"ip", "-n", ns1_, "link", "set", veth1_, "up"});
  run({"ip", "-n", ns2_, "link", "set", veth2_, "up"});
  set_loss(0);
}

NetnsPair::~NetnsPair() { remove(); }

void NetnsPair::remove() {
  if (!created_) return;
  created_ = false;
  if (relay_ > 0) {
    kill(relay_, SIGTERM);
    wait_program(relay_);
  }
  // Deleting a namespace removes its end of the veth, the other end, and the rules in it.
  for (const auto* ns : {&ns1_, &ns2_, &mid_})
    if (!ns->empty()) run({"ip", "netns", "delete", *ns}, false);
}

void NetnsPair::nft(const std::string& ns, const std::string& rules) const {
  const std::string file =
      (std::filesystem::temp_directory_path() / ("plexus_bench_nft_" + std::to_string(getpid()))).string();
  std::ofstream(file) << rules;
  run({"ip", "netns", "exec", ns, "nft", "-f", file});
  std::filesystem::remove(file);
}

void NetnsPair::set_loss(double percent) {
  // One table per namespace, made anew (counters at zero): a counter of every packet arriving
  // on the veth end, the cut chain (empty unless the link is cut), then the loss rule, in
  // hundredths of a percent.
  const long per_10000 = std::lround(percent * 100);
  for (int end : {1, 2}) {
    const std::string& dev = end == 1 ? veth1_ : veth2_;
    run({"ip", "netns", "exec", ns(end), "nft", "delete", "table", "inet", "plexus_bench"}, false);
    std::ostringstream r;
    r << "table inet plexus_bench {\n  chain cut {\n  }\n  chain loss {\n";
    if (per_10000 > 0) r << "    numgen random mod 10000 < " << per_10000 << " counter drop\n";
    r << "  }\n  chain input {\n    type filter hook input priority 0; policy accept;\n"
      << "    iifname \"" << dev << "\" counter jump cut\n    iifname \"" << dev << "\" jump loss\n  }\n"
      << "  chain output {\n    type filter hook output priority 0; policy accept;\n"
      << "    oifname \"" << dev << "\" jump cut\n  }\n}\n";
    nft(ns(end), r.str());
  }
}

std::string NetnsPair::cut_command() const {
  return "ip netns exec " + ns1_ + " nft add rule inet plexus_bench cut drop && ip netns exec " + ns2_ +
         " nft add rule inet plexus_bench cut drop";
}

std::string NetnsPair::heal_command() const {
  return "ip netns exec " + ns1_ + " nft flush chain inet plexus_bench cut && ip netns exec " + ns2_ +
         " nft flush chain inet plexus_bench cut";
}

std::string NetnsPair::counters() const {
  long arrived = 0, dropped = 0;
  for (int end : {1, 2}) {
    arrived += counter(run({"ip", "netns", "exec", ns(end), "nft", "list", "chain", "inet", "plexus_bench", "input"}));
    dropped += counter(run({"ip", "netns", "exec", ns(end), "nft", "list", "chain", "inet", "plexus_bench", "loss"}));
  }
  return "dropped " + std::to_string(dropped) + " of " + std::to_string(arrived) + " packets";
}

std::vector<std::string> NetnsPair::exec_prefix(int end) const { return {"netns", "exec", ns(end)}; }

}  // namespace plexus::cli::bench
