#include "rodshape/solvers/stable_equilibrium.hpp"

#include <Eigen/Eigenvalues>
#include <optional>
#include <sstream>
#include <vector>

namespace rodshape {

namespace {

/// The direction across the shape: the axis of least spread of the nodes (the normal of a planar
/// shape), where an imperfection load breaks the shape's symmetry.
Eigen::Vector3d across(const RodConfiguration& configuration) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : configuration.p) mean += p;
  mean /= static_cast<double>(configuration.p.size());
  Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& p : configuration.p) spread += (p - mean) * (p - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> axes(spread);
  return axes.eigenvectors().col(0);  // eigenvalues ascending
}

/// The imperfection's continuation: the rod under `rod.load` + η_k f, η_k = 1, ½, ¼, … down to
/// 1/2^(kHalvings), then without it, each solved directly from the last. Empty when a solve fails.
constexpr int kHalvings = 8;

std::optional<ShootingResult> remove_imperfection(const ClampedRod& rod,
                                                  const TipCondition& tip,
                                                  const BaseWrench& start,
                                                  const Eigen::Vector3d& f,
                                                  const ShootingOptions& direct,
                                                  int& solves) {
  BaseWrench w = start;
  for (int k = 0; k <= kHalvings + 1; ++k) {
    ClampedRod imperfect = rod;
    if (k <= kHalvings) imperfect.load.force += std::ldexp(1.0, -k) * f;
    ShootingResult solved = solve_equilibrium(imperfect, tip, w, direct);
    ++solves;
    if (!solved.summary.converged()) return std::nullopt;
    if (k == kHalvings + 1) return solved;
    w = solved.base_wrench;
  }
  return std::nullopt;
}

}  // namespace

StableEquilibriumResult seek_stable_equilibrium(const ClampedRod& rod,
                                                const TipCondition& tip,
                                                const ShootingResult& unstable,
                                                const StabilityResult& /*verdict*/,
                                                const ShootingOptions& options) {
  ShootingOptions direct = options;
  direct.continuation = false;  // each solve stays on the branch it starts on
  direct.output_derivatives = Derivatives::AllNodes;
  // Load units: EI/L³ per unit length bends the rod by about a radian.
  const double L = rod.properties.length;
  const double EI = 0.5 * (rod.properties.K_rot.x() + rod.properties.K_rot.y());
  const Eigen::Vector3d normal = across(unstable.configuration);
  StableEquilibriumResult result;
  std::optional<ShootingResult> best;
  std::optional<StabilityResult> best_verdict;
  for (const double eta : {0.3, 1.0, 3.0}) {
    for (const double sign : {1.0, -1.0}) {
      const Eigen::Vector3d f = sign * eta * EI / (L * L * L) * normal;
      std::optional<ShootingResult> solved =
          remove_imperfection(rod, tip, unstable.base_wrench, f, direct, result.solves);
      if (!solved) continue;
      ClampedRod at = rod;
      at.substeps = solved->summary.substeps;
      const StabilityResult stability = assess_stability(at, solved->configuration, tip);
      if (!stability.stable) continue;
      if (!best || solved->configuration.energy < best->configuration.energy) {
        best = std::move(solved);
        best_verdict = stability;
      }
    }
    if (!best) continue;
    std::ostringstream message;
    message.precision(3);
    message << "the solve's equilibrium (energy " << unstable.configuration.energy
            << " J) is unstable; a stable one of energy " << best->configuration.energy
            << " J was found by loading the rod across its shape (" << eta
            << " EI/L³ per length) and removing the load step by step";
    result.found = true;
    result.message = message.str();
    result.solution = std::move(*best);
    result.stability = *best_verdict;
    return result;
  }
  result.message = "the solve's equilibrium is unstable, and no stable one was found in " +
                   std::to_string(result.solves) + " solves (imperfection loads across the shape)";
  return result;
}

}  // namespace rodshape
