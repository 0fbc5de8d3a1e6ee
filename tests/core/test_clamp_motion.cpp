// test_clamp_motion.cpp: move_with_clamp against integrate() at the moved clamp. Without a load
// both are the same configuration (clamp_motion.hpp), so the only difference is round-off: the
// integration's over 20–40 Runge–Kutta steps and the move's few products, a few ε per unit of each
// quantity's size (seen: ≤ 4e-15). The tolerance is 1e-12 per unit size; a wrong factor (Bᵀ
// missing on the right, Q applied to a body-frame angle) errs by O(1), and with gravity (which
// does not turn with the clamp) the move errs by ~1e-3 m.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "rodshape/core/clamp_motion.hpp"
#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/core/so3.hpp"

namespace rodshape {
namespace {

constexpr double kTolerance = 1e-12;  // per unit size, see above

ClampedRod precurved_band(ConstitutiveModel model, int substeps) {
  ClampedRod rod;
  rod.properties.length = 0.29;
  rod.properties.model = model;
  rod.properties.K_rot = Eigen::Vector3d(0.04, 0.03, 0.028);
  rod.properties.K_tra = Eigen::Vector3d(30.0, 40.0, 1280.0);
  rod.properties.u_rest = Eigen::Vector3d(0.5, -0.3, 1.0);
  rod.properties.mass_per_length = 0.5568;
  rod.clamp.position = Eigen::Vector3d(0.1, 0.2, 0.3);
  rod.clamp.rotation = exp_so3(Eigen::Vector3d(0.2, -0.5, 0.3));
  rod.intervals = 20;
  rod.substeps = substeps;
  rod.validate();
  return rod;
}

/// The body-frame wrench (bends the band by O(1) rad in 3D and twists it) in the world at `clamp`.
BaseWrench world_wrench(const Pose& clamp, double L) {
  constexpr double kEI = 0.035;
  const Eigen::Vector3d n_b = Eigen::Vector3d(0.6, -0.4, 0.3) * (kEI / (L * L));
  const Eigen::Vector3d m_b = Eigen::Vector3d(0.7, -0.5, 0.4) * (kEI / L);
  return {clamp.rotation * n_b, clamp.rotation * m_b};
}

double largest(const std::vector<Matrix36d>& a) {
  double most = 0.0;
  for (const Matrix36d& m : a) most = std::max(most, m.cwiseAbs().maxCoeff());
  return most;
}

double worst(const std::vector<Matrix36d>& a, const std::vector<Matrix36d>& b) {
  double most = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
    most = std::max(most, (a[i] - b[i]).cwiseAbs().maxCoeff());
  return most;
}

/// The largest difference between the moved and integrated configurations, per unit size.
double relative_difference(const RodConfiguration& moved, const RodConfiguration& direct) {
  double p = 0.0, R = 0.0, n = 0.0, m = 0.0, size_p = 1e-300, size_n = 1e-300, size_m = 1e-300;
  for (int i = 0; i < direct.nodes(); ++i) {
    p = std::max(p, (moved.p[i] - direct.p[i]).cwiseAbs().maxCoeff());
    R = std::max(R, (moved.R[i] - direct.R[i]).cwiseAbs().maxCoeff());
    n = std::max(n, (moved.n[i] - direct.n[i]).cwiseAbs().maxCoeff());
    m = std::max(m, (moved.m[i] - direct.m[i]).cwiseAbs().maxCoeff());
    size_p = std::max(size_p, direct.p[i].cwiseAbs().maxCoeff());
    size_n = std::max(size_n, direct.n[i].cwiseAbs().maxCoeff());
    size_m = std::max(size_m, direct.m[i].cwiseAbs().maxCoeff());
  }
  double error = std::max({p / size_p, R, n / size_n, m / size_m,
                           std::abs(moved.energy - direct.energy) / direct.energy});
  for (auto member : {&RodConfiguration::dp_dw, &RodConfiguration::dtheta_dw,
                      &RodConfiguration::dn_dw, &RodConfiguration::dm_dw})
    error = std::max(error, worst(moved.*member, direct.*member) / largest(direct.*member));
  const Matrix36d tips[] = {moved.tip_dp_dw - direct.tip_dp_dw,
                            moved.tip_dtheta_dw - direct.tip_dtheta_dw,
                            moved.tip_dn_dw - direct.tip_dn_dw, moved.tip_dm_dw - direct.tip_dm_dw};
  const Matrix36d sizes[] = {direct.tip_dp_dw, direct.tip_dtheta_dw, direct.tip_dn_dw,
                             direct.tip_dm_dw};
  for (int k = 0; k < 4; ++k)
    error = std::max(error, tips[k].cwiseAbs().maxCoeff() / sizes[k].cwiseAbs().maxCoeff());
  error = std::max(error, (moved.denergy_dw - direct.denergy_dw).cwiseAbs().maxCoeff() /
                              direct.denergy_dw.cwiseAbs().maxCoeff());
  for (int i = 0; i < direct.nodes(); ++i)
    error = std::max({error, (moved.v[i] - direct.v[i]).cwiseAbs().maxCoeff(),
                      (moved.u[i] - direct.u[i]).cwiseAbs().maxCoeff()});
  return error;
}

TEST(ClampMotion, MovedConfigurationIsTheIntegrationAtTheMovedClampWithItsDerivatives) {
  for (ConstitutiveModel model : {ConstitutiveModel::Cosserat, ConstitutiveModel::Kirchhoff}) {
    for (int substeps : {1, 2}) {
      const ClampedRod rod = precurved_band(model, substeps);
      const double L = rod.properties.length;
      const RodConfiguration c = integrate(rod, world_wrench(rod.clamp, L), Derivatives::AllNodes);
      ClampedRod moved = rod;
      moved.clamp.position += Eigen::Vector3d(0.05, -0.12, 0.07);
      moved.clamp.rotation = exp_so3(Eigen::Vector3d(-0.9, 1.4, 0.6)) * rod.clamp.rotation;
      const RodConfiguration direct =
          integrate(moved, world_wrench(moved.clamp, L), Derivatives::AllNodes);
      RodConfiguration carried;
      move_with_clamp(c, rod.clamp, moved.clamp, carried);
      ASSERT_EQ(carried.nodes(), direct.nodes());
      EXPECT_EQ(carried.derivatives, Derivatives::AllNodes);
      const double error = relative_difference(carried, direct);
      EXPECT_LT(error, kTolerance) << to_string(model) << ", substeps " << substeps;
      char text[32];
      std::snprintf(text, sizeof text, "%.2e", error);
      RecordProperty("error_" + to_string(model) + "_" + std::to_string(substeps), text);
    }
  }
}

TEST(ClampMotion, LoadedRodDoesNotMoveRigidly) {
  ClampedRod rod = precurved_band(ConstitutiveModel::Cosserat, 1);
  rod.load = DistributedLoad::gravity(0.5568, Eigen::Vector3d(0.0, 0.0, -9.81));
  const double L = rod.properties.length;
  const RodConfiguration c = integrate(rod, world_wrench(rod.clamp, L), Derivatives::AllNodes);
  ClampedRod moved = rod;
  moved.clamp.rotation = exp_so3(Eigen::Vector3d(-0.9, 1.4, 0.6)) * rod.clamp.rotation;
  const RodConfiguration direct =
      integrate(moved, world_wrench(moved.clamp, L), Derivatives::AllNodes);
  RodConfiguration carried;
  move_with_clamp(c, rod.clamp, moved.clamp, carried);
  EXPECT_GT((carried.p.back() - direct.p.back()).norm(), 1e-4);
}

}  // namespace
}  // namespace rodshape
