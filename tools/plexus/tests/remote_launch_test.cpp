// The pure parts of plexus launch over ssh and plexus deploy units: the clock-offset
// estimate (RFC 5905), the ssh command line and its quoting, the launcher protocol's
// lines, and the quoting of systemd ExecStart arguments.
#include <gtest/gtest.h>

#include <stdexcept>

#include "launch/clock_offset.hpp"
#include "launch/remote_protocol.hpp"
#include "launch/ssh_command.hpp"
#include "systemd_units.hpp"

namespace plexus::cli {
namespace {

// A host whose clock is `offset` ahead, with one-way delays `up` and `down` and `hold` there.
ClockSample exchange(int64_t t1, int64_t offset, int64_t up, int64_t down, int64_t hold = 0) {
  ClockSample s;
  s.t1 = t1;
  s.t2 = t1 + up + offset;
  s.t3 = s.t2 + hold;
  s.t4 = t1 + up + hold + down;
  return s;
}

TEST(ClockOffset, SymmetricPathGivesTheExactOffset) {
  const auto o = estimate_offset({exchange(1'000'000, 50'000'000, 200'000, 200'000, 10'000)});
  EXPECT_EQ(o.offset_ns, 50'000'000);
  EXPECT_EQ(o.delay_ns, 400'000);
  EXPECT_EQ(o.uncertainty_ns, 200'000);
}

TEST(ClockOffset, KeepsTheMinimumDelaySampleAndItsErrorIsWithinHalfItsDelay) {
  // Queueing on the way up inflates a sample's delay and skews its offset by half the asymmetry.
  const int64_t offset = -3'000'000;
  std::vector<ClockSample> s{exchange(0, offset, 5'000'000, 100'000), exchange(10'000'000, offset, 150'000, 120'000),
                             exchange(20'000'000, offset, 100'000, 3'000'000)};
  const auto o = estimate_offset(s);
  EXPECT_EQ(o.delay_ns, 270'000);
  EXPECT_EQ(o.samples, 3);
  EXPECT_LE(std::llabs(o.offset_ns - offset), o.uncertainty_ns);
  EXPECT_EQ(o.offset_ns, offset + (150'000 - 120'000) / 2);
}

TEST(ClockOffset, RefusesNoSampleAndAStepDuringTheExchange) {
  EXPECT_THROW(estimate_offset({}), std::invalid_argument);
  ClockSample stepped = exchange(0, 0, 100, 100);
  stepped.t4 = -1;
  EXPECT_THROW(estimate_offset({stepped}), std::invalid_argument);
}

TEST(ClockOffset, BoundIsATenthOfTheBaseStep) {
  EXPECT_EQ(offset_bound_ns(0.01), 1'000'000);
  EXPECT_EQ(offset_bound_ns(0.001), 100'000);
}

TEST(SshCommand, QuotesForThePosixShell) {
  EXPECT_EQ(shell_quote("/opt/plexus"), "'/opt/plexus'");
  EXPECT_EQ(shell_quote("it's; rm -rf /"), "'it'\\''s; rm -rf /'");
}

TEST(SshCommand, RemoteCommandChangesToTheWorkdirAndRunsThatHostsPlexus) {
  scenario::Scenario::HostAccess a{"robot@10.0.0.2", "/opt/plexus dir", ""};
  EXPECT_EQ(remote_launch_command(a, "/usr/bin/plexus"),
            "cd '/opt/plexus dir' && exec '/usr/bin/plexus' launch --remote");
  a.workdir.clear();
  a.plexus = "/opt/p/bin/plexus";
  EXPECT_EQ(remote_launch_command(a, "/usr/bin/plexus"),
            "P='/opt/p/bin/plexus'; if [ -d \"$P\" ]; then P=\"$P/bin/plexus\"; fi; exec \"$P\" launch --remote");
}

TEST(SshCommand, AnInstallPrefixRunsItsBinPlexus) {
  // The command as the remote shell runs it, with `exec` shown instead of done: a folder (an
  // install prefix) runs its bin/plexus, a file runs itself.
  auto run = [](const std::string& plexus) {
    scenario::Scenario::HostAccess a{"robot@10.0.0.2", "", plexus};
    std::string cmd = remote_launch_command(a, "/usr/bin/plexus");
    cmd.replace(cmd.find("exec "), 5, "echo ");
    std::string out;
    FILE* f = popen(cmd.c_str(), "r");
    char buf[256] = {};
    if (f && fgets(buf, sizeof buf, f)) out = buf;
    if (f) pclose(f);
    return out;
  };
  EXPECT_EQ(run("/tmp"), "/tmp/bin/plexus launch --remote\n");
  EXPECT_EQ(run("/opt/p/bin/plexus"), "/opt/p/bin/plexus launch --remote\n");
}

TEST(SshCommand, ArgumentsEndOptionsBeforeTheDestination) {
  SshOptions o;
  o.config_file = "/tmp/cfg";
  const auto a = ssh_arguments(o, "robot@h2", "exec plexus");
  ASSERT_GE(a.size(), 5u);
  EXPECT_EQ(a[0], "-F");
  EXPECT_EQ(a[1], "/tmp/cfg");
  EXPECT_EQ(a[a.size() - 3], "--");
  EXPECT_EQ(a[a.size() - 2], "robot@h2");
  EXPECT_EQ(a.back(), "exec plexus");
  EXPECT_NE(std::find(a.begin(), a.end(), "BatchMode=yes"), a.end());
  EXPECT_EQ(ssh_arguments({}, "h", "c").front(), "-T");  // no -F: the user's own config
}

TEST(RemoteProtocol, RequestRoundTripsWithMultiLineScenarioText) {
  RemoteRequest r;
  r.host = "h2";
  r.scenario_text = "name: x\nstep: 0.01\n# \"quoted\" \\ text\n";
  r.scenario_origin = "deploy/scenarios/x.yaml";
  r.sets = {"duration=3", "clock.mode=realtime"};
  r.vendors = {"observer=cyclone"};
  r.domain = 111;
  r.timeout = 2.5;
  r.clock_injection_ns = -7;
  const std::string line = r.to_line();
  EXPECT_EQ(line.find('\n'), std::string::npos);
  const auto back = RemoteRequest::from_line(line, "test");
  EXPECT_EQ(back.scenario_text, r.scenario_text);
  EXPECT_EQ(back.sets, r.sets);
  EXPECT_EQ(back.vendors, r.vendors);
  EXPECT_EQ(back.domain, 111);
  EXPECT_EQ(back.timeout, 2.5);
  EXPECT_EQ(back.clock_injection_ns, -7);
  EXPECT_THROW(RemoteRequest::from_line("request {\"host\": 1}", "test"), std::exception);
  EXPECT_THROW(RemoteRequest::from_line("hello", "test"), std::exception);
}

TEST(RemoteProtocol, HelloCarriesProtocolAndVersion) {
  int protocol = 0;
  std::string version;
  ASSERT_TRUE(parse_hello(hello_line("1.2.3"), protocol, version));
  EXPECT_EQ(protocol, kRemoteProtocol);
  EXPECT_EQ(version, "1.2.3");
  EXPECT_FALSE(parse_hello("bash: plexus: command not found", protocol, version));
  RemoteReady ready{"abc", "/q.yaml", "10.0.0.2", true, 3}, back;
  ASSERT_TRUE(RemoteReady::from_line(ready.to_line(), back));
  EXPECT_EQ(back.digest, "abc");
  EXPECT_TRUE(back.address_found);
  EXPECT_EQ(back.processes, 3);
  EXPECT_FALSE(RemoteReady::from_line("ready {", back));
}

TEST(SystemdUnits, ExecArgumentsAreQuotedAndEscaped) {
  EXPECT_EQ(exec_argument("/opt/bin/plant_simulator"), "/opt/bin/plant_simulator");
  EXPECT_EQ(exec_argument("localisation_observer observer"), "\"localisation_observer observer\"");
  EXPECT_EQ(exec_argument("50%"), "50%%");
  EXPECT_EQ(exec_argument("$HOME"), "$$HOME");
  EXPECT_EQ(exec_argument("a\"b"), "\"a\\\"b\"");
  EXPECT_EQ(unit_word("plant_simulator r1,r2"), "plant_simulator-r1-r2");
}

}  // namespace
}  // namespace plexus::cli
