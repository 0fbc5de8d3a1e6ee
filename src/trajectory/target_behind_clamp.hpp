// target_behind_clamp.hpp (private to trajectory): why a plan towards a target behind the clamp
// fails (issue 24, item 5). A clamped rod leaves its clamp along its tangent; a target whose points
// lie behind the clamp (straight below a clamp pointing up) is reached only by a rod that turns
// through up to 180° and loops back past its own clamp, while the objective sets carry the
// target's chain of points about the clamp (intermediate_targets.hpp), asking for a kink there
// that no clamped rod takes. The note says so when such a plan stops or would jump.
#pragma once

#include <string>

#include "rodshape/trajectory/plan_problem.hpp"

namespace rodshape::plan_stages {

/// The angle (rad) between the rod's tangent at the clamp, R(0) ṽ, and the chord from the clamp
/// to the target's first point.
double first_point_angle(const PlanProblem& problem);

/// "; ShapeTarget.points[0] lies 180° from the rod's direction at the clamp ..." when that angle
/// exceeds 90° (the point is behind the clamp), else "".
std::string behind_clamp_note(const PlanProblem& problem);

}  // namespace rodshape::plan_stages
