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
#include <sstream>

namespace plexus::rt::detail {
namespace {

// True if some process whose memory map this one may read maps the file with inode `inode`
// (any device: /dev/shm is one tmpfs). Processes of other users are not readable without
// privileges and so count as not mapping it.
bool mapped_by_any_process(ino_t inode) {
  DIR* proc = opendir("/proc");
  if (proc == nullptr) return false;
  bool found = false;
  while (const dirent* e = readdir(proc)) {
    if (!std::isdigit(static_cast<unsigned char>(e->d_name[0]))) continue;
    std::ifstream maps(std::string("/proc/") + e->d_name + "/maps");
    std::string line;
    while (!found && std::getline(maps, line)) {
      // address perms offset dev inode path
      std::istringstream f(line);
      std::string address, perms, offset, dev;
      unsigned long long ino = 0;
      if (f >> address >> perms >> offset >> dev >> ino && ino == static_cast<unsigned long long>(inode) && ino != 0)
        found = true;
    }
    if (found) break;
  }
  closedir(proc);
  return found;
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
