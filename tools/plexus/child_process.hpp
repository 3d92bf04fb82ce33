// Starting the other plexus executables (services, peers) from the CLI.
#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

namespace plexus::cli {

/// Directory of the running plexus executable (build/bin): services live beside it.
std::string bin_dir();

/// Where a program is: beside plexus (the built-in services and tools); for a user's service,
/// beside a loaded plugin or in its prefix's bin/; else on PATH. Not found: bin_dir()/program.
std::string program_path(const std::string& program);

/// Starts `program_path(program) args...` (stdout and stderr to `output_fd` if >= 0, else
/// inherited); returns its pid. Throws std::runtime_error.
pid_t spawn(const std::string& program, const std::vector<std::string>& args, int output_fd = -1);

/// Runs `program_path(program) args...` to completion, capturing stdout. Returns the exit code.
int run_capture(const std::string& program, const std::vector<std::string>& args, std::string& out);

/// If the child has exited, reaps it and returns true with its exit status in `status`.
bool exited(pid_t pid, int& status);

/// SIGTERM, then waits (SIGKILL after `grace_ms`). Returns the exit status.
int stop(pid_t pid, int grace_ms = 3000);

}  // namespace plexus::cli
