// heap_peak.hpp: the peak of the bytes live on the heap through operator new, for the tests of how
// much memory a computation keeps (issue 24: memory per frame). Global operator new/delete are
// replaced by versions that add and subtract each block's usable size (glibc's
// malloc_usable_size); the peak is reset with reset_heap_peak(). The replacements are
// program-wide: include this header in exactly ONE source file of a test executable.
#pragma once

#include <malloc.h>

#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <new>

namespace rodshape::testing {

inline std::atomic<long long> g_heap_live{0};
inline std::atomic<long long> g_heap_peak{0};

inline void heap_add(void* p) {
  const long long live = g_heap_live.fetch_add(static_cast<long long>(malloc_usable_size(p))) +
                         static_cast<long long>(malloc_usable_size(p));
  for (long long peak = g_heap_peak.load();
       live > peak && !g_heap_peak.compare_exchange_weak(peak, live);) {
  }
}

inline void heap_free(void* p) noexcept {
  if (p == nullptr) return;
  g_heap_live.fetch_sub(static_cast<long long>(malloc_usable_size(p)));
  std::free(p);
}

/// Sets the peak to the bytes live now; returns them.
inline long long reset_heap_peak() {
  const long long live = g_heap_live.load();
  g_heap_peak.store(live);
  return live;
}

inline void* heap_allocate(std::size_t size, std::size_t alignment) {
  void* p = alignment <= alignof(std::max_align_t)
                ? std::malloc(size == 0 ? 1 : size)
                : std::aligned_alloc(
                      alignment, ((size == 0 ? 1 : size) + alignment - 1) / alignment * alignment);
  if (p == nullptr) throw std::bad_alloc();
  heap_add(p);
  return p;
}

}  // namespace rodshape::testing

void* operator new(std::size_t size) {
  return rodshape::testing::heap_allocate(size, alignof(std::max_align_t));
}
void* operator new[](std::size_t size) {
  return rodshape::testing::heap_allocate(size, alignof(std::max_align_t));
}
void* operator new(std::size_t size, std::align_val_t a) {
  return rodshape::testing::heap_allocate(size, static_cast<std::size_t>(a));
}
void* operator new[](std::size_t size, std::align_val_t a) {
  return rodshape::testing::heap_allocate(size, static_cast<std::size_t>(a));
}
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  try {
    return rodshape::testing::heap_allocate(size, alignof(std::max_align_t));
  } catch (...) {
    return nullptr;
  }
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
  try {
    return rodshape::testing::heap_allocate(size, alignof(std::max_align_t));
  } catch (...) {
    return nullptr;
  }
}
void operator delete(void* p) noexcept { rodshape::testing::heap_free(p); }
void operator delete[](void* p) noexcept { rodshape::testing::heap_free(p); }
void operator delete(void* p, std::size_t) noexcept { rodshape::testing::heap_free(p); }
void operator delete[](void* p, std::size_t) noexcept { rodshape::testing::heap_free(p); }
void operator delete(void* p, std::align_val_t) noexcept { rodshape::testing::heap_free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { rodshape::testing::heap_free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept {
  rodshape::testing::heap_free(p);
}
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept {
  rodshape::testing::heap_free(p);
}
