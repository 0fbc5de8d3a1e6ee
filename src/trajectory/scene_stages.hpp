// scene_stages.hpp (private): what plan() does with a scene (PlanProblem::scene), stage by stage:
//   target_clear       feasibility: no target point within r + clearance of an obstacle
//   clear_of_scene     an intermediate objective set with its points pushed out of the obstacles,
//                      so that they do not drag the rod in
//   step_clearance     the obstacles one step's optimisation keeps the rod clear of: those near
//                      its start and its objective points (a fixed set of rows), with the gaps
//                      they require widened by the planning margin
//   violated_obstacles the obstacles an optimum violates that its step did not include
//   SweptGap           the least gap of the rod moving between followed substeps (tracking and
//                      the detour's edges)
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "rodshape/core/scene.hpp"
#include "rodshape/optimisation/shape_problem.hpp"
#include "rodshape/trajectory/plan.hpp"

namespace rodshape::scene_stages {

/// Why the target cannot be reached clear of the scene (a point inside an obstacle plus the
/// clearance), naming the point and the obstacle; nullopt when every point is clear.
struct BlockedPoint {
  int point = -1;  // index into the target's points
  std::string reason;
};
std::optional<BlockedPoint> target_clear(const Scene& scene,
                                         const std::vector<double>& required,
                                         const PointSet& points);

/// `points` with each point inside an obstacle's required gap moved out along the obstacle's
/// normal to r + required (a few passes, for points between two obstacles).
PointSet clear_of_scene(const Scene& scene,
                        const std::vector<double>& required,
                        const PointSet& points);

/// The obstacles within reach of a step: nearer than `radius` (plus r and the required gap) to a
/// node of `start` or an objective point, and those in `forced`; the gaps they require, widened
/// by `margin` (m) for all but the clamp's mount.
Clearance step_clearance(const Scene& scene,
                         const std::vector<double>& required,
                         const RodConfiguration& start,
                         const PointSet& points,
                         double radius,
                         double margin,
                         const std::vector<int>& forced);

/// The obstacles of `scene` that `c` comes nearer to than they require, and that `selected` (a
/// step_clearance) does not hold.
std::vector<int> violated_obstacles(const Scene& scene,
                                    const std::vector<double>& required,
                                    const RodConfiguration& c,
                                    const Clearance& selected);

/// The least gap over a rod followed through substeps, including the motion between them
/// (Scene::swept_gap of each substep and the one before). Each add() returns that bound for the
/// interval it closes.
class SweptGap {
 public:
  SweptGap(const Scene& scene,
           const std::vector<double>& required,
           const std::vector<Eigen::Vector3d>& start);
  SceneGap add(const std::vector<Eigen::Vector3d>& p);

 private:
  const Scene& scene_;
  const std::vector<double>& required_;
  std::vector<Eigen::Vector3d> previous_;
};

}  // namespace rodshape::scene_stages
