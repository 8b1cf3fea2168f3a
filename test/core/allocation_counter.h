#pragma once
// Counts heap allocations while a test says so: proves that a per-frame path allocates nothing.
// Replaces the global operator new/delete, so include it in exactly one file of a test program.

#include <atomic>
#include <cstdlib>
#include <new>

namespace {
std::atomic<bool> counting_allocations{false};
std::atomic<long> allocation_count{0};
}  // namespace

// noinline: GCC would otherwise pair the malloc/free it sees with the new/delete expressions
// of the library and warn (-Wmismatched-new-delete).
__attribute__((noinline)) void* operator new(std::size_t size) {
  if (counting_allocations.load(std::memory_order_relaxed)) ++allocation_count;
  if (void* memory = std::malloc(size == 0 ? 1 : size)) return memory;
  throw std::bad_alloc();
}
__attribute__((noinline)) void operator delete(void* memory) noexcept { std::free(memory); }
__attribute__((noinline)) void operator delete(void* memory, std::size_t) noexcept { std::free(memory); }
