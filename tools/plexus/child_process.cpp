#include "child_process.hpp"

#include "external_program.hpp"
#include "plexus/scenario/plugins.hpp"

#include <signal.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <thread>

namespace plexus::cli {

std::string bin_dir() { return std::filesystem::read_symlink("/proc/self/exe").parent_path().string(); }

std::string program_path(const std::string& program) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path own = fs::path(bin_dir()) / program;
  if (fs::exists(own, ec)) return own.string();
  // A user's service: beside the plugin that declares it, or in the bin/ of that plugin's prefix.
  for (const auto& lib : scenario::loaded_plugins()) {
    const fs::path dir = fs::path(lib).parent_path();
    for (const fs::path& p : {dir / program, dir / ".." / "bin" / program})
      if (fs::exists(p, ec)) return fs::weakly_canonical(p, ec).string();
  }
  if (const char* path = std::getenv("PATH")) {
    std::string dirs = path;
    for (std::size_t start = 0; start <= dirs.size();) {
      const std::size_t end = std::min(dirs.find(':', start), dirs.size());
      const fs::path p = fs::path(dirs.substr(start, end - start)) / program;
      if (end > start && fs::exists(p, ec)) return p.string();
      start = end + 1;
    }
  }
  return own.string();  // not found: the start fails naming this path
}

pid_t spawn(const std::string& program, const std::vector<std::string>& args, int output_fd) {
  return spawn_program(program_path(program), args, {}, {.file = {}, .fd = output_fd});
}

int run_capture(const std::string& program, const std::vector<std::string>& args, std::string& out) {
  return run_program(program_path(program), args, out);
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
