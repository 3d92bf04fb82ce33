#include "external_program.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <stdexcept>

extern char** environ;

namespace plexus::cli {
namespace {

std::vector<char*> argv_of(const std::string& path, const std::vector<std::string>& args) {
  std::vector<char*> v;
  v.push_back(const_cast<char*>(path.c_str()));
  for (const auto& a : args) v.push_back(const_cast<char*>(a.c_str()));
  v.push_back(nullptr);
  return v;
}

struct Env {
  std::vector<std::string> storage;
  std::vector<char*> ptrs;
  explicit Env(const std::vector<std::string>& extra) {
    for (char** e = environ; *e; ++e) {
      const std::string s(*e);
      bool overridden = false;
      for (const auto& x : extra) overridden = overridden || s.rfind(x.substr(0, x.find('=') + 1), 0) == 0;
      if (!overridden) storage.push_back(s);
    }
    for (const auto& x : extra) storage.push_back(x);
    for (auto& s : storage) ptrs.push_back(s.data());
    ptrs.push_back(nullptr);
  }
};

int status_code(int status) { return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status); }

}  // namespace

std::string find_program(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "/usr/bin:/bin");
  for (std::string d; std::getline(dirs, d, ':');) {
    const std::string p = d + "/" + name;
    if (access(p.c_str(), X_OK) == 0) return p;
  }
  return "";
}

pid_t spawn_program(const std::string& path, const std::vector<std::string>& args, const std::vector<std::string>& env,
                    const ProgramOutput& output) {
  // Everything the child needs is prepared before fork(): after it, in a process with
  // threads, the child may only make system calls until it execs.
  int file_fd = -1;
  if (!output.file.empty()) {
    file_fd = ::open(output.file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (file_fd < 0) throw std::runtime_error("cannot write " + output.file);
  }
  const int out_fd = file_fd >= 0 ? file_fd : output.fd;
  auto argv = argv_of(path, args);
  Env e(env);
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid == 0) {
    // The child never outlives this process: SIGTERM when it dies, even by SIGKILL. If it
    // died before the request was made, the child is already orphaned: give up.
    if (prctl(PR_SET_PDEATHSIG, SIGTERM) != 0 || getppid() != parent) _exit(127);
    if (out_fd >= 0 && (dup2(out_fd, STDOUT_FILENO) < 0 || dup2(out_fd, STDERR_FILENO) < 0)) _exit(127);
    execve(path.c_str(), argv.data(), e.ptrs.data());
    _exit(127);
  }
  if (file_fd >= 0) ::close(file_fd);
  if (pid < 0) throw std::runtime_error("cannot start " + path);
  return pid;
}

int run_program(const std::string& path, const std::vector<std::string>& args, std::string& out,
                const std::vector<std::string>& env, bool merge_stderr) {
  int fds[2];
  if (pipe(fds) != 0) throw std::runtime_error("pipe failed");
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_adddup2(&fa, fds[1], STDOUT_FILENO);
  if (merge_stderr) posix_spawn_file_actions_adddup2(&fa, fds[1], STDERR_FILENO);
  posix_spawn_file_actions_addclose(&fa, fds[0]);
  auto argv = argv_of(path, args);
  Env e(env);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, path.c_str(), &fa, nullptr, argv.data(), e.ptrs.data());
  posix_spawn_file_actions_destroy(&fa);
  close(fds[1]);
  if (rc != 0) {
    close(fds[0]);
    throw std::runtime_error("cannot start " + path);
  }
  std::array<char, 4096> buf;
  for (ssize_t n; (n = read(fds[0], buf.data(), buf.size())) > 0;) out.append(buf.data(), static_cast<std::size_t>(n));
  close(fds[0]);
  return wait_program(pid);
}

int wait_program(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return status_code(status);
}

}  // namespace plexus::cli
