// field_names.cpp: the table between the library's field names and the task file's (see
// field_names.hpp, and docs/task-file.md for the task file's).
#include "rodshape/io/field_names.hpp"

#include <regex>
#include <string_view>
#include <unordered_map>

namespace rodshape {

namespace {

const std::unordered_map<std::string_view, std::string_view>& table() {
  static const std::unordered_map<std::string_view, std::string_view> names = {
      // trajectory
      {"PlanOptions.steps", "trajectory.steps"},
      {"PlanOptions.max_refinements", "trajectory.max_refinements"},
      {"PlanOptions.tracking_substeps", "trajectory.tracking_substeps"},
      {"EndEffectorLimits.max_linear_speed", "trajectory.max_linear_speed"},
      {"EndEffectorLimits.max_angular_speed", "trajectory.max_angular_speed"},
      {"EndEffectorLimits.max_linear_acceleration", "trajectory.max_linear_acceleration"},
      {"EndEffectorLimits.max_angular_acceleration", "trajectory.max_angular_acceleration"},
      {"EndEffectorLimits.sample_rate", "trajectory.rate"},
      {"EndEffectorLimits", "trajectory"},
      {"PlanProblem.workspace", "workspace"},
      {"PlanOptions.scene_margin", "scene.margin"},
      {"PlanOptions.scene_reach", "scene.reach"},
      {"PlanOptions.track_between_waypoints", "trajectory.track"},
      {"PlanOptions.reach_tolerance", "trajectory.reach_tolerance"},
      {"Scene.rod_radius", "rod.section"},
      {"Scene", "scene"},
      {"PlanProblem.initial", "initial"},
      {"PlanArm.placement.world_T_base", "robot.base"},
      {"PlanArm.placement.flange_T_ee", "robot.flange_to_end_effector"},
      {"PlanArm", "robot"},
      {"PlanProblem.arm.placement.world_T_base", "robot.base"},
      {"PlanProblem.arm.placement.flange_T_ee", "robot.flange_to_end_effector"},
      {"PlanProblem.arm", "robot"},
      {"PlanProblem.base_arm.placement.world_T_base", "base_robot.base"},
      {"PlanProblem.base_arm.placement.flange_T_ee", "base_robot.flange_to_end_effector"},
      {"PlanProblem.rod.clamp", "base"},
      {"PlanProblem.rod.load", "distributed_load"},
      {"PlanProblem.grasp.tip_to_end_effector", "grasp.tip_to_end_effector"},
      {"PlanProblem.grasp.released", "grasp.zero_wrench"},
      {"PlanProblem.grasp", "grasp"},
      {"PlanProblem.wrench_bounds", "wrench_bounds"},
      {"PlanProblem.target", "target"},
      {"PlanProblem.scene", "scene"},
      {"PlanOptions.interpolation", "trajectory.interpolation"},
      // a moving base (issue 21)
      {"PlanProblem.moving_base.motion_weight", "base.motion_weight"},
      {"PlanProblem.moving_base.grasp.tip_to_end_effector", "base_grasp.base_to_end_effector"},
      {"PlanProblem.moving_base.grasp.released", "base_grasp.zero_wrench"},
      {"PlanProblem.moving_base.grasp", "base_grasp"},
      {"PlanProblem.moving_base.wrench_bounds", "base_grasp.wrench_bounds"},
      {"PlanProblem.moving_base.workspace", "base_workspace"},
      {"PlanProblem.moving_base", "base.moving"},
      {"MovingBase.motion_weight", "base.motion_weight"},
      {"MovingBase.grasp.tip_to_end_effector", "base_grasp.base_to_end_effector"},
      {"MovingBase.grasp.released", "base_grasp.zero_wrench"},
      {"MovingBase.wrench_bounds", "base_grasp.wrench_bounds"},
      {"MovingBase.workspace", "base_workspace"},
      {"MovingBase", "base.moving"},
      {"PlanProblem.base_arm", "base_robot"},
      {"PlanOptions.base_end_effector", "trajectory.base_end_effector"},
      {"ArmPlanOptions.use_reach", "robot.reach.use"},
      {"ArmPlanOptions.reach_margin", "robot.reach.margin"},
      {"ArmPlanOptions.replan_tightening", "robot.reach.tightening"},
      {"ArmPlanOptions.max_replans", "robot.reach.max_replans"},
      {"ArmPlanOptions.link_influence", "robot.links.influence"},
      {"ArmPlanOptions.joints.seed", "robot.seed"},
      {"ArmPlanOptions.base_seed", "base_robot.seed"},
      {"BaseMotion.motion_weight", "base.motion_weight"},
      {"BaseMotion.wrench_bounds", "base_grasp.wrench_bounds"},
      {"ArmReachOptions.samples", "robot.reach.samples"},
      {"ArmReachOptions.refinement_steps", "robot.reach.refinement_steps"},
      // sim
      {"PlantModel.factors", "plant.stiffness_factors"},
      {"PlantModel.planner_gravity", "gravity"},
      {"ValidationOptions.seed", "--seed"},
      {"ValidationOptions.runs", "--runs"},
      {"ValidationOptions.jobs", "--jobs"},
      {"PlantModel", "plant"},
      {"MarkerSensorModel.in_plane_noise", "sensor.noise.in_plane"},
      {"MarkerSensorModel.depth_noise", "sensor.noise.depth"},
      {"MarkerSensorModel.wrist", "sensor.wrench_noise"},
      {"MarkerSensorModel", "sensor"},
      {"DepthSensorModel.width", "sensor.depth.resolution[0]"},
      {"DepthSensorModel.height", "sensor.depth.resolution[1]"},
      {"DepthSensorModel.fov_x_deg", "sensor.depth.field_of_view[0]"},
      {"DepthSensorModel.fov_y_deg", "sensor.depth.field_of_view[1]"},
      {"DepthSensorModel.min_range", "sensor.depth.range[0]"},
      {"DepthSensorModel.max_range", "sensor.depth.range[1]"},
      {"DepthSensorModel.points", "sensor.depth.points"},
      {"DepthSensorModel.noise", "sensor.depth.noise"},
      {"DepthSensorModel.outliers", "sensor.depth.outliers"},
      {"DepthSensorModel.wrist", "sensor.wrench_noise"},
      {"DepthSensorModel", "sensor"},
      {"EstimationOptions", "closed_loop"},
      {"ClosedLoopOptions", "closed_loop"},
      // optimisation
      {"ShapeOptimiserOptions", "optimizer"},
      {"ShapeTarget.points", "target.points"},
      {"ShapeTarget.energy_weight", "weights.energy"},
      {"ShapeTarget.distance_weight", "weights.distance"},
      {"ShapeTarget.distance_smoothing", "target.distance_smoothing"},
      {"StrainLimits.max_curvature", "limits.max_curvature"},
      {"StrainLimits.max_axial_strain", "limits.max_axial_strain"},
      {"Workspace", "workspace"},
      {"WrenchBounds", "wrench_bounds"},
      {"Grasp.tip_to_end_effector", "grasp.tip_to_end_effector"},
      {"Grasp.released", "grasp.zero_wrench"},
      // core
      {"RodDescription.length", "rod.length"},
      {"RodDescription.model", "rod.model"},
      {"RodDescription.section", "rod.section"},
      {"RodDescription.material", "rod.material"},
      {"RodDescription.stiffness", "rod.stiffness"},
      {"RodDescription.rest_curvature", "rod.rest_curvature"},
      {"RodProperties.length", "rod.length"},
      {"RodProperties.model", "rod.model"},
      {"RodProperties.K_tra[0]", "rod.stiffness.GA"},
      {"RodProperties.K_tra[1]", "rod.stiffness.GA"},
      {"RodProperties.K_tra[2]", "rod.stiffness.EA"},
      {"RodProperties.K_rot[0]", "rod.stiffness.EIx"},
      {"RodProperties.K_rot[1]", "rod.stiffness.EIy"},
      {"RodProperties.K_rot[2]", "rod.stiffness.GJ"},
      {"RodProperties.u_rest", "rod.rest_curvature"},
      {"RodProperties.section", "rod.section"},
      {"ClampedRod.load", "distributed_load"},
      {"ClampedRod.clamp", "base"},
      {"FreeTip.wrench", "tip.wrench"},
      {"ClampedTip.pose", "tip"},
      {"EstimateTask.tip", "tip"},
      {"CloudFrame", "--cloud"},
      {"GraspedTip.pose", "tip"},
      {"GraspedTip.released", "tip.released"},
      // solvers
      {"ShootingOptions.max_iterations", "solver.max_iterations"},
      {"ShootingOptions.residual_tolerance", "solver.tolerance"},
      {"ShootingOptions.max_continuation_steps", "solver.max_continuation_steps"},
      {"ShootingOptions.continuation", "solver.continuation"},
      {"ShootingOptions.integration_tolerance", "solver.integration_tolerance"},
      {"ShootingOptions.max_substeps", "solver.max_substeps"},
      {"ShootingOptions.strain_limits", "solver"},
      {"PlanProblem.validity", "limits.model"},
  };
  return names;
}

}  // namespace

std::string task_field_name(const std::string& library_field) {
  std::string_view head = library_field;
  for (;;) {
    const auto found = table().find(head);
    if (found != table().end())
      return std::string(found->second) + library_field.substr(head.size());
    const std::size_t dot = head.find_last_of(".[");  // "ShapeTarget.points[1]": its list too
    if (dot == std::string_view::npos) return library_field;
    head = head.substr(0, dot);
  }
}

std::string in_task_names(const InputError& error) {
  if (error.field().empty()) return fields_in_task_names(error.what());
  return task_field_name(error.field()) + fields_in_task_names(error.problem());
}

std::string fields_in_task_names(const std::string& text) {
  // A library field is a type name (capitalised) and its members: "Grasp.released[2]".
  static const std::regex field(R"(\b[A-Z][A-Za-z]*(\.[a-z_][A-Za-z0-9_]*)+)");
  std::string out;
  auto last = text.cbegin();
  for (std::sregex_iterator it(text.begin(), text.end(), field), end; it != end; ++it) {
    out.append(last, (*it)[0].first);
    out += task_field_name(it->str());
    last = (*it)[0].second;
  }
  out.append(last, text.cend());
  return out;
}

}  // namespace rodshape
