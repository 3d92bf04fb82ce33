#include "external_program.hpp"

#include <fcntl.h>
#include <spawn.h>
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
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  if (!output.file.empty()) {
    posix_spawn_file_actions_addopen(&fa, STDOUT_FILENO, output.file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&fa, STDOUT_FILENO, STDERR_FILENO);
  } else if (output.fd >= 0) {
    posix_spawn_file_actions_adddup2(&fa, output.fd, STDOUT_FILENO);  // dup2 clears close-on-exec
    posix_spawn_file_actions_adddup2(&fa, output.fd, STDERR_FILENO);
  }
  auto argv = argv_of(path, args);
  Env e(env);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, path.c_str(), &fa, nullptr, argv.data(), e.ptrs.data());
  posix_spawn_file_actions_destroy(&fa);
  if (rc != 0) throw std::runtime_error("cannot start " + path);
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
