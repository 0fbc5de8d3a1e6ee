// plan_page.cpp (figures): plan.html and validation.html, one self-contained page each. The page
// is three.js (inlined from Debian's libjs-three), the page's own code (page/rodshape_view.js,
// compiled in) and the data as JSON, filled in here: shapes, times, the arm's joint frames
// (forward kinematics of the joint trajectory), obstacles, series. Nothing is solved in the
// browser. docs/figures.md describes the page, docs/limits.md its caps.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "figures/svg_drawing.hpp"
#include "io/scene_json.hpp"
#include "rodshape/figures/figures.hpp"
#include "rodshape/optimisation/shape_target.hpp"
#include "rodshape/robot/arm_placement.hpp"
#include "rodshape/version.hpp"

namespace rodshape::figures::detail {
extern const char* const kViewScript;  // page/rodshape_view.js (cmake/embed_text.cmake)
extern const char* const kViewStyle;   // page/rodshape_view.css
}  // namespace rodshape::figures::detail

namespace rodshape {

namespace {

using nlohmann::json;

/// A length in metres to the micrometre: the page's numbers stay short.
double round_um(double metres) { return std::round(metres * 1e6) / 1e6; }

json point(const Eigen::Vector3d& p) {
  return json::array({round_um(p.x()), round_um(p.y()), round_um(p.z())});
}

/// The indices 0 … n-1 kept when at most `cap` are: evenly spaced, the first and the last kept.
std::vector<std::size_t> decimated(std::size_t n, std::size_t cap) {
  std::vector<std::size_t> kept;
  if (n == 0) return kept;
  if (n <= cap || cap < 2) {
    for (std::size_t i = 0; i < n; ++i) kept.push_back(i);
    return kept;
  }
  for (std::size_t k = 0; k < cap; ++k) {
    const std::size_t i = static_cast<std::size_t>(
        std::llround(static_cast<double>(k) * static_cast<double>(n - 1) / (cap - 1)));
    if (kept.empty() || kept.back() != i) kept.push_back(i);
  }
  return kept;
}

json points(const std::vector<Eigen::Vector3d>& ps, std::size_t cap = 0) {
  json out = json::array();
  for (const std::size_t i : decimated(ps.size(), cap == 0 ? ps.size() : cap))
    out.push_back(point(ps[i]));
  return out;
}

json shape(const RodConfiguration& c) { return points(c.p, kPageMaxNodes); }

/// The time at which the end-effector path reaches each step's pose: the first sample, from the
/// previous step's on, within a micrometre (and a microradian × the rod's length) of it, else the
/// nearest. Without a path (an infeasible or failed plan): 1 s a step.
std::vector<double> step_times(const PlanResult& plan, double length) {
  std::vector<double> times;
  const auto& path = plan.end_effector_path;
  std::size_t from = 0;
  for (std::size_t k = 0; k < plan.steps.size(); ++k) {
    if (path.empty()) {
      times.push_back(static_cast<double>(k + 1));
      continue;
    }
    const Pose& pose = plan.steps[k].end_effector;
    std::size_t best = from;
    double best_distance = std::numeric_limits<double>::infinity();
    for (std::size_t j = from; j < path.size(); ++j) {
      const Eigen::AngleAxisd turn(pose.rotation.transpose() * path[j].pose.rotation);
      const double d = (path[j].pose.position - pose.position).norm() + length * turn.angle();
      if (d < best_distance) best_distance = d, best = j;
      if (d < 1e-6 * (1.0 + length)) break;
    }
    times.push_back(path[best].t);
    from = best;
  }
  return times;
}

/// The arm's joint frames along its joint trajectory, in the world: the base, every moving
/// joint's origin, the flange and the end effector, per sample (at most kPageMaxArmSamples). The
/// samples' times are the path's when the trajectory has one sample per path sample (it was not
/// re-timed), else its own scaled to the path's duration, so that the arm and the rod move
/// together on the page. `problem_arm` and `result` are the tip's arm's (problem.arm, plan.arm)
/// or the base's (problem.base_arm, plan.base_arm), on the same clock.
json arm_json(const PlanResult& plan,
              const std::optional<PlanArm>& problem_arm,
              const std::optional<ArmPlanResult>& result) {
  if (!problem_arm || !result || result->joints.q.empty()) return nullptr;
  const ArmModel& model = problem_arm->model;
  const ArmPlacement& placement = problem_arm->placement;
  const JointTrajectoryResult& joints = result->joints;
  const auto& path = plan.end_effector_path;
  const bool same_samples = joints.q.size() <= path.size() && joints.t.size() == joints.q.size();
  const double scale = (!path.empty() && joints.duration() > 0.0)
                           ? (path.back().t - path.front().t) / joints.duration()
                           : 1.0;
  json times = json::array(), frames = json::array();
  for (const std::size_t i : decimated(joints.q.size(), kPageMaxArmSamples)) {
    const Eigen::VectorXd& q = joints.q[i];
    if (q.size() != model.joints() || !q.allFinite()) continue;
    json frame = json::array();
    frame.push_back(point(placement.world_T_base.position));
    for (const JointAxis& axis : model.joint_axes(q))
      frame.push_back(
          point(placement.world_T_base.position + placement.world_T_base.rotation * axis.origin));
    const Pose flange = compose(placement.world_T_base, model.forward_kinematics(q));
    frame.push_back(point(flange.position));
    frame.push_back(point(compose(flange, placement.flange_T_ee).position));
    frames.push_back(frame);
    const double t = same_samples && i < path.size()
                         ? path[i].t
                         : (i < joints.t.size() ? (joints.t[i] - joints.t.front()) * scale : 0.0);
    times.push_back(t);
  }
  return {{"name", model.robot_name()},
          {"t", times},
          {"frames", frames},
          {"status", to_string(result->status)},
          {"joints", joints.brief()}};
}

/// Everything the page shows of a plan.
json plan_data(const PlanResult& plan, const PlanProblem& problem, const FigureCaption& caption) {
  const double length = problem.rod.properties.length;
  json data;
  data["generator"] = "rodshape " + version();
  data["kind"] = "plan";
  data["source"] = caption.source;
  data["status"] = to_string(plan.status);
  data["summary"] = plan.brief();
  data["message"] = plan.message;
  data["length"] = length;
  data["radius"] = problem.scene.rod_radius;
  data["clamp"] = point(problem.rod.clamp.position);
  data["initial"] = shape(plan.initial_configuration);
  data["target"] = points(problem.target.points);
  // The target's B-spline, as the feasibility check fits it: 10 samples between points.
  data["target_curve"] = points(sample_target_curve(
      problem.target, problem.rod.clamp.position,
      std::min(10 * static_cast<int>(problem.target.points.size()) + 1, kPageMaxPathSamples)));
  data["initial_points"] = points(plan.initial_points);
  // Keyframes: the initial rod at t = 0, then the steps at the times the path reaches them.
  const std::vector<double> times = step_times(plan, length);
  json steps = json::array();
  for (const std::size_t k : decimated(plan.steps.size(), kPageMaxShapes - 1)) {
    const PlanStep& step = plan.steps[k];
    steps.push_back({{"index", k + 1},
                     {"t", times[k]},
                     {"shape", shape(step.solution.configuration)},
                     {"objective", points(step.objective_points)},
                     {"energy", step.solution.configuration.energy},
                     {"max_distance", step.solution.cost.max_distance},
                     {"inserted", step.inserted},
                     {"detour", step.detour}});
  }
  data["steps"] = steps;
  data["initial_energy"] = plan.initial_configuration.energy;
  json path_t = json::array(), path_p = json::array();
  for (const std::size_t i : decimated(plan.end_effector_path.size(), kPageMaxPathSamples)) {
    path_t.push_back(plan.end_effector_path[i].t);
    path_p.push_back(point(plan.end_effector_path[i].pose.position));
  }
  data["path"] = {{"t", path_t}, {"p", path_p}};
  // A moving base (issue 21): the base gripper's path, on the same clock; null with a clamp.
  if (problem.base_moves() && !plan.base_end_effector_path.empty()) {
    json base_t = json::array(), base_p = json::array();
    for (const std::size_t i : decimated(plan.base_end_effector_path.size(), kPageMaxPathSamples)) {
      base_t.push_back(plan.base_end_effector_path[i].t);
      base_p.push_back(point(plan.base_end_effector_path[i].pose.position));
    }
    data["base_path"] = {{"t", base_t}, {"p", base_p}};
  } else {
    data["base_path"] = nullptr;
  }
  double duration = plan.end_effector_path.empty() ? 0.0 : plan.end_effector_path.back().t;
  if (!times.empty()) duration = std::max(duration, times.back());
  data["duration"] = duration;
  data["arm"] = arm_json(plan, problem.arm, plan.arm);
  data["base_arm"] = arm_json(plan, problem.base_arm, plan.base_arm);
  json obstacles = json::array();
  for (const Obstacle& obstacle : problem.scene.obstacles)
    obstacles.push_back(json(io_detail::obstacle_json(obstacle)));  // as plan.json writes them
  data["obstacles"] = obstacles;
  data["clearance"] = problem.scene.clearance;
  if (problem.workspace.box)
    data["workspace_box"] = {{"lower", point(problem.workspace.box->lower)},
                             {"upper", point(problem.workspace.box->upper)}};
  else
    data["workspace_box"] = nullptr;
  data["validation"] = nullptr;
  return data;
}

/// What a validation adds: per run, its errors over time, the plant's last equilibrium, the
/// markers or the depth camera's cloud seen at the last frame and the checkpoints.
json validation_data(const ValidationResult& result) {
  json runs = json::array();
  for (const ValidationRun& run : result.runs) {
    json t = json::array(), e3 = json::array(), e2 = json::array(), et = json::array();
    for (const std::size_t i : decimated(run.time.size(), kPageMaxPathSamples)) {
      const auto mm = [](double e) { return std::isfinite(e) ? json(round_um(e)) : json(nullptr); };
      t.push_back(run.time[i]);
      e3.push_back(mm(run.error_3d[i]));
      e2.push_back(mm(run.error_2d[i]));
      et.push_back(mm(run.true_error[i]));
    }
    json markers = json::array(), cloud = json::array();
    for (const auto& m : run.last_seen.markers)
      if (m) markers.push_back(point(*m));
    for (const Eigen::Vector3d& q : run.last_cloud.points) cloud.push_back(point(q));
    json checkpoints = json::array();
    for (const Checkpoint& c : run.checkpoints)
      checkpoints.push_back({{"t", c.t},
                             {"waypoint", c.waypoint},
                             {"replanned", c.replanned},
                             {"consistent", c.consistent},
                             {"message", c.message}});
    runs.push_back({{"seed", run.seed},
                    {"closed_loop", run.closed_loop},
                    {"t", t},
                    {"error_3d", e3},
                    {"error_2d", e2},
                    {"true_error", et},
                    {"final",
                     {{"error_3d", run.final.error_3d},
                      {"error_2d", run.final.error_2d},
                      {"true_error", run.final.true_error}}},
                    {"plant_final", shape(run.plant_final.configuration)},
                    {"plant_final_t", run.plant_final.t},
                    {"markers", markers},
                    {"markers_t", run.last_seen.t},
                    {"cloud", cloud},
                    {"checkpoints", checkpoints}});
  }
  return {{"status", to_string(result.status)},
          {"summary", result.brief()},
          {"message", result.message},
          {"runs", runs}};
}

/// `text` safe inside a <script> element: no "</" (a JSON string may hold "</script>").
std::string script_safe(std::string text) {
  for (std::size_t at = text.find("</"); at != std::string::npos; at = text.find("</", at + 3))
    text.replace(at, 2, "<\\/");
  return text;
}

std::string page(const json& data, const std::string& title, const PageLibrary& library) {
  std::ostringstream out;
  out << "<!DOCTYPE html>\n"
      << svg_signature_comment() << "\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>"
      << figures::escaped(title) << "</title>\n<style>\n"
      << figures::detail::kViewStyle << "</style>\n</head>\n<body>\n"
      << "<noscript>This page needs JavaScript (and WebGL) to show the plan in 3D; plan.svg "
         "shows it without.</noscript>\n"
      << "<script>\n/* three.js r-series from " << library.directory
      << " (Debian libjs-three), MIT licence */\n"
      << script_safe(library.three) << "\n</script>\n<script>\n"
      << script_safe(library.orbit_controls) << "\n</script>\n"
      << "<script type=\"application/json\" id=\"rodshape-data\">\n"
      << script_safe(data.dump()) << "\n</script>\n<script>\n"
      << figures::detail::kViewScript << "\n</script>\n</body>\n</html>\n";
  return out.str();
}

std::string read_whole(const std::string& path, bool& ok) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  ok = static_cast<bool>(in) || in.eof();
  ok = ok && !text.str().empty();
  return text.str();
}

}  // namespace

std::string page_library_directory() {
  const char* dir = std::getenv("RODSHAPE_THREE_JS_DIR");
  return dir != nullptr && *dir != '\0' ? dir : "/usr/share/javascript/three";
}

std::optional<PageLibrary> load_page_library(std::string* why) {
  PageLibrary library;
  library.directory = page_library_directory();
  for (const auto& [file, text] :
       {std::pair{"three.min.js", &library.three},
        std::pair{"examples/js/controls/OrbitControls.js", &library.orbit_controls}}) {
    bool ok = false;
    const std::string path = library.directory + "/" + file;
    *text = read_whole(path, ok);
    if (!ok) {
      if (why != nullptr)
        *why = path +
               " cannot be read: the 3D page needs three.js (Debian: apt-get install "
               "libjs-three, or set RODSHAPE_THREE_JS_DIR)";
      return std::nullopt;
    }
  }
  return library;
}

std::string plan_html(const PlanResult& plan,
                      const PlanProblem& problem,
                      const FigureCaption& caption,
                      const PageLibrary& library) {
  return page(plan_data(plan, problem, caption), "rodshape plan: " + caption.source, library);
}

std::string validation_html(const ValidationResult& result,
                            const PlanResult& plan,
                            const PlanProblem& problem,
                            const FigureCaption& caption,
                            const PageLibrary& library) {
  json data = plan_data(plan, problem, caption);
  data["kind"] = "validation";
  data["validation"] = validation_data(result);
  return page(data, "rodshape validation: " + caption.source, library);
}

}  // namespace rodshape
