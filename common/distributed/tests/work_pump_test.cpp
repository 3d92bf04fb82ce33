// WorkPump (src/work_pump.hpp): the lockstep's receive-thread work, run by whichever thread
// pokes, one at a time, never losing a poke, and never after close().
#include "work_pump.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <thread>
#include <vector>

namespace plexus::distributed::detail {
namespace {

// Four threads each "deliver" 200 000 items (a counter) and poke; the work takes what was
// delivered. Never two rounds at once, and once every poke has returned, every item is taken:
// a poke made while another thread was in the work was not lost.
TEST(WorkPump, OneRoundAtATimeAndNoPokeLost) {
  std::atomic<uint64_t> delivered{0};
  std::atomic<int> inside{0};
  std::atomic<bool> overlap{false};
  uint64_t taken = 0;  // the work's own: no atomic needed if rounds never overlap
  struct Work {
    std::atomic<uint64_t>* delivered;
    std::atomic<int>* inside;
    std::atomic<bool>* overlap;
    uint64_t* taken;
    void operator()() const {
      if (inside->fetch_add(1) != 0) overlap->store(true);
      *taken = delivered->load();
      inside->fetch_sub(1);
    }
  };
  WorkPump<Work> pump(Work{&delivered, &inside, &overlap, &taken});
  pump.open();
  constexpr int kThreads = 4;
  constexpr uint64_t kItems = 200'000;
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([&] {
      for (uint64_t i = 0; i < kItems; ++i) {
        delivered.fetch_add(1);
        pump.poke();
      }
    });
  for (auto& t : threads) t.join();
  EXPECT_FALSE(overlap.load());
  EXPECT_EQ(taken, kThreads * kItems);
  pump.close();
}

// Before open() and after close(), pokes do no work; close() waits for a round in progress.
TEST(WorkPump, NoWorkBeforeOpenOrAfterClose) {
  std::atomic<int> rounds{0};
  std::atomic<bool> in_round{false};
  std::atomic<bool> release{false};
  struct Work {
    std::atomic<int>* rounds;
    std::atomic<bool>* in_round;
    std::atomic<bool>* release;
    void operator()() const {
      rounds->fetch_add(1);
      in_round->store(true);
      while (!release->load()) std::this_thread::yield();
      in_round->store(false);
    }
  };
  WorkPump<Work> pump(Work{&rounds, &in_round, &release});
  pump.poke();
  EXPECT_EQ(rounds.load(), 0);
  pump.open();
  std::thread worker([&] { pump.poke(); });
  while (!in_round.load()) std::this_thread::yield();
  std::atomic<bool> closed{false};
  std::thread closer([&] {
    pump.close();
    closed.store(true);
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_FALSE(closed.load());  // the round is still running
  release.store(true);
  closer.join();
  worker.join();
  EXPECT_FALSE(in_round.load());
  const int after_close = rounds.load();
  pump.poke();
  EXPECT_EQ(rounds.load(), after_close);
}

}  // namespace
}  // namespace plexus::distributed::detail
