// test_no_alloc.cpp: integrate() into an already-sized configuration allocates nothing.
//
// Two checks:
//  1. Global operator new/new[] replaced by counting versions: catches std::vector growth,
//     std::string and any `new` in the library (the replacement is program-wide).
//  2. On glibc, malloc/calloc/realloc/posix_memalign/aligned_alloc replaced by counting versions
//     that forward to glibc's own allocator (__libc_*): catches Eigen's dynamic-size allocations in
//     the library, which go through std::malloc, not operator new, so check 1 misses them. Skipped
//     under sanitizers, which interpose malloc themselves.
// Also: the data() pointers of every vector in the configuration are unchanged across the call.
// (EIGEN_RUNTIME_NO_MALLOC is not used: it only checks Eigen code compiled in a TU that defines it,
// and with the other test TUs linked in, the linker may keep their unchecked copies of Eigen's
// inline allocation functions — it does at -O0. Check 2 sees every allocation whatever the TU.)
#include <gtest/gtest.h>
#include <Eigen/Core>

#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <new>
#include <vector>

#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/core/so3.hpp"

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

namespace rodshape {
namespace {

ClampedRod make_rod() {
  ClampedRod rod;
  rod.properties.length = 0.29;
  rod.properties.K_rot = Eigen::Vector3d(0.04, 0.03, 0.028);
  rod.properties.K_tra = Eigen::Vector3d(426.7, 426.7, 1280.0);
  rod.properties.u_rest = Eigen::Vector3d(0.2, 0.0, -0.1);
  rod.load = DistributedLoad::gravity(0.5568, Eigen::Vector3d(0.0, 0.0, -9.81));
  rod.clamp.rotation = exp_so3(Eigen::Vector3d(0.1, 0.2, 0.3));
  rod.intervals = 64;
  rod.validate();
  return rod;
}

struct DataPointers {
  std::vector<const void*> pointers;
  explicit DataPointers(const RodConfiguration& c)
      : pointers{c.s.data(),         c.p.data(),     c.R.data(),    c.n.data(),
                 c.m.data(),         c.v.data(),     c.u.data(),    c.dp_dw.data(),
                 c.dtheta_dw.data(), c.dn_dw.data(), c.dm_dw.data()} {}
};

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

TEST(NoAlloc, CountersSeeAnAllocation) {
  // The counters work (else the test below proves nothing): a vector growing inside the window is
  // seen, and (where malloc is counted) so is an Eigen dynamic-size allocation.
  std::vector<double> grows;
  const auto [news, mallocs] = count_allocations([&] { grows.resize(1000); });
  EXPECT_GE(news, 1);
#ifdef RODSHAPE_COUNT_MALLOC
  EXPECT_GE(mallocs, 1);  // our operator new calls malloc
  Eigen::VectorXd dynamic;
  const auto [news_eigen, mallocs_eigen] = count_allocations([&] { dynamic.resize(1000); });
  EXPECT_EQ(news_eigen, 0);
  EXPECT_GE(mallocs_eigen, 1);
  void* volatile raw = nullptr;  // volatile: the compiler may not elide the malloc/free pair
  const auto [news_raw, mallocs_raw] = count_allocations([&] { raw = std::malloc(64); });
  std::free(raw);
  EXPECT_EQ(news_raw, 0);
  EXPECT_EQ(mallocs_raw, 1);
#else
  (void)mallocs;
#endif
}

TEST(NoAlloc, SecondIntegrationIntoASizedConfigurationAllocatesNothing) {
  const ClampedRod rod = make_rod();
  for (Derivatives level : {Derivatives::AllNodes, Derivatives::Tip, Derivatives::None}) {
    RodConfiguration c;
    integrate(rod, {{0.3, -0.2, 0.1}, {0.05, 0.02, -0.01}}, c, level);  // sizes c
    const DataPointers before(c);
    const BaseWrench other{{-0.1, 0.4, 0.2}, {0.01, -0.03, 0.02}};
    const auto [news, mallocs] = count_allocations([&] { integrate(rod, other, c, level); });
    EXPECT_EQ(news, 0) << "operator new calls, level " << static_cast<int>(level);
    EXPECT_EQ(mallocs, 0) << "malloc calls, level " << static_cast<int>(level);
    const DataPointers after(c);
    EXPECT_EQ(before.pointers, after.pointers) << "a vector of the configuration was reallocated";
    EXPECT_EQ(c.nodes(), rod.nodes());
    EXPECT_EQ(c.n.front(), other.force);  // the call did run
  }
}

}  // namespace
}  // namespace rodshape
