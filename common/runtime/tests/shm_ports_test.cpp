// The states of a Fast DDS SHM port and the participant id plexus picks from them
// (src/fastdds/shm_ports.hpp), on a scratch directory standing in for /dev/shm.
#include <fcntl.h>
#include <sys/file.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "fastdds/shm_ports.hpp"

namespace {

using plexus::rt::detail::pick_shm_participant_id;
using plexus::rt::detail::RtpsPorts;
using plexus::rt::detail::shm_port_state;
using plexus::rt::detail::ShmPortState;
namespace fs = std::filesystem;

class ShmPorts : public ::testing::Test {
 protected:
  void SetUp() override {
    char tmpl[] = "/tmp/plexus_shm_ports_XXXXXX";
    ASSERT_NE(mkdtemp(tmpl), nullptr);
    dir_ = tmpl;
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string file(uint32_t port, const char* suffix = "") const {
    return dir_ + "/fastrtps_port" + std::to_string(port) + suffix;
  }
  void touch(const std::string& path, std::size_t size = 0) const { std::ofstream(path) << std::string(size, 'x'); }
  std::string dir_;
};

// A lock file whose lock a live listener holds (here: this process, through another open
// file description, as Fast DDS's RobustExclusiveLock does).
struct HeldLock {
  explicit HeldLock(const std::string& path) : fd(::open(path.c_str(), O_RDONLY)) { ::flock(fd, LOCK_EX); }
  ~HeldLock() { ::close(fd); }
  int fd;
};

TEST_F(ShmPorts, NoLockFileIsAbsent) { EXPECT_EQ(shm_port_state(7411, dir_), ShmPortState::absent); }

TEST_F(ShmPorts, LockedLockFileIsLive) {
  touch(file(7411, "_el"));
  touch(file(7411), 64);
  HeldLock lock(file(7411, "_el"));
  EXPECT_EQ(shm_port_state(7411, dir_), ShmPortState::live);
}

TEST_F(ShmPorts, FreeLockFileOfAnUnmappedSegmentIsZombie) {
  touch(file(7411, "_el"));
  EXPECT_EQ(shm_port_state(7411, dir_), ShmPortState::zombie);  // no segment at all
  touch(file(7411), 64);
  EXPECT_EQ(shm_port_state(7411, dir_), ShmPortState::zombie);  // a segment nobody maps
}

TEST_F(ShmPorts, FreeLockFileOfAMappedSegmentIsHeld) {
  // A writer that opened the port before its listener died still maps the segment.
  touch(file(7411, "_el"));
  touch(file(7411), 4096);
  const int fd = ::open(file(7411).c_str(), O_RDWR);
  ASSERT_GE(fd, 0);
  void* map = ::mmap(nullptr, 4096, PROT_READ, MAP_SHARED, fd, 0);
  ::close(fd);
  ASSERT_NE(map, MAP_FAILED);
  EXPECT_EQ(shm_port_state(7411, dir_), ShmPortState::held);
  ::munmap(map, 4096);
  EXPECT_EQ(shm_port_state(7411, dir_), ShmPortState::zombie);
}

// Domain 0 with a port base of its own: user ports 20011 + 2 p.
const RtpsPorts kPorts{20000, 250, 2, 11};

TEST_F(ShmPorts, LeavesTheChoiceToFastDdsUnlessItsPortIsHeld) {
  EXPECT_EQ(pick_shm_participant_id(0, 8, kPorts, dir_), -1);  // nothing there
  touch(file(20011, "_el"));
  touch(file(20011), 4096);
  HeldLock live(file(20011, "_el"));  // participant 0: a live listener, Fast DDS moves on
  touch(file(20013, "_el"));          // participant 1: dead, nobody maps its segment
  EXPECT_EQ(pick_shm_participant_id(0, 8, kPorts, dir_), -1);
}

TEST_F(ShmPorts, PicksTheFirstIdPastAHeldPort) {
  touch(file(20011, "_el"));
  touch(file(20011), 4096);
  HeldLock live(file(20011, "_el"));  // participant 0: live
  touch(file(20013, "_el"));
  touch(file(20013), 4096);  // participant 1: dead, its segment still mapped by a writer
  const int fd = ::open(file(20013).c_str(), O_RDWR);
  void* map = ::mmap(nullptr, 4096, PROT_READ, MAP_SHARED, fd, 0);
  ::close(fd);
  ASSERT_NE(map, MAP_FAILED);
  touch(file(20015, "_el"));
  touch(file(20015), 4096);
  HeldLock live2(file(20015, "_el"));  // participant 2: live
  // participant 3: nothing there
  EXPECT_EQ(pick_shm_participant_id(0, 8, kPorts, dir_), 3);
  EXPECT_EQ(pick_shm_participant_id(0, 3, kPorts, dir_), -1);  // no id below 3 will do
  ::munmap(map, 4096);
  EXPECT_EQ(pick_shm_participant_id(0, 8, kPorts, dir_), -1);  // the zombie is harmless now
}

TEST_F(ShmPorts, RemovesOnlyTheSegmentsOfDeadParticipants) {
  const std::string dead = dir_ + "/fastrtps_0123456789abcdef";    // lock free, nobody maps it
  const std::string live = dir_ + "/fastrtps_fedcba9876543210";    // its owner holds the lock
  const std::string mapped = dir_ + "/fastrtps_00000000000000aa";  // lock free, a reader maps it
  const std::string odd = dir_ + "/fastrtps_0123";                 // not a participant segment
  for (const auto& f : {dead, live, mapped, odd}) {
    touch(f, 4096);
    touch(f + "_el");
  }
  touch(file(7411), 4096);  // a dead port: left to Fast DDS and pick_shm_participant_id
  touch(file(7411, "_el"));
  HeldLock owner(live + "_el");
  const int fd = ::open(mapped.c_str(), O_RDWR);
  void* map = ::mmap(nullptr, 4096, PROT_READ, MAP_SHARED, fd, 0);
  ::close(fd);
  ASSERT_NE(map, MAP_FAILED);

  EXPECT_EQ(plexus::rt::detail::remove_zombie_segments(dir_), 1);
  EXPECT_FALSE(fs::exists(dead));
  EXPECT_FALSE(fs::exists(dead + "_el"));
  EXPECT_TRUE(fs::exists(live));
  EXPECT_TRUE(fs::exists(mapped));
  EXPECT_TRUE(fs::exists(odd));
  EXPECT_TRUE(fs::exists(file(7411)));

  ::munmap(map, 4096);
  EXPECT_EQ(plexus::rt::detail::remove_zombie_segments(dir_), 1);  // unmapped now
  EXPECT_FALSE(fs::exists(mapped));
  EXPECT_TRUE(fs::exists(live));
}

TEST_F(ShmPorts, ParticipantLockExcludesAnotherHolder) {
  {
    plexus::rt::detail::ShmParticipantLock lock(dir_);
    const int fd = ::open((dir_ + "/plexus_fastdds_participants.lock").c_str(), O_RDONLY);
    ASSERT_GE(fd, 0);
    EXPECT_NE(::flock(fd, LOCK_EX | LOCK_NB), 0);  // held
    ::close(fd);
  }
  const int fd = ::open((dir_ + "/plexus_fastdds_participants.lock").c_str(), O_RDONLY);
  EXPECT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);  // released
  ::close(fd);
}

}  // namespace
