// Test support: replaces the global operator new of a test binary with a counting one, so a
// test can check that a hot path does not allocate:
//
//   const long before = plexus::test::allocations();
//   ... hot path ...
//   EXPECT_EQ(plexus::test::allocations() - before, 0);
//
// Include it from exactly one source file per test executable (the family's
// no_allocation_test.cpp): the replacement operators are definitions, not declarations.
#pragma once

#include <atomic>
#include <cstdlib>
#include <new>

namespace plexus::test {
inline std::atomic<long> g_allocations{0};
inline long allocations() { return g_allocations.load(); }
}  // namespace plexus::test

void* operator new(std::size_t n) {
  ++plexus::test::g_allocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
