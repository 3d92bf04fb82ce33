// A child process whose stdin, stdout and stderr are pipes to this one (the ssh session of
// a remote share). It runs in a process group of its own, so a Ctrl-C on the terminal
// reaches the launcher, which then ends the session in order, not ssh directly.
#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

namespace plexus::cli {

struct PipedProcess {
  pid_t pid = 0;
  int in = -1;   ///< write end: its stdin
  int out = -1;  ///< read end: its stdout
  int err = -1;  ///< read end: its stderr
};

/// Starts `path args...` (path searched on $PATH when it has no '/'). The three descriptors
/// are close-on-exec here. Throws std::runtime_error.
PipedProcess spawn_piped(const std::string& path, const std::vector<std::string>& args);

/// Closes whichever of the three descriptors are open.
void close_pipes(PipedProcess& p);

}  // namespace plexus::cli
