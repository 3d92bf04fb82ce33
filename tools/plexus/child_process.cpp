#include "child_process.hpp"

#include "external_program.hpp"

#include <signal.h>
#include <sys/wait.h>

#include <chrono>
#include <filesystem>
#include <thread>

namespace plexus::cli {

std::string bin_dir() { return std::filesystem::read_symlink("/proc/self/exe").parent_path().string(); }

pid_t spawn(const std::string& program, const std::vector<std::string>& args, int output_fd) {
  return spawn_program(bin_dir() + "/" + program, args, {}, {.file = {}, .fd = output_fd});
}

int run_capture(const std::string& program, const std::vector<std::string>& args, std::string& out) {
  return run_program(bin_dir() + "/" + program, args, out);
}

bool exited(pid_t pid, int& status) {
  int st = 0;
  if (waitpid(pid, &st, WNOHANG) != pid) return false;
  status = WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
  return true;
}

int stop(pid_t pid, int grace_ms) {
  kill(pid, SIGTERM);
  int status = 0;
  for (int waited = 0; waited < grace_ms; waited += 10) {
    if (waitpid(pid, &status, WNOHANG) == pid) return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  kill(pid, SIGKILL);
  waitpid(pid, &status, 0);
  return 128 + SIGKILL;
}

}  // namespace plexus::cli
