// target_behind_clamp.cpp: the note of target_behind_clamp.hpp.
#include "target_behind_clamp.hpp"

#include <cmath>
#include <numbers>

namespace rodshape::plan_stages {

double first_point_angle(const PlanProblem& problem) {
  const Pose& clamp = problem.rod.clamp;
  const Eigen::Vector3d tangent = clamp.rotation * problem.rod.properties.v_rest;
  if (problem.target.points.empty()) return 0.0;
  const Eigen::Vector3d chord = problem.target.points.front() - clamp.position;
  if (chord.norm() == 0.0 || tangent.norm() == 0.0) return 0.0;
  return std::atan2(tangent.cross(chord).norm(), tangent.dot(chord));
}

std::string behind_clamp_note(const PlanProblem& problem) {
  const double angle = first_point_angle(problem);
  if (!(angle > std::numbers::pi / 2)) return "";
  const long degrees = std::lround(angle * 180.0 / std::numbers::pi);
  return "; ShapeTarget.points[0] lies " + std::to_string(degrees) +
         " degrees from the rod's direction at the clamp (behind the clamp): the rod must turn "
         "through up to 180 degrees and loop back past its own clamp to reach the target, while "
         "the objective sets carry the target's points about the clamp as a chain, a kink there "
         "that no clamped rod follows; such a target is not planned (docs/task-file.md, "
         "'Targets behind the clamp')";
}

}  // namespace rodshape::plan_stages
