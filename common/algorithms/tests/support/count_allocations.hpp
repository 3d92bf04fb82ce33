// Test support: counts every heap allocation of a test binary, so a test can check that a
// hot path does not allocate:
//
//   const long before = plexus::test::allocations();
//   ... hot path ...
//   EXPECT_EQ(plexus::test::allocations() - before, 0);
//
// Both ways onto the heap are counted: the global operator new (replaced here) and the C
// allocation functions, which Eigen's dynamic matrices use (interposed here: a test binary's
// malloc, calloc and realloc count and forward to glibc's). operator new allocates through
// malloc, so each allocation counts once.
//
// Include it from exactly one source file per test executable (the family's
// no_allocation_test.cpp): the replacement functions are definitions, not declarations.
#pragma once

#include <atomic>
#include <cstdlib>
#include <new>

namespace plexus::test {
inline std::atomic<long> g_allocations{0};
inline long allocations() { return g_allocations.load(); }
}  // namespace plexus::test

extern "C" {
void* __libc_malloc(std::size_t n);
void* __libc_calloc(std::size_t n, std::size_t size);
void* __libc_realloc(void* p, std::size_t n);
void* malloc(std::size_t n) {
  ++plexus::test::g_allocations;
  return __libc_malloc(n);
}
void* calloc(std::size_t n, std::size_t size) {
  ++plexus::test::g_allocations;
  return __libc_calloc(n, size);
}
void* realloc(void* p, std::size_t n) {
  ++plexus::test::g_allocations;
  return __libc_realloc(p, n);
}
}

void* operator new(std::size_t n) {
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
