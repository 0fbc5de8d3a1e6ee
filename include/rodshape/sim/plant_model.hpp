// plant_model.hpp: the "real" rod of a simulated experiment, whose parameters may differ from the
// planner's model: a stiffness scale (one factor for all, and one per stiffness), its length, its
// mass per length and gravity (the paper's planner neglects gravity; the real band weighs 1.6 N
// over 0.29 m), a rest curvature, and where the gripper really holds it (the actual tip pose in the
// commanded tip frame).
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/core/pose.hpp"

namespace rodshape {

/// Factors on the planner's stiffnesses, each > 0.
struct StiffnessFactors {
  double EA = 1.0, GA = 1.0, EIx = 1.0, EIy = 1.0, GJ = 1.0;
};

struct PlantModel {
  double stiffness_scale = 1.0;  // on every stiffness, > 0
  StiffnessFactors factors;      // on each one, after the scale
  std::optional<double> length;  // m, > 0; the planner's when absent
  std::optional<double>
      mass_per_length;  // the plant's own ρA, kg/m, ≥ 0; the planner's when absent
  /// The one gravity that acts on the real rod (m/s², world frame); planner_gravity when absent.
  std::optional<Eigen::Vector3d> gravity;
  /// The gravity of the planner's model (a task's top-level `gravity`): the planned rod's load
  /// holds its weight ρA × planner_gravity, which the plant's own weight replaces.
  Eigen::Vector3d planner_gravity = Eigen::Vector3d::Zero();
  std::optional<Eigen::Vector3d> rest_curvature;  // ũ, 1/m; the planner's when absent
  /// The tip's actual pose in the commanded tip frame (commanded_T_actual): a grasp that slipped
  /// or was placed a little off.
  Pose grasp_offset;
  /// The plant that drives the rod, by its name in plant_factory.hpp: "quasi_static" (the only one
  /// today: the held equilibrium solved sample by sample, plant.hpp).
  std::string model = "quasi_static";

  /// Throws InputError naming the field ("PlantModel.stiffness_scale = 0 must be > 0", …).
  void validate() const;
  /// The gravity the plant's weight comes from: `gravity`, else `planner_gravity`.
  Eigen::Vector3d acting_gravity() const { return gravity.value_or(planner_gravity); }
  /// The planner's rod as the plant has it: stiffnesses scaled, its length (the nodes keep their
  /// count), its rest curvature, and the planner's loads with the planner's weight
  /// (planned ρA × planner_gravity) replaced by the plant's, mass_per_length × acting_gravity().
  ClampedRod real_rod(const ClampedRod& planned) const;
};

}  // namespace rodshape
