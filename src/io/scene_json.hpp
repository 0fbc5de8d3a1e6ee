// scene_json.hpp (private to the io area): a plan's scene in plan.json: the obstacles as read (for
// figures and viewers), the clearance and the least gap of the tracked rod (docs/task-file.md).
#pragma once

#include <optional>

#include "io/json_format.hpp"
#include "rodshape/core/scene.hpp"
#include "rodshape/trajectory/plan_result.hpp"

namespace rodshape::io_detail {

/// {shape, name, and the shape's fields, as in the task file}.
Json obstacle_json(const Obstacle& obstacle);

/// {clearance, rod_radius, obstacles, min_gap, min_gap_at {step, s, obstacle}, margin, clear,
/// obstacles_per_step}; null without a scene. With two arms (`two_arms`: PlanProblem::arm and
/// base_arm), also without a scene when the result has the arms' gap, and robot_min_gap_at then
/// says whose link (`arm`: "tip" or "base") and, for a gap between the two arms (obstacle
/// "other_arm"), the base arm's link (`other_link`).
Json scene_json(const Scene& scene,
                const std::optional<SceneResult>& result,
                bool two_arms = false);

}  // namespace rodshape::io_detail
