// contact_loads.hpp: the forward problem with the reactions of contacts on the rod (issue 45):
// line forces linear between their ends (N/m) and point forces (N), all in the world frame, on
// top of the rod's distributed load:
//   n' = -(f + Σ λ_k(s)),   n(s⁺) = n(s⁻) - F_j at a point force F_j at s_j.
// The rod is integrated with the classical Runge–Kutta method on its nodes s_i = i L / N with
// every end of a line force and every point force as an extra break point, so that each step sees
// a load linear in s and the method keeps its fourth order.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/core/obstacle.hpp"
#include "rodshape/core/pose.hpp"
#include "rodshape/core/rod_configuration.hpp"
#include "rodshape/core/wrench.hpp"

namespace rodshape {

/// A force per length f(s) = f0 + (s - s0)/(s1 - s0) (f1 - f0) on [s0, s1], zero elsewhere; or,
/// with `normal_of`, a reaction normal to that obstacle where the rod is: f(s) = λ(s) ∇d(p(s)),
/// λ linear from lambda0 to lambda1 (N/m; frictionless contact).
struct LineForce {
  double s0 = 0.0, s1 = 0.0;
  Eigen::Vector3d f0 = Eigen::Vector3d::Zero(), f1 = Eigen::Vector3d::Zero();
  const Obstacle* normal_of = nullptr;
  double lambda0 = 0.0, lambda1 = 0.0;
};

/// A force on the rod at s (0 < s < L): `force`, or with `normal_of`, magnitude ∇d(p(s)).
struct PointForce {
  double s = 0.0;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  const Obstacle* normal_of = nullptr;
  double magnitude = 0.0;
};

struct ContactLoads {
  std::vector<LineForce> line_forces;
  std::vector<PointForce> point_forces;
  bool empty() const { return line_forces.empty() && point_forces.empty(); }
};

/// The rod's state at one s: its pose, internal wrench and rates p' and R' = R û.
struct RodPoint {
  double s = 0.0;
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d n = Eigen::Vector3d::Zero(), m = Eigen::Vector3d::Zero();
  Eigen::Vector3d p_prime = Eigen::Vector3d::UnitZ();  // R v
  Eigen::Vector3d u = Eigen::Vector3d::Zero();         // body curvature
};

/// The state on both sides of a point force (or at a probe, where both are the same).
struct RodPointPair {
  RodPoint before, after;
};

/// Integrates `rod` from the base wrench with `loads` into `out` (Output::Full, no derivatives:
/// the node values, energy included; n at a node carrying a point force is n(s⁻)). `probes` (any
/// s in [0, L]) become break points too; `at_probes` gets the state on both sides of each, in the
/// order given (`before` = `after` unless a point force sits there). Line forces and point forces
/// outside [0, L] are ignored; the rod is not validated here.
void integrate_with_contact_loads(const ClampedRod& rod,
                                  const BaseWrench& base_wrench,
                                  const ContactLoads& loads,
                                  RodConfiguration& out,
                                  const std::vector<double>& probes = {},
                                  std::vector<RodPointPair>* at_probes = nullptr);

}  // namespace rodshape
