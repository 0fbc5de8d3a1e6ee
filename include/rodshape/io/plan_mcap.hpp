// plan_mcap.hpp: a plan, and a validation of it, as ROS 2 messages in an MCAP file (plan.mcap,
// validation.mcap; docs/ros.md). Frames: "world" (the task's), and from it "clamp" (the rod's
// base end, p(0), R(0)), "tip" (its held end, p(L), R(L)), and with an arm "base" (its base link,
// ArmPlacement::world_T_base) and "flange" (its tip link); a base arm's are "base_arm/base" and
// "base_arm/flange". Log times are the plan's clock (t = 0 the plan's start), in ns.
//   /rodshape/joint_trajectory  trajectory_msgs/msg/JointTrajectory   the arm's, once, at t = 0
//   /rodshape/base_joint_trajectory   the base arm's, likewise (with a base arm)
//   /joint_states               sensor_msgs/msg/JointState   at the joint trajectory's samples
//   /base_arm/joint_states      the base arm's (its joints may have the tip arm's names)
//   /tf                         tf2_msgs/msg/TFMessage       clamp, tip (and base, flange) there
//   /rodshape/rod               visualization_msgs/msg/MarkerArray   at t = 0 the initial shape,
//                               then each step's shape at the time its waypoint is reached: the
//                               rod (ns "rod", a line strip through its nodes), the target points
//                               ("target"), the step's objective points ("objective") and the
//                               scene's obstacles ("obstacles", id = index)
// and in validation.mcap besides, at each run's last frame (what a ValidationRun keeps):
//   /camera/points              sensor_msgs/msg/PointCloud2   the depth camera's cloud (float32
//                               x, y, z in "world"; with a depth camera)
//   /rodshape/markers_measured  visualization_msgs/msg/MarkerArray   the markers seen (a sphere
//                               list; with a marker camera)
#pragma once

#include <cstddef>
#include <string>

#include "rodshape/io/mcap_writer.hpp"
#include "rodshape/sim/plan_validation.hpp"
#include "rodshape/trajectory/plan_problem.hpp"
#include "rodshape/trajectory/plan_result.hpp"

namespace rodshape {

/// At most this many /joint_states (and /tf) messages (docs/limits.md, "Sizes"): a longer joint
/// trajectory is decimated evenly, its first and last samples kept (/rodshape/joint_trajectory
/// always has every sample). About 0.34 kB a message for 7 joints, 0.41 kB a /tf message.
inline constexpr std::size_t kMaxJointStateMessages = 100'000;

/// plan.mcap of `plan`, planned for `problem`: the topics above; InputError for a plan without an
/// end-effector path (an infeasible target).
std::string plan_mcap(const PlanResult& plan,
                      const PlanProblem& problem,
                      const McapOptions& options = {});

/// validation.mcap: plan.mcap's topics and the validation's.
std::string validation_mcap(const ValidationResult& result,
                            const PlanResult& plan,
                            const PlanProblem& problem,
                            const McapOptions& options = {});

}  // namespace rodshape
