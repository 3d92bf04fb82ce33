// A Fast DDS participant id whose shared-memory port no running writer still holds
// (shm_ports.hpp says why).
#include "shm_ports.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <fstream>
#include <set>
#include <sstream>
#include <string_view>
#include <utility>
#include <vector>

namespace plexus::rt::detail {
namespace {

// The inodes of the files that processes whose memory maps this one may read have mapped (any
// device: /dev/shm is one tmpfs), among `wanted` (empty: all of them). Processes of other
// users are not readable without privileges and so count as mapping nothing.
std::set<unsigned long long> mapped_inodes(const std::set<unsigned long long>& wanted = {}) {
  std::set<unsigned long long> found;
  DIR* proc = opendir("/proc");
  if (proc == nullptr) return found;
  while (const dirent* e = readdir(proc)) {
    if (!std::isdigit(static_cast<unsigned char>(e->d_name[0]))) continue;
    std::ifstream maps(std::string("/proc/") + e->d_name + "/maps");
    std::string line;
    while (std::getline(maps, line)) {
      // address perms offset dev inode path
      std::istringstream f(line);
      std::string address, perms, offset, dev;
      unsigned long long ino = 0;
      if (f >> address >> perms >> offset >> dev >> ino && ino != 0 && (wanted.empty() || wanted.count(ino)))
        found.insert(ino);
    }
  }
  closedir(proc);
  return found;
}

bool mapped_by_any_process(ino_t inode) {
  const auto ino = static_cast<unsigned long long>(inode);
  return mapped_inodes({ino}).count(ino) != 0;
}

// True if the lock file at `path` exists and no other open file holds its lock (its owner is
// gone). Fast DDS's RobustExclusiveLock is an flock on such a file.
bool lock_file_free(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  const bool free = ::flock(fd, LOCK_EX | LOCK_NB) == 0;
  ::close(fd);  // releases it
  return free;
}

// A participant segment's name: "fastrtps_" and 16 hex digits (Fast DDS's segment id).
bool is_participant_segment(const std::string& name) {
  constexpr std::string_view prefix = "fastrtps_";
  if (name.size() != prefix.size() + 16 || name.compare(0, prefix.size(), prefix) != 0) return false;
  for (std::size_t i = prefix.size(); i < name.size(); ++i)
    if (!std::isxdigit(static_cast<unsigned char>(name[i]))) return false;
  return true;
}

}  // namespace

ShmPortState shm_port_state(uint32_t port, const std::string& shm_dir) {
  const std::string segment = shm_dir + "/fastrtps_port" + std::to_string(port);
  const int fd = ::open((segment + "_el").c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return ShmPortState::absent;
  const bool locked_by_other = ::flock(fd, LOCK_EX | LOCK_NB) != 0 && errno == EWOULDBLOCK;
  if (!locked_by_other) ::flock(fd, LOCK_UN);
  ::close(fd);
  if (locked_by_other) return ShmPortState::live;
  struct stat st {};
  if (::stat(segment.c_str(), &st) != 0) return ShmPortState::zombie;  // the lock file alone
  return mapped_by_any_process(st.st_ino) ? ShmPortState::held : ShmPortState::zombie;
}

int pick_shm_participant_id(uint32_t domain, int limit, const RtpsPorts& ports, const std::string& shm_dir) {
  // Fast DDS's own choice: participant 0, its SHM port moved on by the participant gain while a
  // live listener holds it (RTPSParticipantImpl::createReceiverResources, applyLocatorAdaptRule).
  const uint32_t first = ports.base + ports.domain_gain * domain + ports.offset_d3;
  bool passed_held = false;
  for (int p = 0; p < limit; ++p) {
    const uint32_t port = first + ports.participant_gain * static_cast<uint32_t>(p);
    if (port > 65535) break;
    const ShmPortState s = shm_port_state(port, shm_dir);
    if (s == ShmPortState::live) continue;
    if (s == ShmPortState::held) {
      passed_held = true;
      continue;
    }
    return passed_held ? p : -1;
  }
  return -1;
}

int remove_zombie_segments(const std::string& shm_dir) {
  // Candidates first (a directory read and an flock each), /proc only if there are any.
  std::vector<std::pair<std::string, unsigned long long>> segments;  // path, inode
  DIR* dir = opendir(shm_dir.c_str());
  if (dir == nullptr) return 0;
  while (const dirent* e = readdir(dir)) {
    const std::string name = e->d_name;
    if (!is_participant_segment(name)) continue;
    const std::string path = shm_dir + "/" + name;
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0 || !lock_file_free(path + "_el")) continue;
    segments.emplace_back(path, static_cast<unsigned long long>(st.st_ino));
  }
  closedir(dir);
  if (segments.empty()) return 0;
  std::set<unsigned long long> candidates;
  for (const auto& segment : segments) candidates.insert(segment.second);
  const std::set<unsigned long long> mapped = mapped_inodes(candidates);
  int removed = 0;
  for (const auto& [path, ino] : segments) {
    if (mapped.count(ino) != 0) continue;  // a reader still maps it: later
    if (::unlink(path.c_str()) == 0) ++removed;
    ::unlink((path + "_el").c_str());
  }
  return removed;
}

ShmParticipantLock::ShmParticipantLock(const std::string& shm_dir) {
  fd_ = ::open((shm_dir + "/plexus_fastdds_participants.lock").c_str(), O_RDONLY | O_CREAT | O_CLOEXEC, 0666);
  if (fd_ >= 0 && ::flock(fd_, LOCK_EX) != 0) {
    ::close(fd_);
    fd_ = -1;
  }
}

ShmParticipantLock::~ShmParticipantLock() {
  if (fd_ >= 0) ::close(fd_);  // releases the lock
}

}  // namespace plexus::rt::detail
