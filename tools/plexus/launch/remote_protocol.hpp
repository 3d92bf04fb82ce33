// The lines `plexus launch` and a remote share (`plexus launch --remote`, started over
// ssh) exchange on the session's stdin and stdout; the remote's stderr carries its logs.
//
//   remote:   plexus-remote <protocol> <version>        at once: the version check
//   launcher: request <json>                             the scenario text and the launch options
//   remote:   ready <json>                               its digest, QoS file, address check, process count
//   launcher: ping <n>       remote: pong <n> <t2> <t3>  clock exchanges (wall-clock ns)
//   launcher: go                                         start the processes
//   launcher: alive          remote: status <running> <expected>
//                                                        twice a second: keepalive and per-host health
//   launcher: end of file                                stop everything and exit
//
// A remote share stops when its stdin closes (the launcher or the ssh session is gone) or
// stays silent for kSilenceLimitS; its children never outlive it (PR_SET_PDEATHSIG).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace plexus::cli {

inline constexpr int kRemoteProtocol = 1;
inline constexpr const char* kRemoteHello = "plexus-remote";
/// Seconds between the launcher's keepalives, and of silence after which a remote stops.
inline constexpr double kAliveIntervalS = 0.5;
inline constexpr double kSilenceLimitS = 5.0;
/// Before `go`, a remote waits this long for each of the launcher's lines: the launcher may
/// be waiting for a slower host to connect (ssh ConnectTimeout) meanwhile.
inline constexpr double kPreflightWaitS = 60.0;

/// What the launcher sends: everything the remote's `plexus launch --host H` needs.
struct RemoteRequest {
  std::string host;
  std::string scenario_text;    ///< the scenario file's bytes, sent rather than assumed present
  std::string scenario_origin;  ///< its path on the launcher (relative paths in it resolve from the remote's workdir)
  std::vector<std::string> sets, vendors, externals;
  std::string dds, qos_file, out;
  int domain = -1;
  double timeout = 10.0;
  int64_t clock_injection_ns = 0;  ///< tests: added to the remote's clock readings (--inject-clock-offset)

  std::string to_line() const;
  /// Throws InputError naming `where` for a malformed request.
  static RemoteRequest from_line(const std::string& line, const std::string& where);
};

/// What the remote answers once it has loaded the scenario.
struct RemoteReady {
  std::string digest, qos_file, address;
  bool address_found = false;
  int processes = 0;

  std::string to_line() const;
  static bool from_line(const std::string& line, RemoteReady& out);
};

std::string hello_line(const std::string& version);
/// True for a hello line; fills the protocol number and version.
bool parse_hello(const std::string& line, int& protocol, std::string& version);

}  // namespace plexus::cli
