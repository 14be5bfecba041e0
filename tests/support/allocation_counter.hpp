#pragma once
// Counts allocations on the C++ heap by replacing the global operator new and delete.
// Include it in exactly one file of a test binary (the replacement is the whole
// program's); read the count with test::allocations().
#include <atomic>
#include <cstdlib>
#include <new>

namespace linkage::test {
inline std::atomic<long> g_allocations{0};
/// Allocations so far in the whole program.
inline long allocations() { return g_allocations.load(); }
}  // namespace linkage::test

// GCC pairs the inlined replacement delete with the library's new and warns; the pair
// here is matched (malloc/free), so the warning is a false positive in these files only.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"

[[gnu::noinline]] void* operator new(std::size_t size) {
  linkage::test::g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
[[gnu::noinline]] void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  linkage::test::g_allocations.fetch_add(1, std::memory_order_relaxed);
  return std::malloc(size == 0 ? 1 : size);
}
// Every form that frees what the forms above allocate, so no pair mixes these with the
// library's (std::stable_sort's buffer is nothrow-new'd; the sanitizers check the pairs).
[[gnu::noinline]] void* operator new[](std::size_t size) { return ::operator new(size); }
[[gnu::noinline]] void* operator new[](std::size_t size, const std::nothrow_t& tag) noexcept {
  return ::operator new(size, tag);
}
[[gnu::noinline]] void operator delete(void* p) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete(void* p, std::size_t) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete[](void* p) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
