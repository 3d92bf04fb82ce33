// Running system programs (ddsperf, cyclictest, gnuplot) from plexus subcommands.
#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

namespace plexus::cli {

/// Path of `name` on $PATH, or "" if it is not installed.
std::string find_program(const std::string& name);

/// Where a started program's stdout and stderr go: inherited (default), a file, or an
/// open descriptor (e.g. a LogRelay pipe).
struct ProgramOutput {
  std::string file;
  int fd = -1;
};

/// Starts `path args...` with extra environment entries ("KEY=VALUE") and its stdout and
/// stderr to `output`. The child gets SIGTERM when the thread that started it ends, or this
/// process dies, even by SIGKILL (PR_SET_PDEATHSIG, set before exec: no window in which the
/// parent's death goes unnoticed), so no child outlives plexus. Returns the pid; throws
/// std::runtime_error (a program that cannot be executed exits 127).
pid_t spawn_program(const std::string& path, const std::vector<std::string>& args,
                    const std::vector<std::string>& env = {}, const ProgramOutput& output = {});

/// Runs `path args...` to completion with stdout (and stderr, if merge_stderr) captured.
/// Returns the exit code (128+signal if killed).
int run_program(const std::string& path, const std::vector<std::string>& args, std::string& out,
                const std::vector<std::string>& env = {}, bool merge_stderr = false);

/// Waits for pid; returns its exit code (128+signal if killed).
int wait_program(pid_t pid);

}  // namespace plexus::cli
