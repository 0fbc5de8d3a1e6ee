// test_shape_problem_no_alloc.cpp: ShapeProblem::evaluate() allocates nothing after construction
// (the first call included), with every kind of constraint row and cost term active.
//
// The counting machinery is that of tests/core/test_no_alloc.cpp (which explains it): the global
// operator new/new[] replaced by counting versions, and on glibc without sanitizers malloc & co.
// replaced by counting versions that forward to glibc. Both replacements are program-wide: this
// executable (rodshape_tests_optimisation) must hold no other.
#include <gtest/gtest.h>
#include <Eigen/Core>

#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <new>
#include <string>
#include <vector>

#include "rodshape/core/so3.hpp"
#include "rodshape/optimisation/shape_problem.hpp"

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

ShapeProblem make_problem(ConstitutiveModel model, bool squared) {
  ClampedRod rod;
  rod.properties.length = 0.29;
  rod.properties.model = model;
  rod.properties.K_rot = Eigen::Vector3d(0.04, 0.04, 0.028);
  rod.properties.K_tra = Eigen::Vector3d(426.67, 426.67, 1280.0);
  rod.properties.u_rest = Eigen::Vector3d(0.5, -0.3, 1.0);
  rod.load = DistributedLoad::gravity(0.5568, Eigen::Vector3d(0.0, 0.0, -9.81));
  rod.clamp.rotation = exp_so3(Eigen::Vector3d(0.1, 0.2, 0.3));
  rod.intervals = 32;
  rod.validate();
  ShapeTarget target;
  target.points = {{0.02, 0.05, 0.1}, {0.0, 0.1, 0.2}, {-0.03, 0.12, 0.22}};
  target.squared_distances = squared;
  Workspace ws;
  ws.box = Workspace::Box{Eigen::Vector3d::Constant(-1.0), Eigen::Vector3d::Constant(1.0)};
  ws.inside.push_back({Eigen::Vector3d::Zero(), 0.5});
  ws.outside.push_back({Eigen::Vector3d(0.3, 0.0, 0.0), 0.05});
  ws.half_spaces.push_back({Eigen::Vector3d(0.0, 0.0, 1.0), 0.4});
  Grasp grasp;
  grasp.zero_wrench = {true, false, true, true, false, false};
  StrainLimits limits;
  limits.max_curvature = 20.0;
  limits.max_axial_strain = 0.05;
  return ShapeProblem(rod, target, ws, grasp, limits);
}

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

TEST(ShapeProblemNoAlloc, CountersSeeAnAllocation) {
  std::vector<double> grows;
  const auto [news, mallocs] = count_allocations([&] { grows.resize(1000); });
  EXPECT_GE(news, 1);
#ifdef RODSHAPE_COUNT_MALLOC
  EXPECT_GE(mallocs, 1);
  Eigen::VectorXd dynamic;
  const auto [news_eigen, mallocs_eigen] = count_allocations([&] { dynamic.resize(1000); });
  EXPECT_EQ(news_eigen, 0);
  EXPECT_GE(mallocs_eigen, 1);
#else
  (void)mallocs;
#endif
}

TEST(ShapeProblemNoAlloc, EvaluateAllocatesNothingAfterConstruction) {
  for (ConstitutiveModel model : {ConstitutiveModel::Cosserat, ConstitutiveModel::Kirchhoff}) {
    for (bool squared : {false, true}) {
      ShapeProblem problem = make_problem(model, squared);
      Vector6d w1, w2;
      w1 << 0.1, -0.2, 0.3, 0.05, -0.02, 0.01;
      w2 << -0.2, 0.1, 0.4, -0.03, 0.04, 0.02;
      const std::string label = to_string(model) + (squared ? ", squared" : ", plain");
      // The first call after construction, a new w, the cached w.
      for (const Vector6d* w : {&w1, &w2, &w2}) {
        const auto [news, mallocs] = count_allocations([&] { problem.evaluate(*w); });
        EXPECT_EQ(news, 0) << "operator new calls, " << label;
        EXPECT_EQ(mallocs, 0) << "malloc calls, " << label;
      }
      EXPECT_EQ(problem.configuration().n.front(), w2.head<3>());  // the calls did run
      EXPECT_GE(problem.constraint_count(), 6 + 3 + 33);           // workspace, grasp, curvature
      EXPECT_GT(problem.cost(), 0.0);
    }
  }
}

}  // namespace
}  // namespace rodshape
