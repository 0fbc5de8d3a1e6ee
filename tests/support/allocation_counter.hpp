// allocation_counter.hpp: counts heap allocations program-wide, for the no-allocation tests.
//  1. Global operator new/new[] replaced by counting versions: catches std::vector growth,
//     std::string and any `new` in the library.
//  2. On glibc without sanitizers, malloc/calloc/realloc/posix_memalign/aligned_alloc replaced by
//     counting versions that forward to glibc's own allocator (__libc_*): catches Eigen's
//     dynamic-size allocations, which go through std::malloc, not operator new. Sanitizers
//     interpose malloc themselves, so there only (1) runs; RODSHAPE_COUNT_MALLOC says which.
// The replacements are program-wide definitions: include this header in exactly ONE source file of
// a test executable.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <new>
#include <utility>

namespace {

std::atomic<bool> g_counting{false};
std::atomic<long> g_new_calls{0};
std::atomic<long> g_malloc_calls{0};

void* counted_new(std::size_t size) {
  if (g_counting.load(std::memory_order_relaxed))
    g_new_calls.fetch_add(1, std::memory_order_relaxed);
  if (size == 0) size = 1;
  if (void* p = std::malloc(size)) return p;
  throw std::bad_alloc();
}

void* counted_new_aligned(std::size_t size, std::align_val_t alignment) {
  if (g_counting.load(std::memory_order_relaxed))
    g_new_calls.fetch_add(1, std::memory_order_relaxed);
  const std::size_t a = static_cast<std::size_t>(alignment);
  const std::size_t rounded = ((size == 0 ? 1 : size) + a - 1) / a * a;
  if (void* p = std::aligned_alloc(a, rounded)) return p;
  throw std::bad_alloc();
}

}  // namespace

// ---- 2. operator new ----------------------------------------------------------------------------
void* operator new(std::size_t size) { return counted_new(size); }
void* operator new[](std::size_t size) { return counted_new(size); }
void* operator new(std::size_t size, std::align_val_t a) { return counted_new_aligned(size, a); }
void* operator new[](std::size_t size, std::align_val_t a) { return counted_new_aligned(size, a); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  try {
    return counted_new(size);
  } catch (...) {
    return nullptr;
  }
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
  try {
    return counted_new(size);
  } catch (...) {
    return nullptr;
  }
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }

// ---- 3. malloc (glibc, no sanitizers)
// ------------------------------------------------------------
#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(memory_sanitizer) || \
    __has_feature(thread_sanitizer)
#define RODSHAPE_TEST_SANITIZED 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define RODSHAPE_TEST_SANITIZED 1
#endif

#if defined(__GLIBC__) && !defined(RODSHAPE_TEST_SANITIZED)
#define RODSHAPE_COUNT_MALLOC 1
extern "C" {
// glibc's allocator under its exported internal names: replacing malloc by forwarding to these is
// the interposition glibc documents ("Replacing malloc"); free stays glibc's.
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* p, std::size_t size);
void* __libc_memalign(std::size_t alignment, std::size_t size);

static void count_malloc() {
  if (g_counting.load(std::memory_order_relaxed))
    g_malloc_calls.fetch_add(1, std::memory_order_relaxed);
}
void* malloc(std::size_t size) noexcept {
  count_malloc();
  return __libc_malloc(size);
}
void* calloc(std::size_t count, std::size_t size) noexcept {
  count_malloc();
  return __libc_calloc(count, size);
}
void* realloc(void* p, std::size_t size) noexcept {
  count_malloc();
  return __libc_realloc(p, size);
}
int posix_memalign(void** out, std::size_t alignment, std::size_t size) noexcept {
  count_malloc();
  void* p = __libc_memalign(alignment, size);
  if (p == nullptr) return 12;  // ENOMEM
  *out = p;
  return 0;
}
void* aligned_alloc(std::size_t alignment, std::size_t size) noexcept {
  count_malloc();
  return __libc_memalign(alignment, size);
}
}
#endif

namespace rodshape::testing {

/// Runs `call` with every counter armed; returns (operator new calls, malloc calls).
template <typename Call>
std::pair<long, long> count_allocations(Call&& call) {
  g_new_calls = 0;
  g_malloc_calls = 0;
  g_counting = true;
  call();
  g_counting = false;
  return {g_new_calls.load(), g_malloc_calls.load()};
}

}  // namespace rodshape::testing
