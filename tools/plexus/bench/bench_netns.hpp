// `plexus bench`'s two-host topology on one machine: two network namespaces joined by a veth
// pair (10.233.0.1 and 10.233.0.2, addresses that exist only inside them), with nftables
// rules inside the namespaces that drop a share of the packets arriving on each end, and a
// chain that cuts the link for the burst phase. With a delay, the link goes through a third
// namespace where link_delay relays every frame after it (tools/latency/link_delay.cpp).
// The host's own network and ruleset are never touched; the namespaces (their rules, the
// relay) go when this object does. Needs root.
#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

namespace plexus::cli::bench {

class NetnsPair {
 public:
  /// Creates the pair (names carry this process's id); throws std::runtime_error naming the
  /// command that failed. Namespaces of an earlier bench whose process is gone are removed first.
  explicit NetnsPair(double delay_ms = 0);
  ~NetnsPair();
  NetnsPair(const NetnsPair&) = delete;
  NetnsPair& operator=(const NetnsPair&) = delete;

  static bool possible(std::string& why);  ///< root and the `ip` and `nft` programs

  const std::string& ns(int end) const { return end == 1 ? ns1_ : ns2_; }
  static const char* address(int end) { return end == 1 ? "10.233.0.1" : "10.233.0.2"; }

  /// Drops `percent` % of the packets arriving on each end (both directions; 0: none).
  void set_loss(double percent);
  /// Shell commands that cut the link both ways and restore it (the burst phase's fault).
  std::string cut_command() const;
  std::string heal_command() const;
  /// "dropped N of M packets" since the last set_loss (what the loss rules did).
  std::string counters() const;

  /// `ip netns exec NS` and the program: the argv prefix of a process inside end 1 or 2.
  std::vector<std::string> exec_prefix(int end) const;

 private:
  void build(double delay_ms);
  void remove();  ///< the relay and the namespaces, once
  void nft(const std::string& ns, const std::string& rules) const;
  std::string ns1_, ns2_, mid_, veth1_, veth2_;
  bool created_ = false;
  pid_t relay_ = -1;  ///< link_delay in the middle namespace, if there is a delay
};

}  // namespace plexus::cli::bench
