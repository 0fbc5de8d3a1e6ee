// test_no_alloc.cpp: integrate() and base_pose_derivatives() into an already-sized configuration
// allocate nothing.
//
// The counters (operator new everywhere; malloc & co. on glibc without sanitizers) are
// tests/support/allocation_counter.hpp, which explains them. Also checked: the data() pointers of
// every vector in the configuration are unchanged across the call.
// (EIGEN_RUNTIME_NO_MALLOC is not used: it only checks Eigen code compiled in a TU that defines it,
// and with the other test TUs linked in, the linker may keep their unchecked copies of Eigen's
// inline allocation functions — it does at -O0. The malloc counter sees every allocation.)
#include <gtest/gtest.h>
#include <Eigen/Core>

#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <new>
#include <vector>

#include "rodshape/core/base_pose_derivatives.hpp"
#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/core/so3.hpp"
#include "support/allocation_counter.hpp"

namespace rodshape {
namespace test_no_alloc {
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

using testing::count_allocations;

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

TEST(NoAlloc, SecondTipOnlyIntegrationIntoASizedConfigurationAllocatesNothing) {
  const ClampedRod rod = make_rod();
  for (Derivatives level : {Derivatives::Tip, Derivatives::None}) {
    RodConfiguration c;
    integrate(rod, {{0.3, -0.2, 0.1}, {0.05, 0.02, -0.01}}, c, level, Output::Tip);  // sizes c
    const DataPointers before(c);
    const BaseWrench other{{-0.1, 0.4, 0.2}, {0.01, -0.03, 0.02}};
    const auto [news, mallocs] =
        count_allocations([&] { integrate(rod, other, c, level, Output::Tip); });
    EXPECT_EQ(news, 0) << "operator new calls, level " << static_cast<int>(level);
    EXPECT_EQ(mallocs, 0) << "malloc calls, level " << static_cast<int>(level);
    const DataPointers after(c);
    EXPECT_EQ(before.pointers, after.pointers) << "a vector of the configuration was reallocated";
    EXPECT_EQ(c.nodes(), 2);
    EXPECT_EQ(c.n.front(), other.force);  // the call did run
  }
}

TEST(NoAlloc, SecondBasePoseDerivativesIntoASizedConfigurationAllocatesNothing) {
  ClampedRod rod = make_rod();
  // With the load pass (gravity and a moment load) and without it (no load).
  for (const bool loaded : {true, false}) {
    if (loaded) {
      rod.load.moment = Eigen::Vector3d(0.1, -0.2, 0.05);
    } else {
      rod.load = DistributedLoad{};
    }
    const RodConfiguration c =
        integrate(rod, {{0.3, -0.2, 0.1}, {0.05, 0.02, -0.01}}, Derivatives::AllNodes);
    RodConfiguration out;
    base_pose_derivatives(rod, c, out);  // sizes out
    const DataPointers before(out);
    const RodConfiguration other =
        integrate(rod, {{-0.1, 0.4, 0.2}, {0.01, -0.03, 0.02}}, Derivatives::AllNodes);
    const auto [news, mallocs] = count_allocations([&] { base_pose_derivatives(rod, other, out); });
    EXPECT_EQ(news, 0) << "operator new calls, loaded " << loaded;
    EXPECT_EQ(mallocs, 0) << "malloc calls, loaded " << loaded;
    const DataPointers after(out);
    EXPECT_EQ(before.pointers, after.pointers) << "a vector of the configuration was reallocated";
    EXPECT_EQ(out.nodes(), rod.nodes());
    EXPECT_EQ(out.n.front(), other.n.front());  // the call did run
  }
}

}  // namespace
}  // namespace test_no_alloc
}  // namespace rodshape
